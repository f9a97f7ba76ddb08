#!/usr/bin/env python3
"""Two builds of sanet on the same scenarios, in one run: is the change no slower?

For each scenario it runs the baseline and the candidate `sanet run` in turn, `--repeat` times
each (interleaved, so that a busy moment of the machine falls on both), and prints the median wall
time of each, their ratio (candidate / baseline: under 1 is faster), and whether the two give the
same fingerprint (a change that must not alter results says so here too).

The baseline is a `sanet` binary (`--baseline PATH`), or a commit (`--rev REV`): then it is built
here, in a git worktree of this checkout under the system's temporary folder, with the same
CMake options as ./setup (ccache makes it quick when the objects are cached), and removed after.

  bench/binary_ratio.py --rev HEAD~1 scenarios/swarm-1k.yaml:20 scenarios/help-request.yaml
  bench/binary_ratio.py --baseline /tmp/base/build/sanet --candidate build/sanet --repeat 5 ...

A scenario is FILE or FILE:SECONDS (its duration cut to SECONDS of simulated time).
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def build_baseline(rev, folder):
    """`sanet` built from commit `rev` in a worktree at `folder`; its path."""
    subprocess.run(["git", "-C", ROOT, "worktree", "add", "--detach", folder, rev], check=True,
                   capture_output=True, text=True)
    build = os.path.join(folder, "build")
    subprocess.run(["cmake", "-S", folder, "-B", build, "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release"], check=True,
                   capture_output=True, text=True)
    done = subprocess.run(["cmake", "--build", build, "--target", "sanet"], capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"binary_ratio: building {rev} failed:\n{done.stdout[-2000:]}{done.stderr[-2000:]}")
    return os.path.join(build, "sanet")


def run_once(sanet, scenario, seconds, folder):
    """Wall seconds of one `sanet run`, and the run's fingerprint."""
    command = [sanet, "run", scenario, "-q", "--force", "-o", folder]
    if seconds is not None:
        command += ["--duration", str(seconds)]
    start = time.monotonic()
    done = subprocess.run(command, capture_output=True, text=True)
    wall = time.monotonic() - start
    if done.returncode != 0:
        sys.exit(f"binary_ratio: {' '.join(command)} failed ({done.returncode}):\n{done.stderr[-2000:]}")
    with open(os.path.join(folder, "summary.json")) as f:
        return wall, json.load(f)["fingerprint"]


def compare(baseline, candidate, scenario, seconds, repeat, tmp):
    walls = {"baseline": [], "candidate": []}
    prints = {}
    for i in range(repeat):
        for tag, sanet in (("baseline", baseline), ("candidate", candidate)):
            wall, fingerprint = run_once(sanet, scenario, seconds, os.path.join(tmp, f"{tag}-{i}"))
            walls[tag].append(wall)
            prints[tag] = fingerprint
    base, cand = statistics.median(walls["baseline"]), statistics.median(walls["candidate"])
    same = "same fingerprint" if prints["baseline"] == prints["candidate"] else (
        f"fingerprints differ: {prints['baseline']} / {prints['candidate']}")
    name = os.path.basename(scenario) + (f" ({seconds} s)" if seconds is not None else "")
    print(f"{name:36s} baseline {base:8.2f} s  candidate {cand:8.2f} s  ratio {cand / base:5.2f}  {same}", flush=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("scenarios", nargs="+", help="FILE or FILE:SECONDS")
    which = parser.add_mutually_exclusive_group(required=True)
    which.add_argument("--baseline", help="the baseline sanet binary")
    which.add_argument("--rev", help="build the baseline from this commit")
    parser.add_argument("--candidate", default=os.path.join(ROOT, "build", "sanet"), help="default: build/sanet")
    parser.add_argument("--repeat", type=int, default=3, help="runs of each binary per scenario (default 3)")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        worktree = os.path.join(tmp, "baseline")
        baseline = args.baseline or build_baseline(args.rev, worktree)
        try:
            print(f"baseline {args.baseline or args.rev}, candidate {args.candidate}, "
                  f"median of {args.repeat} interleaved runs each", flush=True)
            for item in args.scenarios:
                path, _, seconds = item.partition(":")
                compare(baseline, args.candidate, path, float(seconds) if seconds else None, args.repeat, tmp)
        finally:
            if args.rev:
                subprocess.run(["git", "-C", ROOT, "worktree", "remove", "--force", worktree], capture_output=True)


if __name__ == "__main__":
    main()
