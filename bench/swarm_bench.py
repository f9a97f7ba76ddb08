#!/usr/bin/env python3
"""Swarm scale: wall time, real-time factor and memory of the shipped swarms, with and without their radio.

The shipped swarms (flocking diffdrive robots on the 2D engine, a one-hop 802.11 beacon a
second each) run as `sanet run` runs them, for a few simulated seconds each, swarm-1k and
swarm-10k in these cases:

  ... without radio          the same robots, controllers and physics, with no network and
                             no beacons: the baseline, measured in the same run, that tells
                             the radio's share of the cost
  ..., abstract radio        network.radio_model: abstract (docs/swarms.md#the-abstract-radio), its
                             calibration measured before the case if not cached
  ..., full, indexed channel ns-3's whole 802.11 model on sanet's indexed channel
  swarm-1k, full, yans       the full model on ns-3's YansWifiChannel (every frame to every radio)
  ..., 2 threads             the case before with the physics on its own thread; its ratio is to
                             the run without radio on two threads

It prints wall time, real-time factor, the profile's stages ("physics" is physics plus sensing,
"control" the controllers, "other" the rest: the network), the ratio of each case to its
baseline, the cost per robot-second, and peak memory per robot (summary.json's peak_memory_mb,
the process's peak resident set), and the start-up: the process's own wall time less the run's
(loading and checking the scenario, printing the effective scenario once, building the world,
writing the results).

  bench/swarm_bench.py [--sanet build/sanet] [--seconds 10] [--seconds-10k 3]
"""
import argparse
import json
import os
import re
import subprocess
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def variant(path, folder, tag, edit):
    text = edit(open(path).read())
    out = os.path.join(folder, tag + ".yaml")
    with open(out, "w") as f:
        f.write(text)
    return out


def without_radio(text):
    text = re.sub(r"^network:\n(  .*\n)+", "", text, flags=re.M)
    return text.replace("params: {", "params: {beacon: 1.0e9, ", 1)


def with_model(model):
    def edit(text):
        text = re.sub(r"^  radio_model: .*\n", "", text, flags=re.M)  # the scenario's own, if any
        return text.replace("network:\n", "network:\n  radio_model: %s\n" % model, 1)
    return edit


def with_yans(text):
    text = re.sub(r"^  channel: .*\n", "", text, flags=re.M)  # the scenario's own, if any
    return text.replace("network:\n", "network:\n  channel: {model: yans}\n", 1)


def run(sanet, scenario, seconds, out, threads=1):
    start = time.monotonic()
    subprocess.run([sanet, "run", scenario, "--duration", str(seconds), "-q", "-o", out, "--threads", str(threads)],
                   check=True)
    process = time.monotonic() - start
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    summary["outside_run_s"] = process - summary["wall_time_s"]
    return summary


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--sanet", default=os.path.join(ROOT, "build", "sanet"))
    parser.add_argument("--seconds", type=float, default=10, help="simulated seconds per 1k case")
    parser.add_argument("--seconds-10k", type=float, default=3, help="simulated seconds per 10k case")
    args = parser.parse_args()
    print("%-28s %8s %7s %9s %9s %9s %12s %9s %10s %9s" % (
        "case", "wall s", "RTF", "physics", "control", "other", "us/robot-s", "vs base", "MB/robot", "start-up"))
    with tempfile.TemporaryDirectory() as tmp:
        for name, seconds, robots, extra in (("swarm-1k", args.seconds, 1000, True),
                                             ("swarm-10k", args.seconds_10k, 10000, False)):
            path = os.path.join(ROOT, "scenarios", name + ".yaml")
            full = variant(path, tmp, name + "-full", with_model("full"))
            abstract = variant(path, tmp, name + "-abstract", with_model("abstract"))
            local = variant(path, tmp, name + "-local", without_radio)
            cases = [("without radio", local, 1), ("without radio, 2 threads", local, 2),
                     ("abstract radio", abstract, 1), ("abstract, 2 threads", abstract, 2),
                     ("full, indexed channel", full, 1), ("full, indexed, 2 threads", full, 2)]
            if extra:
                cases.append(("full, yans channel", variant(full, tmp, name + "-yans", with_yans), 1))
            base = {}  # by threads: the run without radio
            for label, scenario, threads in cases:
                s = run(args.sanet, scenario, seconds, os.path.join(tmp, name + label.replace(" ", "-")), threads)
                wall = s["wall_time_s"]
                p = s["profile_s"]
                # With two threads the physics overlaps the rest: only its waits count on the clock.
                physics = p["physics"] + p["sensing"] if threads == 1 else p["physics_wait"]
                other = wall - physics - p["controllers"] - p["recording"]
                base.setdefault(threads, wall)
                print("%-28s %8.2f %7.2f %9.2f %9.2f %9.2f %12.1f %8.2fx %10.3f %8.2fs" % (
                    name + ", " + label, wall, s["real_time_factor"], p["physics"] + p["sensing"],
                    p["controllers"], other, wall / (robots * seconds) * 1e6, wall / base[threads],
                    s["peak_memory_mb"] / robots, s["outside_run_s"]), flush=True)


if __name__ == "__main__":
    main()
