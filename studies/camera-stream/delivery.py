#!/usr/bin/env python3
"""The pictures of a run of scenarios/camera-stream.yaml, from its log.csv: each the rover sent
(`sent FRAME BYTES DRIVEN`) and each the operator received (`frame FRAME BYTES DRIVEN DELAY
whole|cut`), by the rover's distance from the operator in bins of 5 m: the share delivered and the
median delay, as a figure of two panels and a table. With --ros2, the same of a launch of
scenarios/ros2-camera-radio.yaml beside it: the pictures examples/ros2/image_relay logged (the
rover's ROVER-sent.csv and the operator's OPERATOR.csv in PICTURES), placed by the launch's
trajectories.csv (in RUN), a picture whole when its pixels' CRC-32 is the one sent.
Usage: delivery.py RUN_FOLDER FIGURE.svg [--ros2 RUN PICTURES]"""
import bisect
import csv
import math
import os
import statistics
import sys

import matplotlib

matplotlib.use("svg")
import matplotlib.pyplot as plt  # noqa: E402

BIN = 5.0  # m
START = 2.0  # m: the rover starts this far from the operator, and drives away


def pictures(folder):
    """{frame: (distance m, bytes)} sent, {frame: (delay s, whole)} received."""
    sent, received = {}, {}
    with open(os.path.join(folder, "log.csv"), newline="") as f:
        for row in csv.DictReader(f):
            words = row["text"].split()
            if row["node"] == "rover" and words[0] == "sent":
                sent[int(words[1])] = (START + float(words[3]), int(words[2]))
            elif row["node"] == "operator" and words[0] == "frame":
                received[int(words[1])] = (float(words[4]), words[5] == "whole")
    return sent, received


def rows_of(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def distance_at(trajectories, t):
    """The rover's distance from the operator at t (s), between the two trajectory samples around it."""
    def position(node):
        times, points = trajectories[node]
        i = min(max(bisect.bisect_left(times, t), 1), len(times) - 1)
        (t0, p0), (t1, p1) = (times[i - 1], points[i - 1]), (times[i], points[i])
        w = 0.0 if t1 == t0 else min(max((t - t0) / (t1 - t0), 0.0), 1.0)
        return p0[0] + w * (p1[0] - p0[0]), p0[1] + w * (p1[1] - p0[1])
    return math.dist(position("rover"), position("operator"))


def ros2_pictures(run, pictures):
    """As pictures(), for the pictures image_relay relayed over the radio in a launch: keyed by stamp."""
    trajectories = {}
    for r in rows_of(os.path.join(run, "trajectories.csv")):
        times, points = trajectories.setdefault(r["node"], ([], []))
        times.append(float(r["time"]))
        points.append((float(r["x"]), float(r["y"])))
    sent = {r["stamp"]: (distance_at(trajectories, float(r["stamp"])), int(r["bytes"]), r["crc32"])
            for r in rows_of(os.path.join(pictures, "rover-sent.csv"))}
    received = {r["stamp"]: (float(r["heard_at"]) - float(r["stamp"]) if r["heard_at"] else None,  # none before /clock
                             r["crc32"] == sent.get(r["stamp"], (0, 0, ""))[2])
                for r in rows_of(os.path.join(pictures, "operator.csv")) if r["peer"] == "rover"}
    return {k: v[:2] for k, v in sent.items()}, received


def by_distance(sent, received):
    """[(bin's middle m, sent, delivered, median delay ms or None)]"""
    bins = {}
    for frame, (distance, _) in sent.items():
        bins.setdefault(int(distance // BIN), []).append(frame)
    rows = []
    for b in sorted(bins):
        frames = bins[b]
        delivered = [f for f in frames if f in received]
        delays = [received[f][0] * 1000 for f in delivered if received[f][0] is not None]
        rows.append(((b + 0.5) * BIN, len(frames), len(delivered), statistics.median(delays) if delays else None))
    return rows


def table(title, sent, received):
    """Prints the pictures by distance; returns the rows."""
    cut = sum(not whole for _, whole in received.values())
    rows = by_distance(sent, received)
    sizes = [size for _, size in sent.values()]
    print(f"{title}: {len(sent)} pictures sent ({min(sizes)} to {max(sizes)} bytes), {len(received)} delivered, "
          f"{cut} cut")
    print(f"{'distance m':>10} {'sent':>5} {'delivered':>9} {'share':>6} {'median delay ms':>15}")
    for middle, n, got, delay in rows:
        print(f"{middle:10.1f} {n:5d} {got:9d} {got / n:6.2f} {'-' if delay is None else f'{delay:.1f}':>15}")
    return rows


def plot(series, figure):
    """series: [(label, rows, colour)], side by side in each bin."""
    fig, (share, delay) = plt.subplots(2, 1, sharex=True, figsize=(6.4, 5.6))
    width = BIN * 0.8 / len(series)
    for k, (label, rows, colour) in enumerate(series):
        shift = (k - (len(series) - 1) / 2) * width
        share.bar([r[0] + shift for r in rows], [r[2] / r[1] for r in rows], width=width, color=colour, label=label)
        with_delay = [r for r in rows if r[3] is not None]
        delay.plot([r[0] for r in with_delay], [r[3] for r in with_delay], "o-", color=colour, label=label)
    share.set_ylabel("pictures delivered")
    share.set_ylim(0, 1.05)
    share.set_title("a rover's pictures over 802.11g")
    delay.set_ylabel("median delay (ms)")
    delay.set_xlabel("distance from the operator (m)")
    if len(series) > 1:
        share.legend(loc="lower left", fontsize="small")
    fig.tight_layout()
    os.makedirs(os.path.dirname(os.path.abspath(figure)), exist_ok=True)
    fig.savefig(figure, metadata={"Date": None})
    print(f"figure: {figure}")


def main():
    args = sys.argv[1:]
    if len(args) not in (2, 5) or (len(args) == 5 and args[2] != "--ros2"):
        sys.exit(__doc__.splitlines()[-1])
    sent, received = pictures(args[0])
    series = [("sanet's messages (sanet run)", table("sanet's messages", sent, received), "#3264c8")]
    if len(args) == 5:
        sent, received = ros2_pictures(args[3], args[4])
        series.append(("ROS 2 over the radio (sanet launch)", table("ROS 2 over the radio", sent, received),
                       "#c84632"))
    plot(series, args[1])


if __name__ == "__main__":
    main()
