#!/usr/bin/env python3
"""sanet launch runs the formation with four agent processes over real UDP (loopback),
shortened to 25 s: the robots keep their distances and the followers hear the leader."""
import json
import os
import subprocess
import sys
import tempfile

sanet, source = sys.argv[1], sys.argv[2]
with tempfile.TemporaryDirectory() as tmp:
    out = subprocess.run([sanet, "launch", os.path.join(source, "scenarios", "formation-hil.yaml"), "--duration", "25",
                          "-o", tmp, "--udp-base", "47500"], capture_output=True, text=True, timeout=120)
    print(out.stdout, out.stderr)
    assert out.returncode == 0, out.returncode
    assert out.stdout.count("agent ") == 4, out.stdout
    summary = json.load(open(os.path.join(tmp, "summary.json")))
    assert summary["min_distance"]["min_m"] > 0.4, summary["min_distance"]
    assert summary["min_distance"]["fraction_within_10_percent"] > 0.8, summary["min_distance"]
    for follower in ("f1", "f2", "f3"):
        heard = summary["metrics"][follower]["pose_delay"]["count"]
        assert heard > 150, (follower, heard)  # 10 Hz for 25 s
    leader = [r for r in open(os.path.join(tmp, "trajectories.csv")) if ",leader," in r]
    assert float(leader[-1].split(",")[2]) > 5, "the leader drove"
    print("lag:", summary["real_time_lag"])
