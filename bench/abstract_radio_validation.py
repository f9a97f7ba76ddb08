#!/usr/bin/env python3
"""The abstract radio against the full 802.11 model it replaces: the validation table of docs/swarms.md.

1. Sparse traffic: `sanet link-curve` of both models on three radios (a threshold radio, a grey
   zone of shadowing and Nakagami fading, the swarms' radio): the largest difference in PRR over
   the distances, and the median delay of each.
2. The case studies, side by side over several seeds: the help request (AODV over a grid of motes,
   without and with a grey zone), the formation (pose messages to the followers) and the sensor
   network (a report over eight AODV hops, floods): the outcome, messages sent and received, message
   delay quartiles, route discoveries and their time quartiles.
3. Where the abstraction departs, measured on scenarios made for it: contention (ten radios in
   each other's range broadcasting at a rising offered load), hidden terminals (two senders that
   cannot hear each other sending to one receiver between them) and a broadcast storm (a flood
   relayed by every mote of a 7 x 7 grid).

  bench/abstract_radio_validation.py [--sanet build/sanet] [--seeds 5] [--markdown FILE] [--parts curves,cases,departures]

Every run uses the same seed for both models; the calibrations are measured once and cached
(SANET_CACHE, as a run does).
"""
import argparse
import csv
import json
import os
import statistics
import subprocess
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MODELS = ("full", "abstract")


def sanet(args, *command):
    subprocess.run([args.sanet, *command], check=True, capture_output=True, text=True)


def run(args, scenario, out, model, *sets):
    sanet(args, "run", scenario, "-q", "--force", "-o", out, "--set", "network.radio_model=" + model,
          *[x for s in sets for x in ("--set", s)])
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    with open(os.path.join(out, "messages.csv")) as f:
        summary["rows"] = list(csv.DictReader(f))
    return summary


def curve(args, scenario, out, model):
    sanet(args, "link-curve", scenario, "-q", "--force", "-o", out, "--links", "100",
          "--set", "network.radio_model=" + model)
    with open(os.path.join(out, "link_curve.csv")) as f:
        return list(csv.DictReader(f))


def unicast_pairs(tmp, distances, links):
    """Pairs of motes `d` apart, each pair 3 km from the others, the sender sending 32 B a second."""
    nodes = []
    for k, (d, link) in enumerate((d, link) for d in distances for link in range(links)):
        x, y = (k % 25) * 3000, (k // 25) * 3000
        nodes.append("  - {name: s%d_%d, model: mote, pose: [%d, %d, 0], controller: {name: pinger, params: {to: r%d_%d, "
                     "interval: 1, start: %.4f, size: 32}}}" % (d, link, x, y, d, link, 1 + 0.0007 * k))
        nodes.append("  - {name: r%d_%d, model: mote, pose: [%d, %d, 0]}" % (d, link, x + d, y))
    with open(os.path.join(ROOT, "scenarios", "help-request-grey-zone.yaml")) as f:
        radio = f.read().split("network:\n", 1)[1].split("\nnodes:", 1)[0].replace("routing: aodv", "routing: none")
    path = os.path.join(tmp, "pairs.yaml")
    with open(path, "w") as f:
        f.write("name: pairs\nduration: 61\nworld: {size: [76000, 76000]}\nnetwork:\n%s\n  packet_log: false\n"
                "nodes:\n%s\n" % (radio, "\n".join(nodes)))
    return path


def unicast_delivery(args, tmp, table):
    distances, links = range(50, 501, 50), 60
    path = unicast_pairs(tmp, distances, links)
    shares = []
    for model in MODELS:
        r = run(args, path, os.path.join(tmp, "pairs-" + model), model)
        got = {d: 0 for d in distances}
        for row in r["rows"]:
            if row["time_received"]:
                got[int(row["from"][1:].split("_")[0])] += 1
        shares.append([got[d] / (links * 60) for d in distances])
    worst = max(abs(f - a) for f, a in zip(*shares))
    table.append("| grey zone, unicast one hop (ARP, MAC retries), %d links per distance | %d | %.3f | - |"
                 % (links, len(distances), worst))


def sparse_traffic(args, tmp, table):
    table.append("| radio | distances | largest PRR difference | median delay, full / abstract (ms) |")
    table.append("|---|---|---|---|")
    for name in ("help-request", "help-request-grey-zone", "swarm-1k"):
        path = os.path.join(ROOT, "scenarios", name + ".yaml")
        full, abstract = (curve(args, path, os.path.join(tmp, name + "-" + m), m) for m in MODELS)
        worst = max(abs(float(f["prr"]) - float(a["prr"])) for f, a in zip(full, abstract))
        delays = [statistics.median(float(r["delay_median_ms"]) for r in c if r["delay_median_ms"])
                  for c in (full, abstract)]
        table.append("| %s | %d | %.3f | %.3f / %.3f |" % (name, len(full), worst, *delays))
    unicast_delivery(args, tmp, table)


def quartiles(q):
    return "%.1f / %.1f / %.1f" % (q["q1"] * 1e3, q["median"] * 1e3, q["q3"] * 1e3) if q else "-"


def pooled(runs, pick):
    values = [v for r in runs for v in pick(r)]
    if not values:
        return None
    values.sort()
    at = lambda p: values[min(len(values) - 1, int(p * len(values)))]
    return {"q1": at(0.25), "median": at(0.5), "q3": at(0.75)}


def delays(r):
    return [float(row["delay"]) for row in r["rows"] if row["delay"]]


def discoveries(r):
    d = r["network"].get("route_discoveries")
    return d and d["established"], d and d["started"]


def arrival(r):
    return "arrived at %.0f s" % r["ended_at_s"] if "arrived" in r.get("ended_by", "") else "not arrived"


OUTCOMES = {
    "help-request": lambda r: arrival(r),
    "help-request-grey-zone": lambda r: arrival(r),
    "formation": lambda r: "poses missed %.3f" % r["metrics"]["f3"]["pose_missed"]["mean"],
    "sensor-network": lambda r: "report delivered %d of 12" % sum(
        1 for row in r["rows"] if row["from"] == "reporter" and row["time_received"]),
}


def case_studies(args, tmp, table):
    table.append("| case study | model | outcome (per seed) | messages sent / received | message delay q1 / median / "
                 "q3 (ms) | routes found / asked | discovery q1 / median / q3 (ms) |")
    table.append("|---|---|---|---|---|---|---|")
    for name, outcome in OUTCOMES.items():
        path = os.path.join(ROOT, "scenarios", name + ".yaml")
        for model in MODELS:
            runs = [run(args, path, os.path.join(tmp, "%s-%s-%d" % (name, model, s)), model, "seed=%d" % s)
                    for s in range(1, args.seeds + 1)]
            packets = [r["network"]["packets"] for r in runs]
            found = [discoveries(r) for r in runs if discoveries(r)[1]]
            routes = "%d / %d" % (sum(f for f, _ in found), sum(a for _, a in found)) if found else "-"
            times = [r["network"]["route_discoveries"]["time_s"] for r in runs
                     if r["network"].get("route_discoveries", {}).get("time_s", {}).get("count")]
            discovery = {k: statistics.median(t[k] for t in times) for k in ("q1", "median", "q3")} if times else None
            table.append("| %s | %s | %s | %d / %d | %s | %s | %s |" % (
                name, model, "; ".join(outcome(r) for r in runs), sum(p["messages_sent"] for p in packets),
                sum(p["messages_received"] for p in packets), quartiles(pooled(runs, delays)), routes,
                quartiles(discovery)))


def mote_grid(name, rows, cols, spacing, controller, network="", duration=30, source=False):
    """Motes on a grid, each running `controller`; or with `source`, only a mote amid them."""
    if source:
        where = (cols - 1) * spacing / 2 + spacing / 2, (rows - 1) * spacing / 2 + spacing / 2
        return mote_grid(name, rows, cols, spacing, "null", network, duration).replace("    controller: null\n", "") + \
            "  - {name: source, model: mote, pose: [%g, %g, 0], controller: %s}\n" % (*where, controller)
    return """name: %s
duration: %d
network:
  tx_power: 30
  data_rate: 1
  routing: none
%snodes:
  - grid: {name: m, rows: %d, cols: %d, origin: [0, 0], spacing: %g}
    model: mote
    controller: %s
""" % (name, duration, network, rows, cols, spacing, controller)


def both_models(args, tmp, tag, text, measure):
    """`measure` of a run of the scenario `text` on each model, full first."""
    scenario = os.path.join(tmp, tag + ".yaml")
    with open(scenario, "w") as f:
        f.write(text)
    return [measure(run(args, scenario, os.path.join(tmp, tag + "-" + model), model)) for model in MODELS]


def reached(receivers):
    """Messages received per message sent and per receiver each could reach."""
    return lambda r: r["network"]["packets"]["messages_received"] / max(
        1, r["network"]["packets"]["messages_sent"] * receivers)


def contention(args, tmp, table):
    table.append("| departure | setting | full | abstract |")
    table.append("|---|---|---|---|")
    # 10 radios within 10 m, each broadcasting 500 B at a random moment of each interval (the
    # broadcast jitter): 1 Mbps carries about 200 such frames a second.
    for interval in (0.5, 0.1, 0.05, 0.025):
        load = 10 * 500 * 8 / interval / 1e6
        text = mote_grid("contention", 2, 5, 2.5, "{name: pinger, params: {to: broadcast, interval: %g, size: 500}}"
                         % interval, "  broadcast_jitter: %g\n" % interval)
        got = both_models(args, tmp, "contention", text, reached(9))
        table.append("| contention: share of 9 neighbours reached per broadcast | offered load %.0f %% of 1 Mbps "
                     "| %.3f | %.3f |" % (100 * load, *got))


def hidden_terminals(args, tmp, table):
    # a -- r -- b, 140 m apart at 30 dBm (heard to 151 m): a and b cannot hear each other. b sends
    # 3.7 % slower than a, so that their frames meet at r at every phase in turn, and starts later
    # (at once, their ARP requests would meet at r every time, and both would give up).
    for interval in (0.2, 0.05, 0.02):
        text = """name: hidden
duration: 30
network: {tx_power: 30, data_rate: 1, routing: none}
nodes:
  - {name: r, model: mote, pose: [140, 0, 0]}
  - {name: a, model: mote, pose: [0, 0, 0], controller: {name: pinger, params: {to: r, interval: %g, size: 500}}}
  - {name: b, model: mote, pose: [280, 0, 0], controller: {name: pinger, params: {to: r, interval: %g, size: 500,
                                                                                  start: 1.37}}}
""" % (interval, interval * 1.037)
        got = both_models(args, tmp, "hidden", text, lambda r: "%.3f, %.1f ms" % (
            reached(1)(r), statistics.median(delays(r)) * 1e3 if delays(r) else float("nan")))
        table.append("| hidden terminals: delivered, median delay | each sender %g frames/s | %s | %s |"
                     % (1 / interval, *got))


def broadcast_storm(args, tmp, table):
    # One mote floods every 2 s; each of the grid's 49 motes relays it once. Motes 40 m apart
    # hear up to about 44 others (151 m).
    for jitter in (0, 0.01):
        text = mote_grid("storm", 7, 7, 40, "{name: pinger, params: {to: flood, interval: 2}}",
                         "  broadcast_jitter: %g\n" % jitter, duration=60, source=True)
        got = both_models(args, tmp, "storm", text, reached(49))
        table.append("| broadcast storm: share of 49 motes a flood reaches | one mote floods every 2 s through 49, "
                     "relay jitter %g s | %.3f | %.3f |" % (jitter, *got))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--sanet", default=os.path.join(ROOT, "build", "sanet"), help="the sanet to measure")
    parser.add_argument("--seeds", type=int, default=5, help="seeds of each case study on each model (1 to N)")
    parser.add_argument("--markdown", help="also write the tables to this file")
    parser.add_argument("--parts", default="curves,cases,departures",
                        help="comma-separated parts to run: curves (about 40 s), cases (about 5 min with 5 seeds), "
                             "departures (about 15 s)")
    args = parser.parse_args()
    parts = {"curves": sparse_traffic, "cases": case_studies, "departures": contention}
    tables = []
    with tempfile.TemporaryDirectory() as tmp:
        for part in (parts[p] for p in args.parts.split(",")):
            table = []
            part(args, tmp, table)
            if part is contention:
                hidden_terminals(args, tmp, table)
                broadcast_storm(args, tmp, table)
            tables.append("\n".join(table))
            print(tables[-1] + "\n", flush=True)
    if args.markdown:
        with open(args.markdown, "w") as f:
            f.write("\n\n".join(tables) + "\n")


if __name__ == "__main__":
    main()
