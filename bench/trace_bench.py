#!/usr/bin/env python3
"""The run's trace, both of its files: trace.sqlite (sanet's viewer, SQL) and trace.mcap (ROS 2
messages for ROS 2 tools, Foxglove and PlotJuggler), written from the same event stream. Runs each
scenario with the trace off (the baseline, measured in the same run) and on, the same seed, and
prints for each file its size, its bytes per simulated second and the wall time its writer took
(summary.json's profile_s.trace, timed around each writer's calls), then the MCAP file's ratios to
the SQLite one, and the whole run's wall time on against off. The fingerprints must be the same.

    bench/trace_bench.py [--sanet build/sanet] [--duration S] [scenario ...]
    (default: help-request, and swarm-1k for 60 simulated seconds)"""
import argparse
import json
import os
import subprocess
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT = [(os.path.join(ROOT, "scenarios", "help-request.yaml"), None),
           (os.path.join(ROOT, "scenarios", "swarm-1k.yaml"), 60)]


def run(sanet, scenario, duration, trace, out):
    extra = ["--duration", str(duration)] if duration else []
    subprocess.run([sanet, "run", scenario, "-q", "-o", out, "--set", f"outputs.trace={str(trace).lower()}", *extra],
                   check=True)
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sanet", default=os.path.join(ROOT, "build", "sanet"))
    parser.add_argument("--duration", type=float, help="simulated seconds of every scenario given")
    parser.add_argument("scenarios", nargs="*")
    a = parser.parse_args()
    cases = [(s, a.duration) for s in a.scenarios] or DEFAULT
    print(f"{'scenario':>13} {'file':>7} {'MB':>7} {'kB/sim s':>9} {'write s':>8}   "
          f"{'mcap/sqlite size':>16} {'time':>6}   {'run on/off':>10}  fingerprint")
    for scenario, duration in cases:
        with tempfile.TemporaryDirectory() as tmp:
            off = run(a.sanet, scenario, duration, False, os.path.join(tmp, "off"))
            on = run(a.sanet, scenario, duration, True, os.path.join(tmp, "on"))
            sizes = {kind: os.path.getsize(os.path.join(tmp, "on", f"trace.{kind}")) for kind in ("sqlite", "mcap")}
        simulated = on["simulated_s"] if "simulated_s" in on else on["duration_s"]
        cost = on["profile_s"]["trace"]
        name = os.path.splitext(os.path.basename(scenario))[0]
        same = "same" if on["fingerprint"] == off["fingerprint"] else "DIFFERENT"
        for kind in ("sqlite", "mcap"):
            ratios = (f"{sizes['mcap'] / sizes['sqlite']:>16.2f} {cost['mcap'] / max(cost['sqlite'], 1e-9):>6.2f}"
                      if kind == "mcap" else f"{'':>16} {'':>6}")
            run_ratio = f"{on['wall_time_s'] / off['wall_time_s']:>10.2f}  {same}" if kind == "mcap" else ""
            print(f"{name:>13} {kind:>7} {sizes[kind] / 1e6:>7.2f} {sizes[kind] / simulated / 1e3:>9.1f} "
                  f"{cost[kind]:>8.2f}   {ratios}   {run_ratio}", flush=True)


if __name__ == "__main__":
    main()
