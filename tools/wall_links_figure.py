#!/usr/bin/env python3
"""Draws what walls do to a run's radio: the links that carried frames (node pairs with at least
--min-frames frames received) over the building's plan, for a run with wall loss and the same
run without it, and the route discovery times of both. Prints the figures it draws.

    build/sanet run scenarios/help-request-indoor.yaml -o /tmp/walls
    build/sanet run scenarios/help-request-indoor.yaml --set world.obstacle_material=none -o /tmp/open
    /usr/bin/python3 tools/wall_links_figure.py /tmp/walls /tmp/open docs/figures/indoor-links.svg

Each folder must hold trace.sqlite (outputs.trace, on by default up to 200 nodes) and routes.csv."""
import argparse
import csv
import json
import math
import os
import sqlite3
import statistics
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.patches as patches  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402


def load(folder, min_frames):
    path = os.path.join(folder, "trace.sqlite")
    if not os.path.exists(path):
        sys.exit(f"{path}: no trace (run with outputs.trace on)")
    db = sqlite3.connect(path)
    nodes = {i: (name, x, y) for i, name, x, y in db.execute("SELECT id, name, x, y FROM nodes")}
    obstacles = list(db.execute("SELECT cx, cy, length, width, yaw FROM obstacles"))
    pairs = db.execute("SELECT MIN(node, peer), MAX(node, peer), COUNT(*) FROM frames "
                       "WHERE direction = 'rx' AND peer IS NOT NULL GROUP BY 1, 2").fetchall()
    links = [(a, b) for a, b, n in pairs if n >= min_frames and a != b]
    with open(os.path.join(folder, "routes.csv")) as f:
        discoveries = [float(r["duration"]) for r in csv.DictReader(f) if r["duration"]]
    with open(os.path.join(folder, "summary.json")) as f:
        summary = json.load(f)
    ended_at = summary.get("ended_at_s", summary["simulated_s"])  # the end condition's time, before its grace
    ended = f"ended at {ended_at:.1f} s ({summary['ended_by']})"
    return nodes, obstacles, links, discoveries, ended


def draw_plan(ax, nodes, obstacles, links, robot, title):
    for cx, cy, length, width, yaw in obstacles:
        c, s = math.cos(yaw), math.sin(yaw)
        corner = (cx - (length * c - width * s) / 2, cy - (length * s + width * c) / 2)
        ax.add_patch(patches.Rectangle(corner, length, width, angle=math.degrees(yaw), color="#555"))
    for a, b in links:
        if robot in (a, b):
            continue  # the robot's links change as it drives: the plan shows the motes'
        ax.plot([nodes[a][1], nodes[b][1]], [nodes[a][2], nodes[b][2]], color="#1f77b4", lw=1, alpha=0.7)
    for i, (name, x, y) in nodes.items():
        if i != robot:
            ax.plot(x, y, "s", color="#2a7f3f", ms=4)
    ax.set_title(title, fontsize=10)
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("walls", help="results of the run with wall loss")
    parser.add_argument("open", help="results of the same run without it")
    parser.add_argument("out", help="the figure (.svg or .png)")
    parser.add_argument("--min-frames", type=int, default=5, help="frames a pair must exchange to count as a link")
    parser.add_argument("--robot", default="robot", help="the robot's name (its links are left off the plan)")
    args = parser.parse_args()
    runs = [load(args.walls, args.min_frames), load(args.open, args.min_frames)]
    fig, axes = plt.subplots(3, 1, figsize=(8, 10), gridspec_kw={"height_ratios": [3, 3, 2]})
    for ax, (nodes, obstacles, links, _, ended), label in zip(axes, runs, ("with wall loss", "without wall loss")):
        robot = next((i for i, n in nodes.items() if n[0] == args.robot), None)
        count = sum(1 for a, b in links if robot not in (a, b))
        draw_plan(ax, nodes, obstacles, links, robot, f"{label}: {count} links between motes; {ended}")
        print(f"{label}: {count} links between motes; {ended}")
    ax = axes[2]
    for row, ((*_, discoveries, _), label) in enumerate(zip(runs, ("with wall loss", "without wall loss"))):
        ax.plot([d * 1000 for d in discoveries], [row] * len(discoveries), "o", alpha=0.6)
        if discoveries:
            print(f"{label}: {len(discoveries)} route discoveries, median {statistics.median(discoveries) * 1000:.1f} ms,"
                  f" longest {max(discoveries) * 1000:.1f} ms")
    ax.set_yticks([0, 1], ["with walls", "without"])
    ax.set_xscale("log")
    ax.set_xlabel("route discovery time (ms, log scale)")
    ax.set_ylim(-0.5, 1.5)
    fig.tight_layout()
    fig.savefig(args.out, metadata={"Date": None} if args.out.endswith(".svg") else None)


if __name__ == "__main__":
    main()
