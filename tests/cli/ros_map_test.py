#!/usr/bin/env python3
"""Worlds from ROS maps (`world.map`) and worlds to ROS maps (`sanet map`), as a user meets them:
- map_server's rules, each on a small image written here: the thresholds (inclusive, as Nav2's
  map server since Jazzy), `negate`, unknown cells free or blocked, a transparent pixel unknown,
  the image's top row the map's last, `origin` offsetting every box;
- a round trip: a world of walls and boxes -> `sanet map` -> `world.map` -> `sanet map` gives the
  same image, and the boxes cover exactly the occupied cells;
- the effective scenario carries the boxes and runs the same without the map's files;
- a laser in a map world reads the distance the map's wall gives, within a cell;
- a radio link through a map wall loses what the same wall built by hand loses;
- faults are refused naming the file, the line and the key."""
import csv
import json
import math
import os
import re
import shutil
import sqlite3
import struct
import subprocess
import sys
import tempfile
import unittest
import zlib

SANET = sys.argv.pop(1)


def png(path, rows, alpha=None):
    """A grey PNG (grey + alpha where `alpha` gives each row's alpha values); rows top first."""
    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)
    width, height = len(rows[0]), len(rows)
    if alpha is None:
        raw, kind = b"".join(b"\x00" + bytes(r) for r in rows), 0
    else:
        raw, kind = b"".join(b"\x00" + bytes(v for pair in zip(r, a) for v in pair) for r, a in zip(rows, alpha)), 4
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, kind, 0, 0, 0)) +
                chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


def pgm(path, rows):
    with open(path, "wb") as f:
        f.write(b"P5\n# written by a test\n%d %d\n255\n" % (len(rows[0]), len(rows)) + b"".join(bytes(r) for r in rows))


def read_pgm(path):
    with open(path, "rb") as f:
        data = f.read()
    fields = re.sub(rb"#[^\n]*\n", b"", data).split(maxsplit=4)
    assert fields[0] == b"P5", fields[0]
    width, height = int(fields[1]), int(fields[2])
    pixels = fields[4]
    return [list(pixels[r * width:(r + 1) * width]) for r in range(height)]


def map_yaml(folder, image, resolution=0.1, origin=(0, 0, 0), negate=0, occupied=0.65, free=0.196, mode=None):
    with open(os.path.join(folder, "m.yaml"), "w") as f:
        f.write(f"image: {image}\nresolution: {resolution}\norigin: [{origin[0]}, {origin[1]}, {origin[2]}]\n"
                f"negate: {negate}\noccupied_thresh: {occupied}\nfree_thresh: {free}\n" +
                (f"mode: {mode}\n" if mode else ""))
    return "m.yaml"


def scenario(folder, map_block, nodes="  - {name: m, model: mote, pose: [50, 50, 0]}\n", extra=""):
    path = os.path.join(folder, "s.yaml")
    with open(path, "w") as f:
        f.write("name: s\nduration: 1\nworld:\n  map: " + map_block + "\n" + extra + "nodes:\n" + nodes)
    return path


class Sanet:
    def sanet(self, *args, check=True):
        done = subprocess.run([SANET, *args], capture_output=True, text=True, timeout=300)
        if check:
            self.assertEqual(done.returncode, 0, done.stderr)
        return done

    def cells(self, path):
        """The blocked cells the effective scenario's boxes cover, as (column, row)."""
        printed = self.sanet("validate", path, "--print").stdout
        boxes = re.search(r"\n    boxes:\n((?:      - \[.*\]\n)*)", printed)
        covered = set()
        for line in (boxes.group(1).splitlines() if boxes else []):
            c, r, w, h = map(int, re.findall(r"-?\d+", line))
            for x in range(c, c + w):
                for y in range(r, r + h):
                    self.assertNotIn((x, y), covered, "boxes overlap")
                    covered.add((x, y))
        return covered


class MapServerRules(Sanet, unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp()

    def tearDown(self):
        shutil.rmtree(self.tmp)

    # One row of greys, top to bottom the only row: p = (255 - v) / 255.
    GREYS = [0, 89, 90, 200, 205, 254, 255]  # p: 1, 0.651, 0.647, 0.216, 0.19608, 0.004, 0

    def test_thresholds_are_inclusive_and_negate_flips(self):
        png(os.path.join(self.tmp, "m.png"), [self.GREYS])
        # occupied_thresh 0.65: grey 89 (p 0.651) is a wall, grey 90 (p 0.647) is not.
        s = scenario(self.tmp, "{file: " + map_yaml(self.tmp, "m.png") + "}")
        self.assertEqual(self.cells(s), {(0, 0), (1, 0)})
        # Inclusive: occupied_thresh exactly p(89) = 166/255 still makes it a wall.
        map_yaml(self.tmp, "m.png", occupied=166 / 255)
        self.assertEqual(self.cells(s), {(0, 0), (1, 0)})
        # negate: p = v / 255: the light pixels are the walls.
        map_yaml(self.tmp, "m.png", negate=1)
        self.assertEqual(self.cells(s), {(3, 0), (4, 0), (5, 0), (6, 0)})

    def test_unknown_cells_free_or_blocked_and_scale_mode(self):
        png(os.path.join(self.tmp, "m.png"), [self.GREYS])
        yaml = map_yaml(self.tmp, "m.png")
        # free_thresh 0.196: grey 205 (p 0.19608, a map saver's unknown), 200 and 90 are unknown;
        # 254 (p 0.004) is free.
        blocked = self.cells(scenario(self.tmp, "{file: " + yaml + ", unknown: blocked}"))
        self.assertEqual(blocked, {(0, 0), (1, 0), (2, 0), (3, 0), (4, 0)})
        map_yaml(self.tmp, "m.png", mode="scale")  # shades between are no walls, nor unknown
        self.assertEqual(self.cells(scenario(self.tmp, "{file: " + yaml + ", unknown: blocked}")), {(0, 0), (1, 0)})

    def test_a_transparent_pixel_is_unknown_and_the_top_row_is_the_last(self):
        png(os.path.join(self.tmp, "m.png"), [[0, 254, 254], [254, 0, 254]], alpha=[[255, 255, 0], [255, 255, 255]])
        yaml = map_yaml(self.tmp, "m.png")
        self.assertEqual(self.cells(scenario(self.tmp, "{file: " + yaml + "}")), {(0, 1), (1, 0)})
        self.assertEqual(self.cells(scenario(self.tmp, "{file: " + yaml + ", unknown: blocked}")),
                         {(0, 1), (1, 0), (2, 1)})

    def test_a_pgm_with_an_origin_puts_the_boxes_where_the_origin_says(self):
        rows = [[254] * 10 for _ in range(6)]
        for r in range(6):
            rows[r][7] = 0  # a wall along column 7, the whole height
        pgm(os.path.join(self.tmp, "m.pgm"), rows)
        yaml = map_yaml(self.tmp, "m.pgm", resolution=0.5, origin=(-3, 2, 0))
        s = scenario(self.tmp, "{file: " + yaml + ", height: 2, material: brick}",
                     nodes="  - {name: m, model: mote, pose: [0, 3, 0]}\n",
                     extra="network: {radio: 802.11b, routing: none}\n")
        out = os.path.join(self.tmp, "out")
        self.sanet("run", s, "-q", "-o", out)
        with sqlite3.connect(os.path.join(out, "trace.sqlite")) as db:
            boxes = db.execute("SELECT kind, cx, cy, length, width, height FROM obstacles").fetchall()
        self.assertEqual(len(boxes), 1)
        kind, x, y, length, width, height = boxes[0]
        self.assertEqual(kind, "map")
        # Column 7 spans x -3 + 3.5 .. -3 + 4 m; six rows of 0.5 m from y = 2.
        self.assertAlmostEqual(x, 0.75), self.assertAlmostEqual(y, 3.5)
        self.assertAlmostEqual(length, 0.5), self.assertAlmostEqual(width, 3), self.assertAlmostEqual(height, 2)
        # A node inside the wall is refused, as inside any obstacle.
        s = scenario(self.tmp, "{file: " + yaml + "}", nodes="  - {name: m, model: mote, pose: [0.75, 3, 0]}\n")
        done = self.sanet("validate", s, check=False)
        self.assertEqual(done.returncode, 2, done.stderr)
        self.assertIn("s.yaml:6", done.stderr)
        self.assertIn("inside a wall of world.map m.yaml (its box from (0.50, 2.00) to (1.00, 5.00) m)", done.stderr)

    def test_pgm_depths_colour_and_a_turned_origin(self):
        # A 16-bit PGM (two bytes, big-endian) and one of maxval 100: values scaled to 0..255.
        with open(os.path.join(self.tmp, "m.pgm"), "wb") as f:
            f.write(b"P5\n# sixteen bits\n3 1\n65535\n" + bytes([0x00, 0xFF, 0xFE, 0x00, 0xFF, 0xFF]))
        s = scenario(self.tmp, "{file: " + map_yaml(self.tmp, "m.pgm") + "}")
        self.assertEqual(self.cells(s), {(0, 0)})  # 0x00FF is dark: a wall; 0xFE00 and 0xFFFF light
        with open(os.path.join(self.tmp, "m.pgm"), "wb") as f:
            f.write(b"P5 3 1 100\n" + bytes([0, 50, 100]))
        self.assertEqual(self.cells(s), {(0, 0)})  # 100 is white, 50 (p 0.5) unknown
        self.assertEqual(self.cells(scenario(self.tmp, "{file: m.yaml, unknown: blocked}")), {(0, 0), (1, 0)})
        # A colour PNG: red's luma (76) is a wall at occupied_thresh 0.65, blue's (29) too, green's (150) not.
        with open(os.path.join(self.tmp, "m.png"), "wb") as f:
            rows = [[255, 0, 0, 0, 0, 255, 0, 255, 0]]
            def chunk(kind, data):
                body = kind + data
                return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)
            f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 3, 1, 8, 2, 0, 0, 0)) +
                    chunk(b"IDAT", zlib.compress(b"\x00" + bytes(rows[0]))) + chunk(b"IEND", b""))
        self.assertEqual(self.cells(scenario(self.tmp, "{file: " + map_yaml(self.tmp, "m.png") + "}")), {(0, 0), (1, 0)})
        # A turned origin: one wall cell at column 2 of a map turned 90 degrees about (1, 1).
        png(os.path.join(self.tmp, "m.png"), [[254, 254, 0, 254]])
        map_yaml(self.tmp, "m.png", resolution=1, origin=(1, 1, math.pi / 2))
        out = os.path.join(self.tmp, "turned")
        self.sanet("run", scenario(self.tmp, "{file: m.yaml}"), "-q", "-o", out)
        with sqlite3.connect(os.path.join(out, "trace.sqlite")) as db:
            (x, y, yaw), = db.execute("SELECT cx, cy, yaw FROM obstacles").fetchall()
        self.assertAlmostEqual(x, 0.5), self.assertAlmostEqual(y, 3.5), self.assertAlmostEqual(yaw, math.pi / 2)

    def test_a_cut_short_or_empty_pgm_is_refused(self):
        map_yaml(self.tmp, "m.pgm")
        s = scenario(self.tmp, "{file: m.yaml}")
        for content, words in ((b"P5\n10 10\n255\n" + bytes(50), "cut short"), (b"P5\n0 0\n255\n", "header")):
            with open(os.path.join(self.tmp, "m.pgm"), "wb") as f:
                f.write(content)
            done = self.sanet("validate", s, check=False)
            self.assertEqual(done.returncode, 2, done.stderr)
            self.assertIn("m.yaml:1", done.stderr)
            self.assertIn(words, done.stderr)

    def test_faults_name_the_file_the_line_and_the_key(self):
        png(os.path.join(self.tmp, "m.png"), [self.GREYS])
        cases = [
            ("image: m.png\nresolution: 0.1\norigin: [0, 0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.2\n",
             "m.yaml:3", "origin"),
            ("image: m.png\nresolution: 0.1\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.65\n", "m.yaml",
             "free_thresh"),
            ("image: gone.png\nresolution: 0.1\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.65\n"
             "free_thresh: 0.2\n", "m.yaml:1", "cannot read the image"),
            ("image: m.png\nresolution: 0.1\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.65\n"
             "free_thresh: 0.2\nmode: raw\n", "m.yaml:7", "raw"),
            ("image: m.png\nresolution: 0.1\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.5\n"
             "free_thresh: 0.6\n", "m.yaml:6", "below occupied_thresh"),
        ]
        s = scenario(self.tmp, "{file: m.yaml}")
        for text, where, words in cases:
            with open(os.path.join(self.tmp, "m.yaml"), "w") as f:
                f.write(text)
            done = self.sanet("validate", s, check=False)
            self.assertEqual(done.returncode, 2, done.stderr)
            self.assertIn(where, done.stderr)
            self.assertIn(words, done.stderr)
        map_yaml(self.tmp, "m.png")  # a good map again: the scenario's own mistakes
        for block, where, words in (("{file: none.yaml}", "s.yaml:4", "no map file"),
                                    ("{file: m.yaml, unknown: maybe}", "s.yaml:4", "free or blocked"),
                                    ("{file: m.yaml, material: cheese}", "s.yaml:4", "unknown material"),
                                    ("{file: m.yaml, material: brick}", "s.yaml:4", "needs a 'network'")):
            done = self.sanet("validate", scenario(self.tmp, block), check=False)
            self.assertEqual(done.returncode, 2, done.stderr)
            self.assertIn(where, done.stderr)
            self.assertIn(words, done.stderr)


RANGER = """
class Ranger:
    \"\"\"Logs the laser's middle beam (straight ahead) once, standing still.\"\"\"
    def __init__(self, params):
        self.done = False

    def control_step(self, node):
        scan = node.laser()
        if scan is not None and not self.done:
            node.log("ahead %.4f" % scan.ranges[len(scan.ranges) // 2])
            self.done = True
"""


class InTheMapsWorld(Sanet, unittest.TestCase):
    """A ragged wall of a map of 0.05 m cells: column 60 (x from 3.0 to 3.05 m) the whole height,
    and column 61 beside it on every other row (the odd rows from the bottom), as SLAM draws a
    wall: the map's boxes are column 60 and single cells beside it. The laser and the radio meet
    it there."""

    def setUp(self):
        self.tmp = tempfile.mkdtemp()
        rows = [[254] * 100 for _ in range(60)]
        for i, row in enumerate(rows):
            row[60] = 0
            row[61] = 0 if (59 - i) % 2 == 1 else 254
        pgm(os.path.join(self.tmp, "m.pgm"), rows)
        map_yaml(self.tmp, "m.pgm", resolution=0.05)

    def tearDown(self):
        shutil.rmtree(self.tmp)

    def test_a_laser_reads_the_distance_to_the_maps_wall(self):
        with open(os.path.join(self.tmp, "ranger.py"), "w") as f:
            f.write(RANGER)
        s = scenario(self.tmp, "{file: m.yaml}", nodes="  - name: r\n    model: diffdrive\n    pose: [1, 1.525, 0]\n"
                     "    sensors: {laser: {mount_x: 0.2, max_range: 5}}\n"
                     "    controller: {python: \"ranger:Ranger\", rate: 10}\n")
        out = os.path.join(self.tmp, "out")
        self.sanet("run", s, "-q", "-o", out)
        with open(os.path.join(out, "log.csv")) as f:
            said = [r["text"] for r in csv.DictReader(f) if r["text"].startswith("ahead")]
        self.assertEqual(len(said), 1)
        # The wall's near face at x = 3.0; the laser 0.2 m ahead of the robot at x = 1.
        self.assertAlmostEqual(float(said[0].split()[1]), 3.0 - 1.2, delta=0.05)

    def test_a_radio_link_through_the_maps_wall_loses_what_a_wall_built_by_hand_loses(self):
        """Link curves across the wall, square-on (along y = 1.5 from x = 1.5) and slanted (45
        degrees from (1.5, 0.2)): the received power beyond it, with the map's wall of concrete
        0.1 m thick (two boxes side by side across it: its columns), equals that with the same
        wall built by hand, and is well below the power with no wall loss."""
        for along in ("1.5,1.575,9,1.575", "1.5,0.2,4.5,3.2"):
            with self.subTest(along=along):
                self.compare(along)

    def compare(self, along):
        radio = "network: {radio: 802.11b, routing: none}\n"
        powers = {}
        for name, world in (("map", "{file: m.yaml, material: concrete, thickness: 0.1}"),
                            ("none", "{file: m.yaml, material: none}")):
            s = scenario(self.tmp, world, extra=radio)
            powers[name] = self.curve(s, name, along)
        hand = os.path.join(self.tmp, "hand.yaml")
        with open(hand, "w") as f:
            f.write("name: s\nduration: 1\nworld:\n  obstacles:\n    - wall: {from: [3.05, 0], to: [3.05, 3], "
                    "thickness: 0.1, material: concrete}\n" + radio +
                    "nodes:\n  - {name: m, model: mote, pose: [50, 50, 0]}\n")
        powers["hand"] = self.curve(hand, "hand", along)
        face = 1.5 if along.startswith("1.5,1.575") else 1.5 * math.sqrt(2)  # where the line meets the wall
        for distance in powers["map"]:
            if abs(distance - face) < 0.3:
                continue  # in the wall
            if distance > face:
                self.assertAlmostEqual(powers["map"][distance], powers["hand"][distance], delta=0.05)
                self.assertGreater(powers["none"][distance] - powers["map"][distance], 5, distance)
            else:
                self.assertAlmostEqual(powers["map"][distance], powers["none"][distance], delta=0.05)

    def curve(self, scenario_path, name, along):
        out = os.path.join(self.tmp, "curve-" + name)
        self.sanet("link-curve", scenario_path, "-o", out, "--force", "--along", along, "--from", "0.5", "--to", "3",
                   "--step", "0.5", "--frames", "10", "--links", "2", "-q")
        with open(os.path.join(out, "link_curve.csv")) as f:
            # (mean_dbm is the open field's: the received power through the walls is the RSSI's)
            return {float(r["distance_m"]): float(r["rssi_median_dbm"]) for r in csv.DictReader(f)}


WORLD = """name: built
duration: 1
world:
  size: [20, 10]
  obstacles:
    - wall: {from: [1, 1], to: [9, 1], thickness: 0.2, height: 1}
    - wall: {from: [9, 1], to: [9, 6], thickness: 0.2, height: 1}
    - box: {center: [4, 4], size: [1, 0.6, 0.5]}
nodes:
  - {name: m, model: mote, pose: [5, 3, 0]}
"""


class RoundTrip(Sanet, unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp()

    def tearDown(self):
        shutil.rmtree(self.tmp)

    def test_world_to_map_to_world_to_map_is_the_same_map(self):
        built = os.path.join(self.tmp, "built.yaml")
        with open(built, "w") as f:
            f.write(WORLD)
        said = self.sanet("map", built, "-o", os.path.join(self.tmp, "maps"), "--resolution", "0.05").stdout
        self.assertIn("built.yaml and built.pgm", said)
        first = read_pgm(os.path.join(self.tmp, "maps", "built.pgm"))
        with open(os.path.join(self.tmp, "maps", "built.yaml")) as f:
            meta = f.read()
        self.assertIn("occupied_thresh: 0.65", meta)
        self.assertIn("free_thresh: 0.196", meta)
        # The walls: 8 x 0.2 m and 0.2 x 5 m (overlapping in 0.1 x 0.1 m at the corner), the box
        # 1 x 0.6 m, in cells of 0.05 m.
        occupied = sum(v == 0 for row in first for v in row)
        self.assertEqual(occupied, 160 * 4 + 4 * 100 - 2 * 2 + 20 * 12)
        self.assertTrue(all(v in (0, 254) for row in first for v in row))
        # The map as the world, mapped again.
        again = scenario(self.tmp, "{file: maps/built.yaml}", nodes="  - {name: m, model: mote, pose: [5, 3, 0]}\n")
        self.sanet("map", again, "-o", os.path.join(self.tmp, "again"), "--resolution", "0.05", "--name", "built")
        self.assertEqual(read_pgm(os.path.join(self.tmp, "again", "built.pgm")), first)
        # And its boxes cover exactly the occupied cells.
        height = len(first)
        blocked = {(c, height - 1 - r) for r, row in enumerate(first) for c, v in enumerate(row) if v == 0}
        self.assertEqual(self.cells(again), blocked)

    def test_a_wall_thinner_than_a_cell_stays_a_wall(self):
        built = os.path.join(self.tmp, "built.yaml")
        with open(built, "w") as f:
            f.write(WORLD)
        self.sanet("map", built, "-o", os.path.join(self.tmp, "coarse"), "--resolution", "0.5")
        cells = read_pgm(os.path.join(self.tmp, "coarse", "built.pgm"))
        # The 0.2 m wall along y = 1 from x = 1 to 9: a row of cells at 0.5 m, unbroken.
        rows = [r for r, row in enumerate(cells) if sum(v == 0 for v in row) >= 16]
        self.assertTrue(rows, "the wall along x is in the coarse map")

    def test_the_effective_scenario_runs_the_same_without_the_files(self):
        built = os.path.join(self.tmp, "built.yaml")
        with open(built, "w") as f:
            f.write(WORLD)
        self.sanet("map", built, "-o", os.path.join(self.tmp, "maps"))
        s = scenario(self.tmp, "{file: maps/built.yaml, material: concrete}",
                     nodes="  - {name: r, model: diffdrive, pose: [5, 2.5, 0]}\n",
                     extra="network: {radio: 802.11b, routing: none}\n")
        effective = os.path.join(self.tmp, "effective.yaml")
        with open(effective, "w") as f:
            f.write(self.sanet("validate", s, "--print").stdout)
        runs = []
        for path in (s, effective):
            out = os.path.join(self.tmp, "run-" + os.path.basename(path))
            self.sanet("run", path, "-q", "-o", out)
            with open(os.path.join(out, "summary.json")) as f:
                runs.append(json.load(f))
            if path == s:
                shutil.rmtree(os.path.join(self.tmp, "maps"))
        self.assertEqual(runs[0]["scenario_fingerprint"], runs[1]["scenario_fingerprint"])
        self.assertEqual(runs[0]["fingerprint"], runs[1]["fingerprint"])


if __name__ == "__main__":
    unittest.main()
