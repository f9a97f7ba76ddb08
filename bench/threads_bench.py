#!/usr/bin/env python3
"""The physics thread: wall time of shipped scenarios with `--threads 2` against `--threads 1`.

Each scenario runs as `sanet run` runs it, alternately with one thread (the baseline) and two,
`--reps` times each; the best wall time of each is kept (the machine's other load only ever
adds). It prints both wall times, their ratio (two threads over one), how long the network's
thread waited for the physics thread (summary.json's profile_s.physics_wait, two threads), the
physics' own time (physics and sensing stages, one thread), the share of physics steps in which
nothing else happened (quiet_physics_steps / physics_steps: there the physics thread has
nothing to overlap with), and checks that both give the same fingerprint.

  bench/threads_bench.py [--sanet build/sanet] [--reps 3] [SCENARIO[:SECONDS] ...]

Default scenarios: help-request (whole run), formation (whole run), swarm-1k (10 s), swarm-10k (2 s).
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT = ["help-request", "formation", "swarm-1k:10", "swarm-10k:2"]


def run(sanet, scenario, seconds, threads, out):
    command = [sanet, "run", scenario, "-q", "-o", out, "--threads", str(threads)]
    if seconds:
        command += ["--duration", seconds]
    if subprocess.run(command).returncode != 0:
        sys.exit("threads_bench: %s failed (see above)" % " ".join(command))
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--sanet", default=os.path.join(ROOT, "build", "sanet"))
    parser.add_argument("--reps", type=int, default=3, help="runs of each case; the best is kept")
    parser.add_argument("cases", nargs="*", default=DEFAULT, help="scenario name or file, optionally :SECONDS")
    args = parser.parse_args()
    print("%-16s %11s %11s %9s %10s %10s %7s  %s" % ("scenario", "1 thread s", "2 threads s", "2 / 1",
                                                       "waited s", "physics s", "quiet", "fingerprints"))
    same = True
    with tempfile.TemporaryDirectory() as tmp:
        for case in args.cases:
            name, _, seconds = case.partition(":")
            path = name if os.path.exists(name) else os.path.join(ROOT, "scenarios", name + ".yaml")
            if not os.path.exists(path):
                sys.exit("threads_bench: no scenario %s (neither a file nor scenarios/%s.yaml)" % (name, name))
            best = {1: None, 2: None}
            for rep in range(args.reps):
                for threads in (1, 2):
                    s = run(args.sanet, path, seconds, threads, os.path.join(tmp, "%s-%d-%d" % (
                        os.path.basename(name), threads, rep)))
                    if best[threads] is None or s["wall_time_s"] < best[threads]["wall_time_s"]:
                        best[threads] = s
            one, two = best[1], best[2]
            equal = one["fingerprint"] == two["fingerprint"]
            same = same and equal
            quiet = one["quiet_physics_steps"] / max(1, one["physics_steps"])
            print("%-16s %11.2f %11.2f %8.2fx %10.2f %10.2f %6.0f%%  %s" % (
                os.path.basename(name), one["wall_time_s"], two["wall_time_s"],
                two["wall_time_s"] / one["wall_time_s"], two["profile_s"]["physics_wait"],
                one["profile_s"]["physics"] + one["profile_s"]["sensing"], 100 * quiet,
                "same" if equal else "DIFFERENT %s %s" % (one["fingerprint"], two["fingerprint"])), flush=True)
    if not same:
        sys.exit("fingerprints differ between one thread and two")


if __name__ == "__main__":
    main()
