#!/usr/bin/env python3
"""The run's trace (trace.sqlite): its size and what it costs. Runs each scenario with the trace
on and off (the same seed) and prints the trace's size, the wall time of each and their ratio.

    bench/trace_bench.py build/sanet [scenario ...]   (default: help-request and formation)"""
import json
import os
import subprocess
import sys
import tempfile

sanet = sys.argv[1]
here = os.path.dirname(os.path.abspath(__file__))
scenarios = sys.argv[2:] or [os.path.join(here, "..", "scenarios", n + ".yaml") for n in ("help-request", "formation")]


def wall(scenario, trace, folder):
    with open(scenario) as f:
        text = f.read()
    text = text.replace("outputs:\n", f"outputs:\n  trace: {'true' if trace else 'false'}\n") if "outputs:\n" in text \
        else text + f"\noutputs:\n  trace: {'true' if trace else 'false'}\n"
    path = os.path.join(folder, "s.yaml")
    with open(path, "w") as f:
        f.write(text)
    out = os.path.join(folder, "on" if trace else "off")
    subprocess.run([sanet, "run", path, "-q", "-o", out], check=True)
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    size = os.path.getsize(os.path.join(out, "trace.sqlite")) if trace else 0
    return summary["wall_time_s"], summary["real_time_factor"], size, summary["fingerprint"]


print(f"{'scenario':>14} {'trace MB':>9} {'wall off s':>11} {'wall on s':>10} {'on/off':>7} {'rtf on':>8}  fingerprint")
for scenario in scenarios:
    with tempfile.TemporaryDirectory() as tmp:
        off = wall(scenario, False, tmp)
        on = wall(scenario, True, tmp)
    same = "same" if on[3] == off[3] else "DIFFERENT"
    name = os.path.splitext(os.path.basename(scenario))[0]
    print(f"{name:>14} {on[2] / 1e6:>9.2f} {off[0]:>11.2f} {on[0]:>10.2f} {on[0] / off[0]:>7.2f} {on[1]:>8.1f}  {same}",
          flush=True)
