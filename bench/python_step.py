#!/usr/bin/env python3
"""What stepping a run from Python costs: the formation (scenarios/formation.yaml: four robots,
their controllers and 802.11b radio) for 60 simulated seconds, run in one `sanet run` (the
baseline, measured in the same run), in one Simulation.run() call, and stepped with
Simulation.step(dt) at dt = 1, 0.1 and 0.01 s, each reading every robot's pose between steps as
a script would. It prints each run's own wall time (summary.json's wall_time_s, which
Simulation.finish() returns as `wall`: loading and writing excluded), its ratio to `sanet run`
and to one Simulation.run() (the module's own baseline: a process without sanet's tcmalloc), and
the cost per step over Simulation.run(), which is within the runs' noise; then the cost of the
calls themselves, timed over many: a step that advances nothing, and a pose read.

  PYTHONPATH=build/python /usr/bin/python3 bench/python_step.py [--sanet build/sanet] [--seconds 60] [--repeat 3]
"""
import argparse
import json
import os
import subprocess
import tempfile
import time

import sanet

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENARIO = os.path.join(ROOT, "scenarios", "formation.yaml")
ROBOTS = ("leader", "f1", "f2", "f3")


def stepped(folder, seconds, dt):
    steps = 0
    sim = sanet.Simulation(SCENARIO, duration=seconds, output=folder, force=True)
    if dt is None:
        sim.run()
    else:
        while sim.step(dt):
            steps += 1
            for robot in ROBOTS:
                sim.pose(robot)
    return sim.finish()["wall"], steps


def sanet_run(command, out, seconds):
    subprocess.run([command, "run", SCENARIO, "--duration", str(seconds), "-o", out, "-q", "--force"], check=True)
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)["wall_time_s"]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sanet", default=os.path.join(ROOT, "build", "sanet"))
    parser.add_argument("--seconds", type=float, default=60)
    parser.add_argument("--repeat", type=int, default=3, help="runs of each case; the fastest counts")
    a = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "run")
        base = min(sanet_run(a.sanet, out, a.seconds) for _ in range(a.repeat))
        print(f"{'case':>18} {'wall s':>8} {'/ sanet run':>12} {'/ run()':>8} {'steps':>6} {'us per step':>12}")
        print(f"{'sanet run':>18} {base:>8.3f} {1.0:>12.2f}")
        one = None
        for label, dt in (("Simulation.run()", None), ("step(1)", 1.0), ("step(0.1)", 0.1), ("step(0.01)", 0.01)):
            wall, steps = min(stepped(os.path.join(tmp, label), a.seconds, dt) for _ in range(a.repeat))
            one = one or wall
            per_step = f"{(wall - one) / steps * 1e6:12.1f}" if steps else f"{'':>12}"
            print(f"{label:>18} {wall:>8.3f} {wall / base:>12.2f} {wall / one:>8.2f} {steps:>6} {per_step}",
                  flush=True)
        step, pose = call_costs(os.path.join(tmp, "calls"))
        print(f"step(0): {step:.2f} us a call; pose(): {pose:.2f} us a call")


def call_costs(folder, calls=20000):
    """us per step(0) (the crossing into the run and back, nothing to simulate) and per pose()."""
    with sanet.Simulation(SCENARIO, duration=10, output=folder, force=True) as sim:
        sim.step(1)
        start = time.perf_counter()
        for _ in range(calls):
            sim.step(0)
        step = (time.perf_counter() - start) / calls * 1e6
        start = time.perf_counter()
        for _ in range(calls):
            sim.pose("leader")
        pose = (time.perf_counter() - start) / calls * 1e6
    return step, pose


if __name__ == "__main__":
    main()
