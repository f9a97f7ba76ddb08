#!/usr/bin/env python3
"""What the grey zone costs (docs/network.md#a-grey-zone): each case runs on the plain radio (the
baseline, measured in the same run) and with log-normal shadowing (sigma 6 dB, correlated over
10 m), shadowing and Nakagami fading (m = 1.5), and both with a hardware spread (1 dB), and
prints the median wall time, its ratio to the baseline, the frames the radios received, the wall
time per received frame and its ratio, and the radios the indexed channel considered per frame
(its ranges widen by the shadowing's clip and the fading's cap) and handed each frame (those it
arrived at at the floor or stronger, which ns-3's PHY then processes).

  400 motes  a 20 x 20 grid 40 m apart, AODV, 40 motes sending 64 B to a far mote every 2 s (the
             field of bench/walls_bench.py): the motes stand, so each link's shadowing is kept
  swarm-1k   the shipped swarm (1,000 robots, a beacon each per second): every robot moves, so the
             shadowing of its links is computed again for every frame

The radio changes what is received, so the runs differ in their work as well as in the cost of a
frame: the ratio per received frame is the one to read for the models' own cost.

    bench/grey_zone_bench.py [--sanet build/sanet] [--seconds 30] [--swarm-seconds 5] [--repeat 3]"""
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

SHADOWING = ["network.propagation.shadowing={sigma_db: 6, correlation_m: 10}"]
FADING = SHADOWING + ["network.propagation.fading={model: nakagami, m: 1.5}"]
SPREAD = FADING + ["network.hardware_spread={tx_power_db: 1, noise_figure_db: 1}"]
VARIANTS = [("plain", []), ("shadowing", SHADOWING), ("+fading", FADING), ("+spread", SPREAD)]


def measure(sanet, scenario, out, seconds, sets, repeat):
    """Median wall time over `repeat` runs, and the last run's summary."""
    args = [arg for s in ["outputs.trace=false", *sets] for arg in ("--set", s)]
    walls, summary = [], None
    for _ in range(repeat):
        subprocess.run([sanet, "run", scenario, "-q", "-o", out, "--force", "--duration", str(seconds), *args],
                       check=True)
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
        walls.append(summary["wall_time_s"])
    return statistics.median(walls), summary


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sanet", default=os.path.join(ROOT, "build", "sanet"))
    parser.add_argument("--seconds", type=float, default=30, help="simulated seconds of the 400 motes")
    parser.add_argument("--swarm-seconds", type=float, default=5, help="simulated seconds of swarm-1k")
    parser.add_argument("--repeat", type=int, default=3, help="runs of each case (the median is kept)")
    a = parser.parse_args()
    print(f"{'case':>10} {'radio':>10} {'wall s':>8} {'ratio':>6} {'received':>10} {'us/frame':>9} {'ratio':>6} "
          f"{'considered':>10} {'handed':>7}")
    with tempfile.TemporaryDirectory() as tmp:
        field = os.path.join(tmp, "field.yaml")
        with open(field, "w") as f:
            f.write(grid_scenario(None))
        cases = [("400 motes", field, a.seconds), ("swarm-1k", os.path.join(ROOT, "scenarios", "swarm-1k.yaml"),
                                                    a.swarm_seconds)]
        for name, scenario, seconds in cases:
            base_wall = base_per_frame = None
            for variant, sets in VARIANTS:
                wall, summary = measure(a.sanet, scenario, os.path.join(tmp, "out"), seconds, sets, a.repeat)
                channel = summary["network"]["channel"]
                per_frame = wall / max(1, channel["frames_received"]) * 1e6
                base_wall = base_wall or wall
                base_per_frame = base_per_frame or per_frame
                print(f"{name:>10} {variant:>10} {wall:>8.2f} {wall / base_wall:>6.2f} {channel['frames_received']:>10} "
                      f"{per_frame:>9.1f} {per_frame / base_per_frame:>6.2f} "
                      f"{channel.get('receivers_considered_per_frame', 0):>10.1f} {channel.get('receivers_per_frame', 0):>7.1f}",
                      flush=True)


if __name__ == "__main__":
    main()
