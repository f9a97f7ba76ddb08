#!/usr/bin/env python3
"""A study's database in Python: a metric's mean and 95 % confidence interval per value of the
first varied parameter (a line per combination of the others, as `sanet report` groups them),
with nothing but the standard library; with pandas and matplotlib installed, the same as a data
frame and a plot.

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
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    folder = sys.argv[1]
    metric = sys.argv[2] if len(sys.argv) > 2 else "ended_at_s"
    db = sqlite3.connect(os.path.join(folder, "study.sqlite"))
    parameters = [p for p in db.execute("SELECT value FROM study WHERE key = 'parameters'").fetchone()[0].split("\n")
                  if p]
    if not db.execute("SELECT 1 FROM scalars WHERE name = ? LIMIT 1", (metric,)).fetchone():
        sys.exit("no run has a metric '%s' (sanet report %s --list lists them)" % (metric, folder))
    # One row per completed run: its values of the varied parameters, and the metric.
    runs = {}
    for run, name, value in db.execute("SELECT run, name, value FROM parameters"):
        runs.setdefault(run, {})[name] = value
    rows = [(runs.get(run, {}), x) for run, x in db.execute(
        "SELECT s.run, s.value FROM scalars s JOIN runs r ON r.id = s.run "
        "WHERE r.status = 'completed' AND s.name = ? ORDER BY s.run", (metric,))]
    by = parameters[0] if parameters else None
    groups = {}  # (the other parameters' values, the value of `by`) -> samples
    for values, x in rows:
        others = ", ".join("%s=%s" % (p, values[p]) for p in parameters[1:])
        groups.setdefault((others, values.get(by, "all")), []).append(x)
    print("%s by %s" % (metric, by or "(seeds only)"))
    for (others, value), xs in groups.items():
        mean = statistics.fmean(xs)
        half = T95[min(len(xs), 11) - 2] * statistics.stdev(xs) / math.sqrt(len(xs)) if len(xs) > 1 else 0
        print("  %-12s runs %3d  mean %.6g  95%% CI [%.6g, %.6g]  %s" % (value, len(xs), mean, mean - half,
                                                                     mean + half, others))
    try:
        import pandas as pd
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        if len(sys.argv) > 3:
            print("no plot: pandas and matplotlib are not installed (Debian: python3-pandas python3-matplotlib)")
        return  # the standard library has done the work
    frame = pd.DataFrame([dict(values, **{metric: x}) for values, x in rows])
    stats = frame.groupby(parameters or [lambda _: "all"], sort=False)[metric].agg(["mean", "sem", "count"])
    print(stats)
    if len(sys.argv) > 3:
        stats["mean"].plot(yerr=1.96 * stats["sem"], marker="o", capsize=4)
        plt.ylabel(metric)
        plt.savefig(sys.argv[3])


if __name__ == "__main__":
    main()
