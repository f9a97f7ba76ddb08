#!/usr/bin/env python3
"""What a field of 802.15.4 motes costs against the same field on 802.11b (docs/network.md#cost-of-80215.4),
measured in one run of this script: the median wall time of each, the ratio (802.15.4 / 802.11b),
the events ns-3 processed and the frames sent and received whole.

  400 motes a 20 x 20 grid 20 m apart, no routing (one hop), 40 of them each sending 64 B every
            2 s to a neighbour 20 m away and every tenth of the others broadcasting 16 B every
            5 s; 802.11b at 5 dBm (21 m) against 802.15.4 at 0 dBm (41 m, the CC2420's)

802.11 runs on sanet's indexed channel, which hands a frame only to the radios in range;
802.15.4 runs on ns-3's spectrum channel, which asks the loss of every pair for every frame but
schedules a reception only where the frame arrives at the sensitivity or stronger (its maximum-
loss cut-off). Every 802.15.4 unicast is acknowledged: it has about twice the frames. The third
row is the same 802.11b field on the abstract radio (docs/swarms.md#the-abstract-radio), whose
frames are the channel's (no ACKs, no retries on the air); its calibration is measured before
the first run if not cached.

    bench/lr_wpan_bench.py [--sanet build/sanet] [--seconds 60] [--repeat 3]"""
import argparse
import os
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from grey_zone_bench import measure  # noqa: E402  (median wall time of `repeat` runs, the last summary)
RADIOS = {"802.11b": "{radio: 802.11b, tx_power: 5, routing: none, packet_log: false}",
          "802.15.4": "{radio: 802.15.4, routing: none, packet_log: false}",
          "abstract": "{radio: 802.11b, tx_power: 5, routing: none, packet_log: false, radio_model: abstract}"}


def field(radio):
    lines = ["name: lr-wpan-400", "seed: 1", "duration: 60", "world:", "  size: [420, 420]",
             f"network: {RADIOS[radio]}", "outputs: {trace: false, figures: false}", "nodes:",
             "  - grid: {name: m, rows: 20, cols: 20, origin: [0, 0], spacing: 20}", "    model: mote"]
    for i in range(40):
        at = (i * 10) % 400
        row, col = at // 20, at % 20
        to = at + 1 if col < 19 else at - 1
        lines += [f"  - name: s{i}", "    model: mote", f"    pose: [{20 * col + 1}, {20 * row + 1}, 0]",
                  f"    controller: {{name: pinger, params: {{to: m{to}, interval: 2, start: 1, size: 64}}}}"]
    for i in range(40):
        at = (i * 10 + 5) % 400
        lines += [f"  - name: b{i}", "    model: mote", f"    pose: [{20 * (at % 20) + 1}, {20 * (at // 20) - 1}, 0]",
                  "    controller: {name: pinger, params: {to: broadcast, interval: 5, start: 1, size: 16}}"]
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sanet", default=os.path.join(ROOT, "build", "sanet"))
    parser.add_argument("--seconds", type=float, default=60, help="simulated seconds of each run")
    parser.add_argument("--repeat", type=int, default=3, help="runs of each radio (the median is kept)")
    a = parser.parse_args()
    print(f"{'radio':>9} {'wall s':>8} {'ratio':>6} {'x real':>7} {'events':>10} {'frames':>8} {'received':>9} "
          f"{'messages in':>11}")
    base = None
    with tempfile.TemporaryDirectory() as tmp:
        for radio in RADIOS:
            scenario = os.path.join(tmp, f"{radio}.yaml")
            with open(scenario, "w") as f:
                f.write(field(radio))
            wall, s = measure(a.sanet, scenario, os.path.join(tmp, radio), a.seconds, [], a.repeat)
            base = base or wall
            channel, packets = s["network"]["channel"], s["network"]["packets"]
            print(f"{radio:>9} {wall:>8.2f} {wall / base:>6.3f} {a.seconds / wall:>7.1f} {s['events']:>10} "
                  f"{channel['frames_sent']:>8} {channel['frames_received']:>9} {packets['messages_received']:>11}",
                  flush=True)


if __name__ == "__main__":
    main()
