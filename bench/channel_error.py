#!/usr/bin/env python3
"""What the indexed channel's floor costs in accuracy, against ns-3's YansWifiChannel.

With its floor at the receivers' sensitivity the indexed channel gives Yans's results exactly
(tests/net/indexed_channel_test.cc checks the fingerprint). Above it, frames too weak to be
detected are not handed to a radio, so their share of the interference there is lost. One run
of each cannot show that: a single different reception sends the two runs down different
paths. So each scenario runs with several seeds under each channel, and the averages of what
the network delivered are compared:

  delivered    frames received whole per frame sent (all radios; summary.json, network.channel)
  messages     controller messages received per message sent (totals over the seeds: one run
               whose mission fails sends few and would weigh too much in a mean of ratios)
  delay        median delay of controller messages (s)
  discovery    median time of a route discovery (s)

and the difference of `delivered` (indexed against Yans, in % of Yans's) with its 95 %
confidence interval. The runs go two at a time (the cores of this machine); nothing is timed.

  bench/channel_error.py [--sanet build/sanet] [--seeds 1-10] [--floor -85] [--duration S] [scenarios...]
"""
import argparse
import concurrent.futures
import json
import math
import os
import re
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_SCENARIOS = ["help-request", "help-request-team", "sensor-network", "formation"]


def seeds_of(text):
    out = []
    for part in text.split(","):
        low, _, high = part.partition("-")
        out.extend(range(int(low), int(high or low) + 1))
    return out


def with_channel(scenario, channel, folder):
    """A copy of `scenario` whose network section starts with `channel`."""
    text = open(scenario).read()
    if not re.search(r"^network:", text, re.M):
        return None
    copy = os.path.join(folder, os.path.basename(scenario).replace(".yaml", "-" + channel.split(",")[0] + ".yaml"))
    text = re.sub(r"^  channel: .*\n", "", text, flags=re.M)  # the scenario's own, if any
    with open(copy, "w") as f:
        f.write(re.sub(r"^network:", "network:\n  channel: {model: %s}" % channel, text, count=1, flags=re.M))
    return copy


def run(sanet, scenario, seed, folder, duration=None):
    out = os.path.join(folder, "seed%d" % seed)
    command = [sanet, "run", scenario, "--seed", str(seed), "-o", out, "-q"]
    if duration:
        command += ["--duration", str(duration)]
    subprocess.run(command, check=True)
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    n = s["network"]
    c = n["channel"]
    p = n["packets"]
    return {
        "delivered": c["frames_received"] / max(c["frames_sent"], 1),
        "messages_received": p["messages_received"],
        "messages_sent": p["messages_sent"],
        "delay": (s.get("message_delay_s") or {}).get("median"),
        "discovery": n["route_discoveries"]["time_s"].get("median"),
        "per_frame": c.get("receivers_per_frame"),
    }


def mean_ci(values):
    values = [v for v in values if v is not None]
    if not values:
        return None, None
    m = statistics.fmean(values)
    half = 1.96 * statistics.stdev(values) / math.sqrt(len(values)) if len(values) > 1 else float("nan")
    return m, half


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--sanet", default=os.path.join(ROOT, "build", "sanet"))
    parser.add_argument("--seeds", default="1-10")
    parser.add_argument("--floor", default=None, help="dBm; default: the scenario's default floor")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--duration", type=float, help="s simulated per run (default: the scenario's)")
    parser.add_argument("scenarios", nargs="*", default=DEFAULT_SCENARIOS)
    args = parser.parse_args()
    seeds = seeds_of(args.seeds)
    indexed = "indexed" + (", floor: %s" % args.floor if args.floor else "")
    print("indexed channel (%s) against Yans, seeds %s; means over seeds, +- 95 %% CI" % (indexed, args.seeds))
    print("%-20s %-8s %18s %10s %10s %10s %8s" % ("scenario", "channel", "delivered/frame", "messages", "delay s",
                                                 "discov. s", "rx/frame"))
    with tempfile.TemporaryDirectory() as tmp, concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        for name in args.scenarios:
            path = name if os.path.exists(name) else os.path.join(ROOT, "scenarios", name + ".yaml")
            results = {}
            for channel in ("yans", indexed):
                copy = with_channel(path, channel, tmp)
                if copy is None:
                    print("%-20s has no network" % name)
                    break
                folder = copy[:-len(".yaml")] + "-runs"
                results[channel] = list(pool.map(lambda s: run(args.sanet, copy, s, folder, args.duration), seeds))
            if len(results) < 2:
                continue
            for channel, rows in results.items():
                d, dh = mean_ci([r["delivered"] for r in rows])
                messages = sum(r["messages_received"] for r in rows) / max(sum(r["messages_sent"] for r in rows), 1)
                cells = [messages] + [mean_ci([r[k] for r in rows])[0] for k in ("delay", "discovery", "per_frame")]
                print("%-20s %-8s %11.4f+-%.4f %10s %10s %10s %8s" % (
                    name, channel.split(",")[0], d, dh,
                    *[("%.4f" % v if v is not None else "-") for v in cells[:3]],
                    "%.1f" % cells[3] if cells[3] is not None else "all"))
            y = [r["delivered"] for r in results["yans"]]
            i = [r["delivered"] for r in results[indexed]]
            diff = statistics.fmean(i) - statistics.fmean(y)
            half = 1.96 * math.sqrt(statistics.variance(y) / len(y) + statistics.variance(i) / len(i))
            base = statistics.fmean(y)
            print("%-20s delivered frames: indexed - yans = %+.2f %% +- %.2f %% of Yans's" % (
                name, 100 * diff / base, 100 * half / base))
            sys.stdout.flush()


if __name__ == "__main__":
    main()
