#!/usr/bin/env python3
"""Case study 1 is robust: with ten seeds the robot reaches the target in at least nine runs,
within about a minute of the others. A run where it does not must be one where the robot gave
up after asking the target three times (its unicasts lost on the last hop), as the case study
allows, and not a crash or a hang.

Why not ten: with sanet's default (indexed) channel, seed 3 loses the robot's three requests
at the target's last hop, where two hidden neighbours' ARP retries collide at the target at the
same instant, once a second (docs/network.md#the-indexed-channel). With ns-3's Yans channel the
same seed arrives; seeds 11-30 arrive on both channels."""
import csv
import os
import sqlite3
import subprocess
import sys
import tempfile

sanet, source = sys.argv[1], sys.argv[2]
with tempfile.TemporaryDirectory() as tmp:
    out = subprocess.run([sanet, "sweep", os.path.join(source, "scenarios", "help-request.yaml"),
                          "--seeds", "1-10", "-o", tmp], capture_output=True, text=True, timeout=580)
    print(out.stdout, out.stderr)
    assert out.returncode == 0, out.returncode
    with sqlite3.connect(os.path.join(tmp, "study.sqlite")) as db:
        runs = list(db.execute("SELECT seed, status, ended_by, ended_at_s, folder FROM runs ORDER BY seed"))
    assert len(runs) == 10 and all(r[1] == "completed" for r in runs), runs
    arrived = [r for r in runs if r[2] == "'arrived' logged by robot"]
    assert len(arrived) >= 9, "the robot arrived in fewer than nine runs"
    for seed, _, ended_by, _, folder in runs:
        if ended_by == "'arrived' logged by robot":
            continue
        with open(os.path.join(tmp, folder, "transitions.csv")) as f:
            gave_up = [r for r in csv.DictReader(f) if r["node"] == "robot" and r["why"].startswith("gave up")]
        assert gave_up, ("a run that did not arrive must be one where the robot gave up", seed)
    times = [r[3] for r in arrived]
    print(f"arrival: mean {sum(times) / len(times):.1f} s over {len(times)} runs")
