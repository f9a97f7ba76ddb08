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
import json
import os
import subprocess
import sys
import tempfile

sanet, source = sys.argv[1], sys.argv[2]
with tempfile.TemporaryDirectory() as tmp:
    out = subprocess.run([sanet, "sweep", os.path.join(source, "scenarios", "help-request.yaml"),
                          "--seeds", "1-10", "-o", tmp], capture_output=True, text=True, timeout=580)
    print(out.stdout, out.stderr)
    assert out.returncode == 0, out.returncode
    sweep = json.load(open(os.path.join(tmp, "sweep.json")))
    assert sweep["runs"] == 10, sweep["runs"]
    assert sweep["ended_by_condition"] >= 9, "the robot arrived in fewer than nine runs"
    for run in sweep["per_seed"]:
        if run["ended_by"] == "'arrived' logged by robot":
            continue
        with open(os.path.join(tmp, "seed-%d" % run["seed"], "transitions.csv")) as f:
            gave_up = [r for r in csv.DictReader(f) if r["node"] == "robot" and r["why"].startswith("gave up")]
        assert gave_up, ("a run that did not arrive must be one where the robot gave up", run)
    end = sweep["end_time_s"]
    print(f"arrival: mean {end['mean']:.1f} s, 95% CI [{end['ci95'][0]:.1f}, {end['ci95'][1]:.1f}] s")
