#!/usr/bin/env python3
"""A grey-zone radio (shadowing and fading) in a served run: a WSS client, written from
docs/protocol.md, asks for signal strengths throughout the run. The strengths are the mean power
with the links' shadowing (off the plain path loss by several dB, the same both ways, steady while
the motes stand still: no fading), and asking changes nothing: the served run's fingerprint equals
that of `sanet run` on the same scenario, where nobody asks."""
import json
import math
import os
import subprocess
import sys
import tempfile
import time
import unittest

from protocol_client import Wss, serve

SANET = sys.argv.pop(1)
TX_POWER = 5
SCENARIO = f"""name: grey-wss
duration: 4
seed: 3
network:
  tx_power: {TX_POWER}
  broadcast_jitter: 0.2
  propagation:
    shadowing: {{sigma_db: 6, correlation_m: 5}}
    fading: {{model: rayleigh}}
nodes:
  - grid: {{name: m, rows: 2, cols: 5, spacing: 8, origin: [0, 0]}}
    model: mote
    controller: {{name: pinger, params: {{interval: 0.2}}}}
"""
MOTES = [f"m{i}" for i in range(10)]


def position(name):
    i = int(name[1:])
    return 8 * (i % 5), 8 * (i // 5)


def path_loss_dbm(a, b):
    (ax, ay), (bx, by) = position(a), position(b)
    return TX_POWER - 46.6777 - 30 * math.log10(math.hypot(ax - bx, ay - by))


def strength(answer):
    return float(answer.split("{Strength ")[1].split("}")[0])


class GreyZoneUnderWss(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        served = os.path.join(cls.tmp.name, "served")
        os.makedirs(served)
        port_file = os.path.join(served, "wss-port")
        server, _, out = serve(SANET, SCENARIO, served, "--wss-port", "0", "--wss-port-file", port_file,
                               "--no-foxglove")
        while not os.path.exists(port_file):
            if server.poll() is not None:
                raise RuntimeError("sanet serve ended before it listened")
            time.sleep(0.01)
        with open(port_file) as f:
            wss_port = int(f.read())
        clients = {name: Wss(wss_port) for name in ("m0", "m7")}
        for name, client in clients.items():
            assert "OK" in client.ask(f"INIT {{Robot {name}}} {{Port 5000}}"), name
        cls.samples = {}  # (from, to) -> strengths asked over the run
        while server.poll() is None:
            for name, client in clients.items():
                for other in MOTES:
                    if other == name:
                        continue
                    try:
                        answer = client.ask(f"GETSS {{Robot {other}}}")
                    except OSError:
                        break
                    if "Strength" in answer:
                        cls.samples.setdefault((name, other), []).append(strength(answer))
        for client in clients.values():
            client.sock.close()
        with open(os.path.join(out, "summary.json")) as f:
            cls.served = json.load(f)
        ran = os.path.join(cls.tmp.name, "ran")
        subprocess.run([SANET, "run", os.path.join(served, "scenario.yaml"), "-o", ran, "-q"], check=True)
        with open(os.path.join(ran, "summary.json")) as f:
            cls.ran = json.load(f)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_asking_for_strengths_does_not_change_the_run(self):
        self.assertGreater(sum(len(s) for s in self.samples.values()), 100, "the client asked throughout the run")
        self.assertGreater(self.ran["network"]["channel"]["frames_received"], 50)
        self.assertEqual(self.served["fingerprint"], self.ran["fingerprint"])

    def test_strengths_carry_the_shadowing_but_no_fading(self):
        offsets = []
        for (a, b), seen in self.samples.items():
            self.assertEqual(min(seen), max(seen), f"{a} -> {b}: motes stand still, the mean power too")
            offsets.append(seen[0] - path_loss_dbm(a, b))
        spread = math.sqrt(sum(o * o for o in offsets) / len(offsets))
        self.assertGreater(spread, 2.5, "the links are shadowed by a few dB (sigma 6)")
        self.assertLess(spread, 10)
        self.assertAlmostEqual(self.samples[("m0", "m7")][0], self.samples[("m7", "m0")][0], places=9,
                               msg="shadowing is the same both ways")


if __name__ == "__main__":
    unittest.main()
