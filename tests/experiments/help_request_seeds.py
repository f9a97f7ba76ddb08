#!/usr/bin/env python3
"""Case study 1 is robust: with ten seeds the robot reaches the target in every run."""
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
    assert sweep["ended_by_condition"] == 10, "the robot did not arrive in every run"
    for run in sweep["per_seed"]:
        assert run["ended_by"] == "'arrived' logged by robot", run
    end = sweep["end_time_s"]
    print(f"arrival: mean {end['mean']:.1f} s, 95% CI [{end['ci95'][0]:.1f}, {end['ci95'][1]:.1f}] s")
