#!/usr/bin/env python3
"""Study throughput: runs per minute of `sanet sweep` with one and two runs at a time, and what the
sweep itself (a process per run, the results database) costs against plain `sanet run`s.

The same runs three ways, in one invocation, alternating, best of --repeat:

  plain runs         `sanet run` once per seed, one after the other, into plain folders (baseline)
  plain, two at once the same runs as two `sanet run` processes at a time: what this machine
                     gives two processes (a virtual machine's two cores may give far less than 2x)
  sweep, --jobs 1    `sanet sweep` of the same seeds, one at a time, into study.sqlite
  sweep, --jobs 2    the same, two at a time

and checks that the three give the same fingerprints.

  bench/sweep_bench.py [--sanet build/sanet] [--scenario scenarios/help-request.yaml]
                       [--seeds 4] [--duration 300] [--repeat 2]
"""
import argparse
import json
import os
import sqlite3
import subprocess
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def plain(sanet, scenario, seeds, duration, folder):
    prints = {}
    for seed in seeds:
        out = os.path.join(folder, "seed%d" % seed)
        subprocess.run([sanet, "run", scenario, "--seed", str(seed), "--duration", str(duration), "-q", "-o", out],
                       check=True)
        with open(os.path.join(out, "summary.json")) as f:
            prints[seed] = json.load(f)["fingerprint"]
    return prints


def plain_pairs(sanet, scenario, seeds, duration, folder):
    prints = {}
    for pair in (seeds[i:i + 2] for i in range(0, len(seeds), 2)):
        running = []
        for seed in pair:
            out = os.path.join(folder, "seed%d" % seed)
            running.append((seed, out, subprocess.Popen([sanet, "run", scenario, "--seed", str(seed), "--duration",
                                                         str(duration), "-q", "-o", out])))
        for seed, out, process in running:
            if process.wait() != 0:
                raise SystemExit("a run failed")
            with open(os.path.join(out, "summary.json")) as f:
                prints[seed] = json.load(f)["fingerprint"]
    return prints


def sweep(sanet, scenario, seeds, duration, folder, jobs):
    subprocess.run([sanet, "sweep", scenario, "--seeds", ",".join(map(str, seeds)), "--duration", str(duration),
                    "--jobs", str(jobs), "-q", "-o", folder], check=True)
    with sqlite3.connect(os.path.join(folder, "study.sqlite")) as db:
        return dict(db.execute("SELECT seed, fingerprint FROM runs WHERE status = 'completed'"))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--sanet", default=os.path.join(ROOT, "build", "sanet"))
    parser.add_argument("--scenario", default=os.path.join(ROOT, "scenarios", "help-request.yaml"))
    parser.add_argument("--seeds", type=int, default=4, help="runs per case")
    parser.add_argument("--duration", type=float, default=300, help="simulated seconds per run")
    parser.add_argument("--repeat", type=int, default=2, help="best of this many")
    args = parser.parse_args()
    if not os.path.exists(args.scenario):
        parser.error("no scenario " + args.scenario)
    seeds = list(range(1, args.seeds + 1))
    cases = {"plain runs": lambda d: plain(args.sanet, args.scenario, seeds, args.duration, d),
             "plain, two at once": lambda d: plain_pairs(args.sanet, args.scenario, seeds, args.duration, d),
             "sweep, --jobs 1": lambda d: sweep(args.sanet, args.scenario, seeds, args.duration, d, 1),
             "sweep, --jobs 2": lambda d: sweep(args.sanet, args.scenario, seeds, args.duration, d, 2)}
    best = {name: float("inf") for name in cases}
    prints = {}
    for _ in range(args.repeat):
        for name, case in cases.items():
            with tempfile.TemporaryDirectory() as folder:
                start = time.monotonic()
                prints[name] = case(os.path.join(folder, "out"))
                best[name] = min(best[name], time.monotonic() - start)
    print("%d runs of %s, %.0f s simulated each, best of %d, %d cores" % (
        len(seeds), os.path.basename(args.scenario), args.duration, args.repeat, os.cpu_count()))
    print("%-20s %8s %12s %10s" % ("case", "wall s", "runs/minute", "vs plain"))
    base = best["plain runs"]
    for name in cases:
        print("%-20s %8.2f %12.1f %9.2fx" % (name, best[name], 60 * len(seeds) / best[name], base / best[name]))
    ceiling = best["plain runs"] / best["plain, two at once"]
    two = best["sweep, --jobs 1"] / best["sweep, --jobs 2"]
    print("jobs 2 / jobs 1 throughput: %.2fx; two processes at once on this machine: %.2fx (the sweep gets %.0f%% "
          "of it)" % (two, ceiling, 100 * (two - 1) / max(ceiling - 1, 1e-9)))
    same = all(p == prints["plain runs"] for p in prints.values())
    print("fingerprints: " + ("the same in every case" if same else "DIFFERENT: %s" % prints))
    if not same:
        raise SystemExit(1)


if __name__ == "__main__":
    main()
