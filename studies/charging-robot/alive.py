#!/usr/bin/env python3
"""The motes alive over time in two runs of scenarios/charging-robot.yaml (with the charging robot
and without it), from each run's energy.csv, as one figure; and the motes' lifetime in each run
(from summary.json's energy.nodes: the robot, which lives on its dock, is left out) as a table.
Usage: alive.py WITH_FOLDER WITHOUT_FOLDER FIGURE.svg"""
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("svg")
import matplotlib.pyplot as plt  # noqa: E402


def alive_over_time(folder, robot):
    """[(time, motes alive)] from energy.csv: a mote is alive while its charge is above 0."""
    alive = {}
    with open(os.path.join(folder, "energy.csv"), newline="") as f:
        for row in csv.DictReader(f):
            if row["node"] == robot:
                continue
            t = float(row["time"])
            alive[t] = alive.get(t, 0) + (float(row["remaining_j"]) > 0)
    return sorted(alive.items())


def mote_deaths(folder, robot):
    """The motes' deaths (s, sorted) and how many motes there are."""
    with open(os.path.join(folder, "summary.json")) as f:
        nodes = json.load(f)["energy"]["nodes"]
    motes = {name: node for name, node in nodes.items() if name != robot}
    return sorted(node["died_s"] for node in motes.values() if node["died_s"] is not None), len(motes)


def seconds(value):
    return "none" if value is None else f"{value:.0f} s"


def main(with_folder, without_folder, figure):
    fig, ax = plt.subplots(figsize=(7, 3.6))
    for folder, label, style in ((with_folder, "with the charging robot", "-"),
                                 (without_folder, "without it", "--")):
        points = alive_over_time(folder, "charger")
        ax.step([t for t, _ in points], [n for _, n in points], style, where="post", label=label)
    ax.set_xlabel("time (s)")
    ax.set_ylabel("motes alive")
    ax.set_ylim(bottom=0)
    ax.set_title("A robot keeps a sensor network alive (12 motes)")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="lower left")
    fig.tight_layout()
    fig.savefig(figure, metadata={"Date": None})
    print("| run | first death | half dead | last death | dead at the end |")
    print("| --- | --- | --- | --- | --- |")
    for folder, label in ((with_folder, "with the robot"), (without_folder, "without it")):
        deaths, motes = mote_deaths(folder, "charger")
        kth = lambda k: deaths[k - 1] if len(deaths) >= k else None  # noqa: E731
        print(f"| {label} | {seconds(kth(1))} | {seconds(kth((motes + 1) // 2))} | {seconds(kth(motes))} | "
              f"{len(deaths)} of {motes} |")
    print(f"figure: {figure}")


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    main(*sys.argv[1:])
