#!/usr/bin/env python3
"""A notebook-style study by stepping: the built-in around-the-wall run at four cruise speeds,
each stepped a second at a time until the robot logs its arrival, its time and path length
collected as it goes, then plotted (matplotlib) and tabulated (pandas).

  PYTHONPATH=build/python /usr/bin/python3 examples/python/sweep_by_stepping.py [OUT_FOLDER]
"""
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt  # noqa: E402
import pandas  # noqa: E402

import sanet  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCENARIO = os.path.join(ROOT, "scenarios", "around-the-wall.yaml")


def one_run(speed, out):
    """Steps one run to its end; returns its arrival time and the path the robot drove."""
    path, last = 0.0, None
    with sanet.Simulation(SCENARIO, set={"nodes.robot.controller.params.speed": speed}, output=out,
                          force=True) as sim:
        while sim.step(1.0):
            pose = sim.pose("robot")
            if last is not None:
                path += math.hypot(pose.x - last.x, pose.y - last.y)
            last = pose
        ended = sim.finish()
    return {"speed": speed, "arrival_s": sanet.Results(out).summary["ended_at_s"], "path_m": path,
            "ended_by": ended["ended_by"]}


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "results/sweep-by-stepping"
    rows = [one_run(speed, os.path.join(out, f"speed-{speed}")) for speed in (0.3, 0.5, 0.8, 1.2)]
    table = pandas.DataFrame(rows)
    print(table.to_string(index=False))
    figure, axis = plt.subplots(figsize=(5, 3.5))
    axis.plot(table["speed"], table["arrival_s"], "o-")
    axis.set_xlabel("cruise speed (m/s)")
    axis.set_ylabel("arrival (s)")
    axis.set_title("around-the-wall: arrival against speed")
    figure.tight_layout()
    figure.savefig(os.path.join(out, "arrival.png"), dpi=100)
    table.to_csv(os.path.join(out, "arrival.csv"), index=False)
    print(f"plot in {os.path.join(out, 'arrival.png')}")


if __name__ == "__main__":
    main()
