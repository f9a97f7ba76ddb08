#!/usr/bin/env python3
"""What radio_contacts.csv costs: each scenario run with outputs.radio_contacts off and on, the
same seed, best of three wall times of the whole command (writing the files included), both with
the trace on (the default up to 200 nodes: its frames are heard anyway, so contacts add only their
own bookkeeping) and with the trace off (contacts alone make the network trace every frame: the
worst case). Off and on run in turns; the best of each is kept, of the wall time and of the CPU
time (user + system, steadier on a busy machine). Prints the ratios on/off, the number of frames
received and of contacts, and whether the fingerprints are the same (they must be).

    bench/radio_contacts_bench.py [--sanet build/sanet] [--duration S] [--repeat N] [scenario ...]
    (default: help-request and scattered-field)"""
import argparse
import json
import os
import resource
import subprocess
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT = [os.path.join(ROOT, "scenarios", name + ".yaml") for name in ("help-request", "scattered-field")]


def run(sanet, scenario, out, sets, duration):
    """Wall and CPU seconds (user + system) of one whole command, and its summary."""
    command = [sanet, "run", scenario, "-q", "-o", out] + (["--duration", str(duration)] if duration else [])
    for s in sets:
        command += ["--set", s]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run(command, check=True, stderr=subprocess.DEVNULL)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime
    with open(os.path.join(out, "summary.json")) as f:
        return wall, cpu, json.load(f)


def best_of(sanet, scenario, tmp, trace, repeat, duration):
    """Off and on taken in turns, so that a busy moment of the machine hits both alike."""
    times = {"false": [], "true": []}
    summaries = {}
    for _ in range(repeat):
        for contacts in ("false", "true"):
            wall, cpu, summaries[contacts] = run(sanet, scenario, os.path.join(tmp, contacts),
                                                 [f"outputs.trace={trace}", f"outputs.radio_contacts={contacts}"],
                                                 duration)
            times[contacts].append((wall, cpu))
    best = {k: (min(w for w, _ in v), min(c for _, c in v)) for k, v in times.items()}
    return best["false"], best["true"], summaries["false"], summaries["true"]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sanet", default=os.path.join(ROOT, "build", "sanet"))
    parser.add_argument("--duration", type=float, help="simulated seconds of every scenario")
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("scenarios", nargs="*")
    a = parser.parse_args()
    print(f"{'scenario':>16} {'trace':>5} {'wall off':>8} {'on':>6} {'on/off':>6}   {'cpu off':>7} {'on':>6} "
          f"{'on/off':>6}  {'frames rx':>9} {'contacts':>8}  fingerprint")
    for scenario in a.scenarios or DEFAULT:
        name = os.path.splitext(os.path.basename(scenario))[0]
        for trace in ("true", "false"):
            with tempfile.TemporaryDirectory() as tmp:
                off, on, s_off, s_on = best_of(a.sanet, scenario, tmp, trace, a.repeat, a.duration)
            same = "same" if s_on["fingerprint"] == s_off["fingerprint"] else "DIFFERENT"
            frames = s_on.get("network", {}).get("channel", {}).get("frames_received", 0)
            contacts = s_on.get("radio_contacts", {}).get("contacts", 0)
            print(f"{name:>16} {trace:>5} {off[0]:>8.2f} {on[0]:>6.2f} {on[0] / off[0]:>6.3f}   {off[1]:>7.2f} "
                  f"{on[1]:>6.2f} {on[1] / off[1]:>6.3f}  {frames:>9} {contacts:>8}  {same}", flush=True)


if __name__ == "__main__":
    main()
