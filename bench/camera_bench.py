#!/usr/bin/env python3
"""What cameras cost (docs/scenario.md#sensors), measured in one run of this script against the
same world without them:

- four diffdrive robots circling among 24 boxes and a walled yard for `--seconds` of simulated
  time, each with a camera at 10 Hz, at 320 x 240 and at 640 x 480, with the physics (and the
  rendering) on one thread and on two; each against the same run without cameras on as many
  threads (the baseline: ratio 1.00);
- the wall time of a picture: (the run with cameras - the run without) / the pictures taken;
- the real-time factor: simulated seconds per wall second (four 320 x 240 cameras at 10 Hz should
  keep at least 1.0 on two cores).

    bench/camera_bench.py [--sanet build/sanet] [--seconds 60] [--repeat 3]"""
import argparse
import os
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from grey_zone_bench import measure  # noqa: E402  (median wall time of `repeat` runs, the last summary)

ROBOTS = 4


def scenario(camera):
    """The yard: walls round 40 x 40 m, 24 coloured boxes, four robots circling (radius 4 m)."""
    lines = ["name: cameras", "duration: 60", "world:", "  size: [40, 40]", "  obstacles:"]
    for x0, y0, x1, y1 in ((-20, -20, 20, -20), (20, -20, 20, 20), (20, 20, -20, 20), (-20, 20, -20, -20)):
        lines.append(f"    - wall: {{from: [{x0}, {y0}], to: [{x1}, {y1}], height: 2, color: \"#8080a0\"}}")
    for i in range(24):
        x, y = -15 + (i % 6) * 6, -15 + (i // 6) * 10
        lines.append(f"    - box: {{center: [{x}, {y}], size: [1, 1, {0.5 + i % 3 * 0.5}], color: \"#{40 + i * 8:02x}a050\"}}")
    lines.append("nodes:")
    for r in range(ROBOTS):
        x, y = -9 + r * 6, 0
        sensors = f"\n    sensors: {{camera: {camera}}}" if camera else ""
        lines.append(f"  - name: r{r}\n    model: diffdrive\n    pose: [{x}, {y}, 0]{sensors}\n"
                     f"    controller: {{name: constant_velocity, params: {{vx: 0.8, omega: 0.2}}}}")
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sanet", default=os.path.join(ROOT, "build", "sanet"))
    parser.add_argument("--seconds", type=float, default=60, help="simulated seconds of each run")
    parser.add_argument("--repeat", type=int, default=3, help="runs of each case (the median is kept)")
    a = parser.parse_args()
    cases = [("none", None), ("320x240", "{width: 320, height: 240, rate: 10}"),
             ("640x480", "{width: 640, height: 480, rate: 10}")]
    pictures = ROBOTS * 10 * a.seconds
    print(f"{'cameras':>9} {'threads':>7} {'wall s':>8} {'ratio':>6} {'x real':>7} {'ms/picture':>10}")
    with tempfile.TemporaryDirectory() as tmp:
        for threads in (1, 2):
            base = None
            for name, camera in cases:
                path = os.path.join(tmp, f"{name}.yaml")
                with open(path, "w") as f:
                    f.write(scenario(camera))
                wall, _ = measure(a.sanet, path, os.path.join(tmp, "out"), a.seconds,
                                  [f"world.threads={threads}"], a.repeat)
                base = wall if base is None else base
                per = (wall - base) / pictures * 1000 if camera else 0
                print(f"{name:>9} {threads:>7} {wall:8.2f} {wall / base:6.2f} {a.seconds / wall:7.1f} "
                      f"{per:10.3f}", flush=True)


if __name__ == "__main__":
    main()
