#!/usr/bin/env python3
"""Real-time lag of `sanet serve` with 4, 16 and 32 robots, each driven by its own agent process
(constant_velocity, 10 Hz), physics step 5 ms, sensors at 10 Hz. Prints the lag percentiles and
their ratio to the physics step (the deadline) and to the 4-robot run, measured in this run.

    bench/hil_lag.py build/sanet [seconds per case, default 20]"""
import json
import os
import subprocess
import sys
import tempfile

sanet = sys.argv[1]
seconds = float(sys.argv[2]) if len(sys.argv) > 2 else 20
print(f"sanet real-time lag: physics step 5 ms, sensors 10 Hz, {seconds:.0f} s per case, one agent process per robot")
print(f"{'robots':>6} {'p50 ms':>8} {'p99 ms':>8} {'max ms':>8} {'missed':>8} {'p99/step':>9} {'p99 vs 4':>9}   server")
base = None
for count in (4, 16, 32):
    with tempfile.TemporaryDirectory() as tmp:
        lines = [f"duration: {seconds}", "nodes:"]
        for i in range(count):
            lines.append(f"  - {{name: r{i}, model: diffdrive, pose: [{3 * (i % 8)}, {3 * (i // 8)}, 0], "
                         f"controller: {{name: constant_velocity, params: {{vx: 0.2, omega: 0.2}}}}}}")
        path = os.path.join(tmp, "lag.yaml")
        open(path, "w").write("\n".join(lines) + "\n")
        out = subprocess.run([sanet, "launch", path, "-o", os.path.join(tmp, "out"), "--udp-base", "48000"],
                             capture_output=True, text=True, timeout=seconds + 120)
        if out.returncode != 0:
            sys.exit(out.stdout + out.stderr)
        lag = json.load(open(os.path.join(tmp, "out", "summary.json")))["real_time_lag"]
        p99 = lag["p99_s"]
        base = base or max(p99, 1e-6)
        print(f"{count:>6} {1000 * lag['p50_s']:>8.2f} {1000 * p99:>8.2f} {1000 * lag['max_s']:>8.2f} "
              f"{lag['missed_deadlines']:>8} {p99 / lag['deadline_s']:>9.2f} {p99 / base:>9.2f}   "
              f"{lag.get('scheduling', '')}", flush=True)
