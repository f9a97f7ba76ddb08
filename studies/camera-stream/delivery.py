#!/usr/bin/env python3
"""The pictures of a run of scenarios/camera-stream.yaml, from its log.csv: each the rover sent
(`sent FRAME BYTES DRIVEN`) and each the operator received (`frame FRAME BYTES DRIVEN DELAY
whole|cut`), by the rover's distance from the operator in bins of 5 m: the share delivered and the
median delay, as a figure of two panels and a table.
Usage: delivery.py RUN_FOLDER FIGURE.svg"""
import csv
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


def by_distance(sent, received):
    """[(bin's middle m, sent, delivered, median delay ms or None)]"""
    bins = {}
    for frame, (distance, _) in sent.items():
        bins.setdefault(int(distance // BIN), []).append(frame)
    rows = []
    for b in sorted(bins):
        frames = bins[b]
        delays = [received[f][0] * 1000 for f in frames if f in received]
        rows.append(((b + 0.5) * BIN, len(frames), len(delays), statistics.median(delays) if delays else None))
    return rows


def main():
    folder, figure = sys.argv[1], sys.argv[2]
    sent, received = pictures(folder)
    cut = sum(not whole for _, whole in received.values())
    rows = by_distance(sent, received)
    sizes = [size for _, size in sent.values()]
    print(f"{len(sent)} pictures sent ({min(sizes)} to {max(sizes)} bytes), {len(received)} delivered, {cut} cut")
    print(f"{'distance m':>10} {'sent':>5} {'delivered':>9} {'share':>6} {'median delay ms':>15}")
    for middle, n, got, delay in rows:
        print(f"{middle:10.1f} {n:5d} {got:9d} {got / n:6.2f} {'-' if delay is None else f'{delay:.1f}':>15}")
    fig, (share, delay) = plt.subplots(2, 1, sharex=True, figsize=(6.4, 5.6))
    share.bar([r[0] for r in rows], [r[2] / r[1] for r in rows], width=BIN * 0.8, color="#3264c8")
    share.set_ylabel("pictures delivered")
    share.set_ylim(0, 1.05)
    share.set_title("a rover's pictures over 802.11g, a message each")
    with_delay = [r for r in rows if r[3] is not None]
    delay.plot([r[0] for r in with_delay], [r[3] for r in with_delay], "o-", color="#c84632")
    delay.set_ylabel("median delay (ms)")
    delay.set_xlabel("distance from the operator (m)")
    fig.tight_layout()
    os.makedirs(os.path.dirname(os.path.abspath(figure)), exist_ok=True)
    fig.savefig(figure, metadata={"Date": None})
    print(f"figure: {figure}")


if __name__ == "__main__":
    main()
