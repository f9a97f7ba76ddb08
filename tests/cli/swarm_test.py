#!/usr/bin/env python3
"""The shipped 1,000-robot swarm, shortened to 4 s, as a user runs it:
- it completes, with all 1,000 robots on the 2D engine;
- each robot hears about 8 to 12 one-hop neighbours (its `neighbours` metric, once it has heard
  a beacon from all of them: after the first second), over the simulated 802.11 radio;
- the robots move at 0.2 to 0.5 m/s and stay inside the walled arena;
- the indexed channel handed each beacon to a few dozen radios, not to all 999 others;
- its map names no robot but counts them (a thousand names would cover the paths);
- the same seed gives the same fingerprint."""
import csv
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile
import unittest

SANET = sys.argv.pop(1)
SOURCE = sys.argv.pop(1)
SCENARIO = os.path.join(SOURCE, "scenarios", "swarm-1k.yaml")
ARENA = 180.0  # m, the inner side of the walls


def run(out):
    subprocess.run([SANET, "run", SCENARIO, "--duration", "4", "-q", "-o", out], check=True)
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


class Swarm(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.out = os.path.join(cls.tmp.name, "a")
        cls.summary = run(cls.out)

    def rows(self, name):
        with open(os.path.join(self.out, name)) as f:
            return list(csv.DictReader(f))

    def test_completes_with_a_thousand_robots(self):
        self.assertEqual(self.summary["status"], "completed")
        self.assertEqual(len(self.summary["nodes"]), 1000)
        self.assertAlmostEqual(self.summary["simulated_s"], 4.0, places=3)

    def test_each_robot_hears_eight_to_twelve_neighbours(self):
        heard = [float(r["value"]) for r in self.rows("metrics.csv")
                 if r["name"] == "neighbours" and float(r["time"]) >= 1.5]
        self.assertGreater(len(heard), 1000)
        self.assertTrue(8 <= statistics.fmean(heard) <= 12, statistics.fmean(heard))

    def test_robots_move_at_a_walking_pace_inside_the_arena(self):
        track = {}
        for r in self.rows("trajectories.csv"):
            track.setdefault(r["node"], []).append((float(r["time"]), float(r["x"]), float(r["y"])))
        speeds = []
        for points in track.values():
            (t0, x0, y0), (t1, x1, y1) = points[1], points[-1]  # from 1 s: past the start
            speeds.append(math.hypot(x1 - x0, y1 - y0) / (t1 - t0))
            for _, x, y in points:
                self.assertTrue(0 < x < ARENA and 0 < y < ARENA, (x, y))
        self.assertTrue(0.2 <= statistics.median(speeds) <= 0.5, statistics.median(speeds))

    def test_the_channel_hands_a_beacon_to_a_few_dozen_radios(self):
        channel = self.summary["network"]["channel"]
        self.assertEqual(channel["model"], "indexed")
        self.assertGreater(channel["frames_sent"], 2000)
        self.assertLess(channel["receivers_per_frame"], 80)
        self.assertGreater(channel["frames_received"] / channel["frames_sent"], 6)

    def test_the_map_counts_the_robots_instead_of_naming_them(self):
        with open(os.path.join(self.out, "map.svg")) as f:
            svg = f.read()
        self.assertIn(">1000 robots<", svg)
        self.assertNotIn("(start)", svg)
        self.assertNotIn(">r999<", svg)

    def test_same_seed_same_fingerprint(self):
        again = run(os.path.join(self.tmp.name, "b"))
        self.assertEqual(again["fingerprint"], self.summary["fingerprint"])


if __name__ == "__main__":
    unittest.main()
