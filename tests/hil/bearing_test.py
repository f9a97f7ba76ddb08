#!/usr/bin/env python3
"""The bearing sensor in the loop: a client that said SANET (as sanet's agents do) gets a bearing
line every sensor period naming each node within the sensor's range, its distance and direction
within the sensor's noise; a stock USARSim client, which would not know the line, never sees it.
A client written from docs/protocol.md, standard library only."""
import math
import sys
import tempfile
import unittest

from protocol_client import Client, field, serve

SANET = sys.argv.pop(1)
SCENARIO = """duration: 6
nodes:
  - {name: r1, model: omni3, pose: [0, 0, 0.5], sensors: {bearing: {range: 10, noise_distance: 0.05, noise_angle: 0.01}}}
  - {name: r2, model: omni3, pose: [3, 4, 0]}
  - {name: far, model: mote, pose: [20, 0, 0]}
"""


def bearings(line):
    """{Name R Distance d Bearing b} ... -> {R: (d, b)}, b in USARSim's frame (clockwise)."""
    out = {}
    for part in line.split("{Name ")[1:]:
        words = part.split("}")[0].split()
        out[words[0]] = (float(words[2]), float(words[4]))
    return out


class BearingInTheLoop(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.server, cls.port, cls.out = serve(SANET, SCENARIO, cls.tmp.name)

    @classmethod
    def tearDownClass(cls):
        cls.server.wait(timeout=60)
        cls.tmp.cleanup()

    def test_a_sanet_client_gets_the_nodes_in_range_and_a_stock_client_nothing(self):
        agent = Client(self.port)
        agent.send("SANET {Protocol 3} {Version test}")  # sanet's protocol number (docs/protocol.md)
        agent.send("INIT {Name r1}")
        seen = [bearings(agent.sensor("Bearing")) for _ in range(5)]
        for s in seen:
            self.assertEqual(set(s), {"r2"}, "r2 (5 m) is in range, the mote at 20 m is not")
            distance, angle = s["r2"]
            self.assertAlmostEqual(distance, 5.0, delta=0.25)  # 5 sigma of the distance noise
            # r2 lies at atan2(4, 3) = 0.927 rad in the world, 0.427 rad to r1's left: -0.427 in USARSim's frame
            self.assertAlmostEqual(angle, -(math.atan2(4, 3) - 0.5), delta=0.05)
        self.assertGreater(len({s["r2"][0] for s in seen}), 1, "each period reads the noisy sensor again")
        stock = Client(self.port)
        stock.send("INIT {Name r2}")
        kinds = {field(stock.next("SEN"), "Type") for _ in range(6)}
        self.assertIn("GroundTruth", kinds)
        self.assertNotIn("Bearing", kinds)
        agent.close()
        stock.close()


if __name__ == "__main__":
    unittest.main(verbosity=2)
