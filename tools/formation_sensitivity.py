#!/usr/bin/env python3
"""Case study 2 under added message loss and delay: runs scenarios/formation.yaml with
messages.loss and messages.delay set, and prints a Markdown table of the smallest distance
between robots, the share of time within 10 % of 1.7 m, and the formation error (distance of
each follower from where the leader's true pose puts it, averaged over followers and time).

    tools/formation_sensitivity.py build/sanet [scenario]
"""
import csv
import json
import math
import os
import re
import subprocess
import sys
import tempfile

sanet = sys.argv[1]
scenario = sys.argv[2] if len(sys.argv) > 2 else os.path.join(os.path.dirname(__file__), "..", "scenarios", "formation.yaml")
text = open(scenario).read()
offsets = {m.group(1): (float(m.group(2)), float(m.group(3))) for m in re.finditer(
    r"name: (f\d)\n(?:.*\n)*?\s+offset: \[([-\d.]+), ([-\d.]+)\]", text)}

cases = [("none", 0, 0), ("10 % loss", 0.1, 0), ("30 % loss", 0.3, 0), ("50 % loss", 0.5, 0),
         ("50 ms delay", 0, 0.05), ("200 ms delay", 0, 0.2)]
print("| impairment | smallest distance (m) | time within 10 % of 1.7 m | formation error, mean (m) | formation error, max (m) | poses missed per pose received |")
print("| --- | --- | --- | --- | --- | --- |")
for name, loss, delay in cases:
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "formation.yaml")
        with open(path, "w") as f:
            f.write(text.replace("\nnodes:", f"\nmessages: {{loss: {loss}, delay: {delay}}}\n\nnodes:", 1))
        out = subprocess.run([sanet, "run", path, "-o", os.path.join(tmp, "out"), "-q"], capture_output=True, text=True)
        if out.returncode != 0:
            sys.exit(out.stderr)
        summary = json.load(open(os.path.join(tmp, "out", "summary.json")))
        rows = list(csv.DictReader(open(os.path.join(tmp, "out", "trajectories.csv"))))
        by_time = {}
        for r in rows:
            by_time.setdefault(r["time"], {})[r["node"]] = (float(r["x"]), float(r["y"]), float(r["theta"]))
        errors = []
        for t, poses in by_time.items():
            if "leader" not in poses or float(t) < 5:
                continue
            lx, ly, lt = poses["leader"]
            for follower, (dx, dy) in offsets.items():
                if follower in poses:
                    gx = lx + math.cos(lt) * dx - math.sin(lt) * dy
                    gy = ly + math.sin(lt) * dx + math.cos(lt) * dy
                    errors.append(math.hypot(poses[follower][0] - gx, poses[follower][1] - gy))
        missed = [v.get("pose_missed", {}).get("mean", 0) for v in summary["metrics"].values()]
        md = summary["min_distance"]
        print(f"| {name} | {md['min_m']:.2f} | {100 * md['fraction_within_10_percent']:.0f} % | "
              f"{sum(errors) / len(errors):.2f} | {max(errors):.2f} | {sum(missed) / len(missed):.2f} |")
