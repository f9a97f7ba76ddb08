#!/usr/bin/env python3
"""What energy costs (docs/energy.md): each case runs without `energy` (the baseline, measured in
the same run) and with a battery on every node, the same seed, and prints the median wall time of
each, the ratio (with / without), the events ns-3 processed and whether the run's other results
stayed the same (the fingerprint without energy.csv: energy observes the run, it changes nothing
while no node dies).

  400 motes  a 20 x 20 grid 40 m apart, AODV, 40 motes sending 64 B to a far mote every 2 s (the
             field of bench/walls_bench.py): every radio's state changes update its battery
  swarm-1k   the shipped swarm (1,000 robots on the 2D engine, a beacon each per second)

The batteries are large enough that nobody dies. Whether a run without energy pays anything for
energy existing is bench/binary_ratio.py's question (two builds on the same scenario).

    bench/energy_bench.py [--sanet build/sanet] [--seconds 30] [--swarm-seconds 10] [--repeat 3]"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from walls_bench import grid_scenario  # noqa: E402  (the field without its walls)
BATTERY = "{battery_j: 1000000, voltage: 3, electronics_w: 0.01}"


def run(sanet, scenario, out, seconds, sets):
    args = [arg for s in sets for arg in ("--set", s)]
    subprocess.run([sanet, "run", scenario, "-q", "-o", out, "--duration", str(seconds), *args], check=True)
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def measure(sanet, scenario, folder, seconds, sets, repeat):
    """Median wall time over `repeat` runs, and the last run's summary."""
    walls, summary = [], None
    for _ in range(repeat):
        summary = run(sanet, scenario, folder, seconds, sets)
        walls.append(summary["wall_time_s"])
    return statistics.median(walls), summary


def same_results(plain, powered):
    """Every results file both runs wrote, byte for byte (energy.csv and the summary aside)."""
    skip = {"summary.json", "provenance.json", "scenario.yaml", "energy.csv"}
    for name in sorted(os.listdir(plain)):
        path = os.path.join(plain, name)
        if name in skip or not os.path.isfile(path):
            continue
        with open(path, "rb") as a, open(os.path.join(powered, name), "rb") as b:
            if a.read() != b.read():
                return f"no: {name} differs"
    return "yes"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sanet", default=os.path.join(ROOT, "build", "sanet"))
    parser.add_argument("--seconds", type=float, default=30, help="simulated seconds of the 400 motes")
    parser.add_argument("--swarm-seconds", type=float, default=10, help="simulated seconds of swarm-1k")
    parser.add_argument("--repeat", type=int, default=3, help="runs of each case (the median is kept)")
    a = parser.parse_args()
    print(f"{'case':>10} {'energy':>8} {'wall s':>8} {'ratio':>6} {'events':>10}  same other results")
    with tempfile.TemporaryDirectory() as tmp:
        field = os.path.join(tmp, "field.yaml")
        with open(field, "w") as f:
            f.write(grid_scenario(None))
        cases = [("400 motes", field, a.seconds, ["nodes.m.energy=" + BATTERY]),
                 ("swarm-1k", os.path.join(ROOT, "scenarios", "swarm-1k.yaml"), a.swarm_seconds,
                  ["nodes.r.energy=" + BATTERY])]
        for name, scenario, seconds, sets in cases:
            plain, powered = os.path.join(tmp, "plain"), os.path.join(tmp, "powered")
            base_wall, base = measure(a.sanet, scenario, plain, seconds, ["outputs.trace=false"], a.repeat)
            print(f"{name:>10} {'none':>8} {base_wall:>8.2f} {1:>6.3f} {base['events']:>10}", flush=True)
            wall, summary = measure(a.sanet, scenario, powered, seconds, ["outputs.trace=false", *sets], a.repeat)
            print(f"{name:>10} {'battery':>8} {wall:>8.2f} {wall / base_wall:>6.3f} {summary['events']:>10}  "
                  f"{same_results(plain, powered)}", flush=True)


if __name__ == "__main__":
    main()
