#!/usr/bin/env python3
"""A study's database in Python: a metric's mean and 95 % confidence interval per value of the
first varied parameter, with nothing but the standard library; with pandas and matplotlib
installed, the same as a data frame and a plot.

  examples/study_in_python.py STUDY_FOLDER [METRIC] [PLOT.png]
  examples/study_in_python.py results/aodv-discovery/ring network.route_discoveries.time_s.median
"""
import math
import os
import sqlite3
import statistics
import sys

T95 = [12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228]  # Student's t, 1-10 dof


def main():
    folder = sys.argv[1]
    metric = sys.argv[2] if len(sys.argv) > 2 else "ended_at_s"
    db = sqlite3.connect(os.path.join(folder, "study.sqlite"))
    parameter = db.execute("SELECT value FROM study WHERE key = 'parameters'").fetchone()[0].split("\n")[0]
    rows = db.execute("""
        SELECT p.value, s.value FROM runs r
        JOIN parameters p ON p.run = r.id AND p.name = ?
        JOIN scalars s ON s.run = r.id AND s.name = ?
        WHERE r.status = 'completed' ORDER BY r.id""", (parameter, metric)).fetchall()
    by_value = {}
    for value, x in rows:
        by_value.setdefault(value, []).append(x)
    print("%s by %s" % (metric, parameter))
    for value, xs in by_value.items():
        mean = statistics.fmean(xs)
        half = T95[min(len(xs), 11) - 2] * statistics.stdev(xs) / math.sqrt(len(xs)) if len(xs) > 1 else 0
        print("  %-12s runs %3d  mean %.6g  95%% CI [%.6g, %.6g]" % (value, len(xs), mean, mean - half, mean + half))
    try:
        import pandas as pd
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return  # the standard library has done the work
    frame = pd.DataFrame(rows, columns=[parameter, metric])
    stats = frame.groupby(parameter, sort=False)[metric].agg(["mean", "sem", "count"])
    print(stats)
    if len(sys.argv) > 3:
        stats["mean"].plot(yerr=1.96 * stats["sem"], marker="o", capsize=4)
        plt.ylabel(metric)
        plt.savefig(sys.argv[3])


if __name__ == "__main__":
    main()
