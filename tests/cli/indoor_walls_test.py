#!/usr/bin/env python3
"""The shipped indoor help request (scenarios/help-request-indoor.yaml), run as shipped and with
`world.obstacle_material=none`: with its concrete walls, no link between motes crosses a wall
farther than a frame carries through one (8.1 m at its 3 dBm), the robot is led along the
corridor through doorways (every mote it steers for is in front of a door or in its room) and
arrives; without wall loss the motes hear each other through walls (more links, some through
walls), and the robot still arrives. tools/wall_links_figure.py draws both runs."""
import csv
import math
import os
import re
import sqlite3
import subprocess
import sys
import tempfile
import unittest

SANET = sys.argv.pop(1)
SOURCE = sys.argv.pop(1)
SCENARIO = os.path.join(SOURCE, "scenarios", "help-request-indoor.yaml")
THROUGH_ONE_WALL = 10 ** ((3 - 46.6777 - 11.05 + 82) / 30)  # m: 3 dBm, log-distance, 11.05 dB of concrete


def crosses(a, b, wall):
    """Whether segment a-b crosses the (thin) wall segment, seen from above."""
    (p, q) = wall

    def side(u, v, w):
        return (v[0] - u[0]) * (w[1] - u[1]) - (v[1] - u[1]) * (w[0] - u[0])

    return side(a, b, p) * side(a, b, q) < 0 and side(p, q, a) * side(p, q, b) < 0


def links(folder, min_frames=5):
    db = sqlite3.connect(os.path.join(folder, "trace.sqlite"))
    where = {i: (name, (x, y)) for i, name, x, y in db.execute("SELECT id, name, x, y FROM nodes")}
    pairs = db.execute("SELECT MIN(node, peer), MAX(node, peer), COUNT(*) FROM frames WHERE direction = 'rx' "
                       "AND peer IS NOT NULL GROUP BY 1, 2").fetchall()
    return [(where[a], where[b]) for a, b, n in pairs if n >= min_frames and "robot" not in (where[a][0], where[b][0])]


def walls():
    found = re.findall(r"wall: \{from: \[([\d.]+), ([\d.]+)\], to: \[([\d.]+), ([\d.]+)\]", open(SCENARIO).read())
    return [((float(a), float(b)), (float(c), float(d))) for a, b, c, d in found]


class IndoorWalls(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.walled, cls.open = (os.path.join(cls.tmp.name, name) for name in ("walls", "open"))
        subprocess.run([SANET, "run", SCENARIO, "-q", "-o", cls.walled], check=True)
        subprocess.run([SANET, "run", SCENARIO, "-q", "-o", cls.open, "--set", "world.obstacle_material=none"],
                       check=True)
        cls.walls = walls()

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def through_walls(self, folder):
        return [(a[0], b[0]) for a, b in links(folder)
                if any(crosses(a[1], b[1], w) for w in self.walls) and math.dist(a[1], b[1]) > THROUGH_ONE_WALL]

    def test_with_walls_no_link_reaches_through_a_wall_and_without_them_some_do(self):
        self.assertGreater(len(self.walls), 15)
        self.assertEqual(self.through_walls(self.walled), [])
        self.assertGreater(len(self.through_walls(self.open)), 5)
        self.assertGreater(len(links(self.open)), len(links(self.walled)) + 5)

    def test_the_robot_is_led_through_the_doorways_and_arrives(self):
        for folder in (self.walled, self.open):
            with open(os.path.join(folder, "log.csv")) as f:
                self.assertIn("arrived", [row["text"] for row in csv.DictReader(f) if row["node"] == "robot"], folder)
        with open(os.path.join(self.walled, "log.csv")) as f:
            hops = re.findall(r"from (\w+)", " ".join(row["text"] for row in csv.DictReader(f)
                                                      if row["text"].startswith("route refresh")))
        self.assertGreater(len(hops), 5)
        self.assertTrue(all(h == "south0" or h.startswith("corridor") for h in hops), hops)

    def test_the_figure_draws_both_runs(self):
        out = os.path.join(self.tmp.name, "links.svg")
        printed = subprocess.run(["/usr/bin/python3", os.path.join(SOURCE, "tools", "wall_links_figure.py"),
                                  self.walled, self.open, out], check=True, capture_output=True, text=True).stdout
        counts = [int(n) for n in re.findall(r"(\d+) links between motes", printed)]
        self.assertEqual(counts, [len(links(self.walled)), len(links(self.open))])
        self.assertIn("<svg", open(out).read(2000))


if __name__ == "__main__":
    unittest.main()
