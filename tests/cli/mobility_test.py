#!/usr/bin/env python3
"""The mobility controllers as a user runs them: random waypoint stays in its region with its
legs' speeds in their range (and follows the seed), a tour visits its points in the order asked,
a lawnmower covers its region's cells."""
import csv
import math
import os
import subprocess
import sys
import tempfile
import unittest

SANET = sys.argv.pop(1)
SCENARIO = """name: mobility
duration: 240
nodes:
  - name: rwp
    model: omni3
    pose: [5, 5, 0]
    controller: {name: random_waypoint, params: {region: [[0, 0], [40, 30]], speed_min: 0.4, speed_max: 1.0, pause: 1}}
  - name: given
    model: diffdrive
    pose: [-10, -10, 0]
    controller: {name: tour, params: {points: [[10, -20], [-10, -25], [15, -12]], speed: 1.0}}
  - name: nearest
    model: diffdrive
    pose: [-10, -40, 0]
    controller: {name: tour, params: {points: [[30, -40], [-10, -45], [10, -52]], order: nearest, speed: 1.0}}
  - name: mower
    model: omni3
    pose: [60, 0, 0]
    controller: {name: lawnmower, params: {region: [[60, 0], [80, 10]], spacing: 2.5, speed: 1.0}}
"""


class Mobility(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.path = os.path.join(cls.tmp.name, "mobility.yaml")
        with open(cls.path, "w") as f:
            f.write(SCENARIO)
        cls.runs = {seed: cls.simulate(seed) for seed in (1, 2)}

    @classmethod
    def simulate(cls, seed, tag=""):
        out = os.path.join(cls.tmp.name, f"seed{seed}{tag}")
        subprocess.run([SANET, "run", cls.path, "-q", "-o", out, "--seed", str(seed)], check=True)
        tracks, logs, metrics = {}, {}, {}
        with open(os.path.join(out, "trajectories.csv")) as f:
            for row in csv.DictReader(f):
                tracks.setdefault(row["node"], []).append((float(row["time"]), float(row["x"]), float(row["y"])))
        with open(os.path.join(out, "log.csv")) as f:
            for row in csv.DictReader(f):
                logs.setdefault(row["node"], []).append(row["text"])
        with open(os.path.join(out, "metrics.csv")) as f:
            for row in csv.DictReader(f):
                metrics.setdefault((row["node"], row["name"]), []).append(float(row["value"]))
        return tracks, logs, metrics

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_random_waypoint_stays_in_its_region_at_speeds_in_range(self):
        tracks, logs, metrics = self.runs[1]
        for _, x, y in tracks["rwp"]:
            self.assertTrue(-0.5 <= x <= 40.5 and -0.5 <= y <= 30.5, (x, y))
        speeds = metrics[("rwp", "leg_speed")]
        self.assertGreater(len(speeds), 5)
        self.assertTrue(all(0.4 <= s <= 1.0 for s in speeds), speeds)
        self.assertGreater(max(speeds) - min(speeds), 0.2, "speeds are drawn over the range")
        track = tracks["rwp"]
        fastest = max(math.hypot(b[1] - a[1], b[2] - a[2]) / (b[0] - a[0]) for a, b in zip(track, track[1:]))
        self.assertLess(fastest, 1.0 * 1.15, "never faster than speed_max")
        self.assertGreaterEqual(sum(t.startswith("reached waypoint") for t in logs["rwp"]), 5)
        other = self.runs[2][2][("rwp", "leg_speed")]
        self.assertNotEqual(speeds[:3], other[:3], "another seed, other legs")
        self.assertEqual(speeds, self.simulate(1, "-again")[2][("rwp", "leg_speed")], "the same seed, the same legs")

    def test_a_tour_visits_its_points_in_the_order_asked(self):
        logs = self.runs[1][1]
        self.assertEqual([t for t in logs["given"] if t.startswith("reached point") or t == "tour done"],
                         ["reached point 0", "reached point 1", "reached point 2", "tour done"])
        # From (-10, -40) the nearest is (-10, -45), then (10, -52), then (30, -40).
        self.assertEqual([t for t in logs["nearest"] if t.startswith("reached point")],
                         ["reached point 1", "reached point 2", "reached point 0"])

    def test_a_lawnmower_covers_its_region(self):
        tracks, logs, _ = self.runs[1]
        self.assertIn("tour done", logs["mower"])
        spacing, cells, covered = 2.5, 0, 0
        for i in range(int(20 / spacing)):
            for j in range(int(10 / spacing)):
                cx, cy = 60 + (i + 0.5) * spacing, (j + 0.5) * spacing
                cells += 1
                covered += any(math.hypot(x - cx, y - cy) <= spacing / 2 for _, x, y in tracks["mower"])
        self.assertEqual(covered, cells, f"{covered} of {cells} cells")


class Mistakes(unittest.TestCase):
    """A mobility controller's wrong parameters are refused at their line."""

    def test_wrong_parameters_are_refused(self):
        cases = [("random_waypoint", "{region: [[0, 0], [10, 10]], speed: 1}", "draws each leg's speed"),
                 ("random_waypoint", "{region: [[0, 0], [10, 10]], speed_min: 2, speed_max: 1}", "under speed_min"),
                 ("random_waypoint", "{region: [[0, 0], [0, 10]]}", "encloses no area"),
                 ("tour", "{points: [{node: nobody}]}", "no node named 'nobody'"),
                 ("tour", "{points: [[1, 1]], order: shortest}", "given or nearest"),
                 ("lawnmower", "{region: [[0, 0], [10, 10]], along: z}", "x or y")]
        with tempfile.TemporaryDirectory() as tmp:
            for name, params, message in cases:
                path = os.path.join(tmp, "bad.yaml")
                with open(path, "w") as f:
                    f.write(f"duration: 5\nnodes:\n  - name: r\n    model: omni3\n    pose: [0, 0, 0]\n"
                            f"    controller: {{name: {name}, params: {params}}}\n")
                done = subprocess.run([SANET, "validate", path], capture_output=True, text=True)
                self.assertEqual(done.returncode, 2, (name, params))
                self.assertIn("bad.yaml:6:", done.stderr)
                self.assertIn(message, done.stderr)


class ScatteredStudy(unittest.TestCase):
    """Each seed of a sweep scatters its own deployment, and a tour through `{nodes: m}` visits
    whatever the seed drew."""

    def test_each_seed_of_a_sweep_has_its_own_deployment(self):
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "field.yaml")
            with open(path, "w") as f:
                f.write("""name: field
duration: 200
nodes:
  - scatter: {name: m, count: 5, region: {min: [0, 0], max: [40, 40]}, min_separation: 8}
    model: mote
  - name: mule
    model: omni3
    pose: [-5, -5, 0]
    controller: {name: tour, params: {points: [{nodes: m}], order: nearest, speed: 1, tolerance: 1.5}}
""")
            study = os.path.join(tmp, "study")
            subprocess.run([SANET, "sweep", path, "--seeds", "1-2", "-o", study, "-q"], check=True)
            poses, reached = [], []
            for run in sorted(os.listdir(os.path.join(study, "runs"))):
                folder = os.path.join(study, "runs", run)
                with open(os.path.join(folder, "scenario.yaml")) as f:
                    poses.append([line for line in f if "pose:" in line])
                with open(os.path.join(folder, "log.csv")) as f:
                    reached.append(sorted(row["text"] for row in csv.DictReader(f) if row["text"].startswith("reached point")))
            self.assertEqual(len(poses), 2)
            self.assertNotEqual(poses[0], poses[1], "two seeds, two deployments")
            for visited in reached:
                self.assertEqual(visited, [f"reached point {i}" for i in range(5)], "every scattered mote visited")


if __name__ == "__main__":
    unittest.main()
