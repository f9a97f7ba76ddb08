#!/usr/bin/env python3
"""What a Python controller costs: the built-in C++ `waypoint` against the same controller in
Python (examples/python/waypoint.py, which gives the same trajectories), at 1, 100 and 1,000
robots stepping at 10 Hz, measured in the same run.

Each case is a grid of diffdrive robots on the 2D engine (world.physics: 2d), each with eight IR
sensors, driving to a way point 30 m ahead past a post; no network. For each it prints:

  step us       the controllers' time (summary.json's profile_s.controllers) per control step
  ratio         Python's per-step time over C++'s (the baseline)
  wall s        the run's wall time
  control %     the controllers' share of the wall time: where Python becomes the bottleneck
  rt factor     simulated seconds per wall second

  bench/python_controllers.py [--sanet build/sanet] [--seconds 10] [--robots 1,100,1000]
"""
import argparse
import json
import os
import subprocess
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def scenario(robots, seconds, controller):
    cols = max(c for c in range(1, 41) if robots % c == 0)
    rows = robots // cols
    return f"""name: python-bench
seed: 1
duration: {seconds}
world:
  physics: 2d
  physics_step: 0.01
  size: [{cols * 6 + 40}, {rows * 4 + 10}]
  obstacles:
    - box: {{center: [15, 2], size: [0.5, 0.5, 0.5]}}
nodes:
  - grid: {{name: r, rows: {rows}, cols: {cols}, origin: [2, 2], spacing: [6, 4]}}
    model: diffdrive
    sensors: {{laser: false, ir: {{count: 8, max_range: 1.0}}}}
    controller: {{{controller}, rate: 10, params: {{waypoints: [[1000, 2]], speed: 0.5}}}}
outputs: {{figures: false, trace: false}}
"""


def run(sanet, folder, tag, text):
    path = os.path.join(folder, tag + ".yaml")
    with open(path, "w") as f:
        f.write(text)
    out = os.path.join(folder, tag)
    subprocess.run([sanet, "run", path, "-o", out, "-q", "--no-progress", "--python-path",
                    os.path.join(ROOT, "examples", "python")], check=True)
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sanet", default=os.path.join(ROOT, "build", "sanet"))
    parser.add_argument("--seconds", type=float, default=10)
    parser.add_argument("--robots", default="1,100,1000")
    a = parser.parse_args()
    print(f"{'robots':>7} {'controller':>10} {'step us':>9} {'ratio':>6} {'wall s':>7} {'control %':>9} {'rt factor':>9}")
    with tempfile.TemporaryDirectory() as folder:
        for robots in (int(n) for n in a.robots.split(",")):
            steps = robots * a.seconds * 10
            base = None
            for tag, controller in (("C++", "name: waypoint"), ("Python", 'python: "waypoint:Waypoint"')):
                s = run(a.sanet, folder, f"{tag}-{robots}", scenario(robots, a.seconds, controller))
                per_step = s["profile_s"]["controllers"] / steps * 1e6
                base = base or per_step
                share = 100 * s["profile_s"]["controllers"] / s["wall_time_s"]
                print(f"{robots:>7} {tag:>10} {per_step:>9.2f} {per_step / base:>6.1f} {s['wall_time_s']:>7.3f} "
                      f"{share:>9.1f} {s['real_time_factor']:>9.1f}", flush=True)


if __name__ == "__main__":
    main()
