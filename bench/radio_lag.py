#!/usr/bin/env python3
"""Real programs over the simulated radio (loop.network: simulated), measured. Needs root.

1. 4 and 16 agents, each sending a 10 Hz message to the next one (a ring) over ns-3's 802.11g
   network through its tap: the server's real-time lag (p50/p99/max, missed 5 ms deadlines) and
   the delay the simulated network adds between taps (p50/p99), with ratios to the 4-agent run.
2. Two agents, one sending small UDP datagrams to the other at rising rates (a Python sender in its
   namespace): datagrams delivered, the lag p99, and the highest rate carried with p99 lag under
   5 ms, with ratios to the lowest rate. One 802.11g link saturates before the simulator does, so:
3. 1, 2, 4 and 8 such pairs, 100 m apart (out of each other's range), each sending 2,000
   datagrams/s: where the simulator stops keeping up (lag p99 over 5 ms), in frames per second.

    sudo bench/radio_lag.py build/sanet [seconds per case, default 10] [sections, default 123]"""
import json
import os
import subprocess
import sys
import tempfile

sanet = sys.argv[1]
seconds = float(sys.argv[2]) if len(sys.argv) > 2 else 10
sections = sys.argv[3] if len(sys.argv) > 3 else "123"  # which of the three to run
NETWORK = "network: {radio: 802.11g, data_rate: 54, tx_power: 16, routing: none}\nloop: {network: simulated}\n"
SENDER = """import socket, sys, time
rate, seconds = float(sys.argv[1]), float(sys.argv[2])
destination = sys.argv[4] if len(sys.argv) > 4 else "10.0.0.2"
s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
start = time.monotonic()
n = 0
while time.monotonic() - start < seconds:
    s.sendto(b"x" * 64, (destination, 9999))
    n += 1
    delay = start + n / rate - time.monotonic()
    if delay > 0:
        time.sleep(delay)
"""


def launch(scenario, *extra):
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "bench.yaml")
        with open(path, "w") as f:
            f.write(scenario)
        out = subprocess.run([sanet, "launch", path, "-o", os.path.join(tmp, "out"), *extra], capture_output=True,
                             text=True, timeout=seconds + 120)
        if out.returncode != 0:
            sys.exit(out.stdout + out.stderr)
        with open(os.path.join(tmp, "out", "summary.json")) as f:
            return json.load(f)


def ring(count):
    lines = [f"duration: {seconds}", NETWORK + "nodes:"]
    for i in range(count):
        lines.append(f"  - {{name: r{i}, model: omni3, pose: [{2 * (i % 8)}, {2 * (i // 8)}, 0], controller: "
                     f"{{name: pinger, rate: 10, params: {{to: r{(i + 1) % count}, interval: 0.1, start: 0.5, size: 64}}}}}}")
    return "\n".join(lines) + "\n"


FLOOR = 1e-5  # s: lags below 10 us count as 10 us in the ratios (the clock's own jitter)


def ms(seconds_value):
    return 1000 * seconds_value


def rings():
    print(f"{'agents':>6} {'lag p50':>8} {'lag p99':>8} {'lag max':>8} {'missed':>7} {'net p50':>8} {'net p99':>8} "
          f"{'msgs':>6} {'p99/step':>9} {'p99 vs 4':>9}   (ms)")
    base = None
    for count in (4, 16):
        summary = launch(ring(count))
        lag, taps = summary["real_time_lag"], summary["network"]["taps"]
        p50 = sorted(t["delay_s"].get("median", 0) for t in taps.values())[len(taps) // 2]
        p99 = max(t["delay_p99_s"] for t in taps.values())
        received = sum(t["packets_received"] for t in taps.values())
        base = base or max(lag["p99_s"], FLOOR)
        print(f"{count:>6} {ms(lag['p50_s']):>8.2f} {ms(lag['p99_s']):>8.2f} {ms(lag['max_s']):>8.2f} "
              f"{lag['missed_deadlines']:>7} {ms(p50):>8.2f} {ms(p99):>8.2f} {received:>6} "
              f"{lag['p99_s'] / lag['deadline_s']:>9.3f} {max(lag['p99_s'], FLOOR) / base:>9.2f}", flush=True)



def rates():
    print("\nrate (datagrams/s offered by one agent to another, 64 bytes)")
    print(f"{'offered':>8} {'delivered':>10} {'lag p99':>8} {'missed':>7} {'net p99':>8} {'p99 vs low':>11}   (ms)")
    pair = (f"duration: {seconds + 3}\n" + NETWORK + "nodes:\n"
            "  - {name: a, model: omni3, pose: [0, 0, 0], controller: {name: constant_velocity, params: {vx: 0}}}\n"
            "  - {name: b, model: omni3, pose: [3, 0, 0], controller: {name: constant_velocity, params: {vx: 0}}}\n")
    base, best = None, 0
    for rate in (250, 500, 1000, 2000, 4000, 8000):
        summary = launch(pair, "--exec", "a", "--", sys.executable, "-c", SENDER, str(rate), str(seconds))
        lag, taps = summary["real_time_lag"], summary["network"]["taps"]
        delivered = taps["b"]["packets_received"] / seconds
        base = base or max(lag["p99_s"], FLOOR)
        if lag["p99_s"] < 0.005:
            best = max(best, delivered)
        print(f"{rate:>8} {delivered:>10.0f} {ms(lag['p99_s']):>8.2f} {lag['missed_deadlines']:>7} "
              f"{ms(taps['b']['delay_p99_s']):>8.2f} {max(lag['p99_s'], FLOOR) / base:>11.2f}", flush=True)
    print(f"highest rate carried with lag p99 under 5 ms: {best:.0f} datagrams/s")



def spread_pairs():
    print("\npairs 100 m apart, each offering 2000 datagrams/s (tx_power 0 dBm: 15 m range)")
    print(f"{'pairs':>6} {'delivered':>10} {'frames/s':>9} {'lag p99':>8} {'missed':>7} {'p99 vs 1':>9}   (ms)")
    base = None
    for pairs in (1, 2, 4, 8):
        nodes = []
        for p in range(pairs):
            nodes.append(f"  - {{name: a{p}, model: omni3, pose: [{100 * p}, 0, 0], "
                         "controller: {name: constant_velocity, params: {vx: 0}}}")
            nodes.append(f"  - {{name: b{p}, model: omni3, pose: [{100 * p + 3}, 0, 0], "
                         "controller: {name: constant_velocity, params: {vx: 0}}}")
        spread = (f"duration: {seconds + 3}\nnetwork: {{radio: 802.11g, data_rate: 54, tx_power: 0, routing: none}}\n"
                  "loop: {network: simulated}\nnodes:\n" + "\n".join(nodes) + "\n")
        # Every pair's sender runs in its a-robot's namespace; one --exec starts them all from a0's
        # namespace by entering the others' (ip netns exec works from inside a namespace too).
        script = " ".join(f"ip netns exec $(ip netns identify $$ | sed 's/-[0-9]*$//')-{2 * p} "
                           f"{sys.executable} -c '{SENDER}' 2000 {seconds} --dst 10.0.0.{2 * p + 2} &"
                           for p in range(pairs)) + " wait"
        summary = launch(spread, "--exec", "a0", "--", "sh", "-c", script)
        lag, taps = summary["real_time_lag"], summary["network"]["taps"]
        delivered = sum(taps[f"b{p}"]["packets_received"] for p in range(pairs)) / seconds
        base = base or max(lag["p99_s"], FLOOR)
        print(f"{pairs:>6} {delivered:>10.0f} {2 * delivered:>9.0f} {ms(lag['p99_s']):>8.2f} "
              f"{lag['missed_deadlines']:>7} {max(lag['p99_s'], FLOOR) / base:>9.2f}", flush=True)
    print("frames/s counts each datagram and its 802.11 acknowledgement")


print(f"sanet simulated radio: 802.11g 54 Mbit/s, physics step 5 ms, {seconds:.0f} s per case")
for number, section in enumerate((rings, rates, spread_pairs), start=1):
    if str(number) in sections:
        section()
