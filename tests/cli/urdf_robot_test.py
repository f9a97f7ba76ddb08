#!/usr/bin/env python3
"""A robot from a URDF file (`body.urdf`) as a user meets it: validate --print shows the values read
under their usual keys (worked out by hand from scenarios/robots/little-diff.urdf), its wheels at
w rad/s drive it at w times their radius, the effective scenario carries the file's text and runs
to the same fingerprint without the file, and faults are refused with the file and line."""
import csv
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest

SANET = sys.argv.pop(1)
ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
URDF = os.path.join(ROOT, "scenarios", "robots", "little-diff.urdf")
SCENARIO = """name: urdf-robot
duration: 5
world: {size: [20, 20]}
nodes:
  - name: r
    model: diffdrive
    pose: [2, 2, 0]
    body:
      urdf: robot.urdf
      wheels: {left: left_wheel_joint, right: right_wheel_joint}
    sensors: {laser: {link: laser, max_range: 5}}
    controller: {name: constant_velocity, params: {wheel_speeds: [4, 4], start: 1, stop: 4}}
"""

# A three-wheeled omnidirectional robot: a cylinder chassis (radius 0.15 m, 0.1 m tall, its centre
# 0.03 m above the base link's origin), wheels of 3.5 cm 0.12 m out at 0, 120 and 240 degrees, at
# the base link's height.
OMNI_URDF = os.path.join(ROOT, "scenarios", "robots", "little-omni.urdf")
OMNI_SCENARIO = """name: urdf-omni
duration: 5
world: {size: [20, 20]}
nodes:
  - name: r
    model: omni3
    pose: [2, 2, 0]
    body:
      urdf: omni.urdf
      wheels: [wheel_0_joint, wheel_1_joint, wheel_2_joint]
    controller: {name: constant_velocity, params: {wheel_speeds: [2, 2, 2], start: 1, stop: 3}}
"""


class UrdfRobot(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp()
        shutil.copy(URDF, os.path.join(self.tmp, "robot.urdf"))

    def tearDown(self):
        shutil.rmtree(self.tmp)

    def write(self, name, text):
        path = os.path.join(self.tmp, name)
        with open(path, "w") as f:
            f.write(text)
        return path

    def sanet(self, *args, check=True):
        done = subprocess.run([SANET, *args], capture_output=True, text=True)
        if check:
            self.assertEqual(done.returncode, 0, done.stderr)
        return done

    def test_the_body_is_the_files_and_its_wheels_drive_it(self):
        scenario = self.write("s.yaml", SCENARIO)
        printed = self.sanet("validate", scenario, "--print").stdout
        for key, value in (("wheel_radius", "0.05"), ("axle_length", "0.29"), ("body_mass", "2.3"),
                           ("wheel_mass", "0.25"), ("body_length", "0.3"), ("body_width", "0.24"),
                           ("body_height", "0.1"), ("ground_clearance", "0.04")):
            self.assertIn("      %s: %s\n" % (key, value), printed)
        # The chassis's moments: base_link, caster, mast and laser (little-diff.urdf's <inertial>s, at
        # their links' places) about their common centre, by the parallel axis theorem.
        links = [(2.0, (-0.05, 0, 0.04), (0.02, 0.03, 0.04)), (0.05, (-0.17, 0, -0.03), (1e-5, 1e-5, 1e-5)),
                 (0.1, (0.05, 0, 0.09), (1e-4, 1e-4, 1e-5)), (0.15, (0.05, 0, 0.21), (1e-4, 1e-4, 1e-4))]
        mass = sum(m for m, _, _ in links)
        centre = [sum(m * at[i] for m, at, _ in links) / mass for i in range(3)]
        moments = [sum(own[i] + m * sum((at[j] - centre[j]) ** 2 for j in range(3) if j != i)
                       for m, at, own in links) for i in range(3)]
        read = re.search(r"\n      body_inertia: \[(.*)\]\n", printed).group(1).split(", ")
        for got, expected in zip(read, moments):
            self.assertAlmostEqual(float(got), expected, places=9)
        # The laser on its link: the mast 0.05 m ahead of the axle and 0.09 m up, the laser 0.12 m
        # above the mast, the axle 0.05 m (a wheel's radius) above the ground.
        laser = printed[printed.index("      laser:\n"):]
        self.assertIn("        mount_x: 0.05\n", laser[:300])
        self.assertIn("        height: 0.26\n", laser[:300])
        out = os.path.join(self.tmp, "run")
        self.sanet("run", scenario, "-q", "-o", out)
        with open(os.path.join(out, "trajectories.csv")) as f:
            rows = list(csv.DictReader(f))
        travelled = float(rows[-1]["x"]) - float(rows[0]["x"])
        self.assertAlmostEqual(travelled, 4 * 0.05 * 3, delta=0.01, msg="4 rad/s for 3 s on wheels of 5 cm")

    def test_an_omni3_from_a_urdf_turns_as_its_wheels_say(self):
        shutil.copy(OMNI_URDF, os.path.join(self.tmp, "omni.urdf"))
        scenario = self.write("omni.yaml", OMNI_SCENARIO)
        printed = self.sanet("validate", scenario, "--print").stdout
        for key, value in (("wheel_radius", 0.035), ("wheel_distance", 0.12), ("body_radius", 0.15),
                           ("body_height", 0.1), ("body_mass", 2), ("wheel_mass", 0.1), ("ground_clearance", 0.015)):
            read = re.search(r"\n      %s: (\S+)\n" % key, printed)
            self.assertAlmostEqual(float(read.group(1)), value, places=5, msg=key)  # the file has 6 decimals
        self.assertIn("wheels: [wheel_0_joint, wheel_1_joint, wheel_2_joint]", printed)
        out = os.path.join(self.tmp, "run")
        self.sanet("run", scenario, "-q", "-o", out)
        with open(os.path.join(out, "trajectories.csv")) as f:
            rows = [r for r in csv.DictReader(f) if 1.5 <= float(r["time"]) <= 2.5]
        # Three wheels at the same speed turn the body in place at w r / d.
        turned = math.remainder(float(rows[-1]["theta"]) - float(rows[0]["theta"]), 2 * math.pi)
        elapsed = float(rows[-1]["time"]) - float(rows[0]["time"])
        self.assertAlmostEqual(abs(turned) / elapsed, 2 * 0.035 / 0.12, delta=0.03)
        self.assertLess(math.hypot(float(rows[-1]["x"]) - 2, float(rows[-1]["y"]) - 2), 0.02)
        # The file's moments are the physics': four thousand times its izz spins it up more slowly.
        heavy = self.write("heavy.yaml", OMNI_SCENARIO.replace("      wheels:", "      body_inertia: [50, 50, 90]\n"
                                                                 "      wheels:"))
        self.sanet("run", heavy, "-q", "-o", os.path.join(self.tmp, "heavy"))
        turned_by = {}
        for name in ("run", "heavy"):
            with open(os.path.join(self.tmp, name, "trajectories.csv")) as f:
                early = [r for r in csv.DictReader(f) if 1.0 <= float(r["time"]) <= 1.3]
            turned_by[name] = abs(math.remainder(float(early[-1]["theta"]) - float(early[0]["theta"]), 2 * math.pi))
        self.assertLess(turned_by["heavy"], 0.5 * turned_by["run"], turned_by)

    def test_the_robot_turns_about_its_axle_wherever_the_base_link_is(self):
        """A URDF whose base link stands 0.1 m behind the axle, under a root footprint link, and whose
        left wheel turns about -y (as some files write it): the robot is the same; the laser's
        mount is measured from the axle; a namespace declaration for xacro alone is no xacro."""
        with open(URDF) as f:
            text = f.read()
        moved = text.replace('<robot name="little_diff">', '<robot name="little_diff" '
                             'xmlns:xacro="http://www.ros.org/wiki/xacro">\n  <link name="base_footprint"/>\n'
                             '  <joint name="footprint_joint" type="fixed">\n    <parent link="base_footprint"/>\n'
                             '    <child link="base_link"/>\n    <origin xyz="0 0 0.05"/>\n  </joint>')
        for joint in ("0 0.145 0", "0 -0.145 0"):
            moved = moved.replace('<origin xyz="%s"' % joint, '<origin xyz="0.1 %s"' % joint.split(" ", 1)[1])
        moved = moved.replace('<origin xyz="0 0.145 0" rpy="-1.5707963 0 0"/>\n    <axis xyz="0 0 1"/>',
                              '<origin xyz="0 0.145 0" rpy="-1.5707963 0 0"/>\n    <axis xyz="0 0 -1"/>')
        self.write("robot.urdf", moved)
        named = SCENARIO.replace("      urdf: robot.urdf\n", "      urdf: robot.urdf\n      base_link: base_link\n")
        refused = self.sanet("validate", self.write("s.yaml", SCENARIO), check=False).stderr
        self.assertIn("the default is the URDF's root", refused, "base_footprint has no chassis")
        printed = self.sanet("validate", self.write("s.yaml", named), "--print").stdout
        for key, value in (("wheel_radius", "0.05"), ("axle_length", "0.29"), ("ground_clearance", "0.04")):
            self.assertIn("      %s: %s\n" % (key, value), printed)
        laser = printed[printed.index("      laser:\n"):]
        self.assertIn("        mount_x: -0.05\n", laser[:300], "the mast is 0.05 m behind the axle now")
        self.assertIn("        height: 0.26\n", laser[:300])

    def test_the_effective_scenario_carries_the_file_and_runs_the_same(self):
        scenario = self.write("s.yaml", SCENARIO)
        effective = self.write("effective.yaml", self.sanet("validate", scenario, "--print").stdout)
        runs = []
        for path in (scenario, effective):
            out = os.path.join(self.tmp, "run-" + os.path.basename(path))
            self.sanet("run", path, "-q", "-o", out)
            with open(os.path.join(out, "summary.json")) as f:
                runs.append(json.load(f))
            os.remove(os.path.join(self.tmp, "robot.urdf")) if path == scenario else None
        self.assertEqual(runs[0]["scenario_fingerprint"], runs[1]["scenario_fingerprint"])
        self.assertEqual(runs[0]["fingerprint"], runs[1]["fingerprint"])
        # The fingerprint covers the file's content: a heavier chassis is another scenario.
        shutil.copy(URDF, os.path.join(self.tmp, "robot.urdf"))
        with open(URDF) as f:
            heavier = f.read().replace('<mass value="2.0"/>', '<mass value="2.5"/>')
        self.write("robot.urdf", heavier)
        out = os.path.join(self.tmp, "run-heavier")
        self.sanet("run", scenario, "-q", "-o", out)
        with open(os.path.join(out, "summary.json")) as f:
            self.assertNotEqual(json.load(f)["scenario_fingerprint"], runs[0]["scenario_fingerprint"])

    def test_faults_are_refused_with_file_and_line(self):
        with open(URDF) as f:
            text = f.read()
        cases = [
            (text.replace('type="continuous">\n    <parent link="base_link"/>\n    <child link="right_wheel"/>',
                          'type="fixed">\n    <parent link="base_link"/>\n    <child link="right_wheel"/>'),
             SCENARIO, "robot.urdf:47", "continuous joint"),
            (text.replace('<origin xyz="0 0 0.12"/>', '<origin xyz="0 0 ${mast}"/>'), SCENARIO, "robot.urdf:90",
             "xacro"),
            (text, SCENARIO.replace("right: right_wheel_joint", "right: rear_wheel_joint"), "s.yaml:10",
             "no joint of that name"),
            (text, SCENARIO.replace("model: diffdrive", "model: omni3"), "s.yaml:10", "list of its three wheel"),
            (text, SCENARIO.replace("model: diffdrive", "model: mote"), "s.yaml:9", "diffdrive's or an omni3's"),
            (text, SCENARIO.replace("      urdf: robot.urdf\n", ""), "s.yaml:9", "goes with `urdf`"),
            (text, SCENARIO.replace("link: laser", "link: lidar"), "s.yaml:11", "no link 'lidar'"),
            (text, SCENARIO.replace("    body:\n      urdf: robot.urdf\n      wheels: {left: left_wheel_joint, "
                                    "right: right_wheel_joint}\n", ""), "s.yaml:8", "needs `urdf`"),
        ]
        no_mass = text
        for mass in ('<mass value="2.0"/>', '<mass value="0.05"/>', '<mass value="0.1"/>', '<mass value="0.15"/>'):
            no_mass = no_mass.replace(mass, '<mass value="0"/>')
        cases += [
            ("", SCENARIO, "robot.urdf:1", "the XML"),
            (text.replace('<mass value="0.25"/>', '<mass value="0"/>', 1), SCENARIO, "robot.urdf:22",
             "<inertial> mass above 0"),
            (no_mass, SCENARIO, "robot.urdf:6", "weigh nothing"),
            (text, SCENARIO.replace("right: right_wheel_joint", "right: left_wheel_joint"), "s.yaml:10", "twice"),
            (text.replace('ixx="0.02" ixy="0" ixz="0" iyy="0.03"', 'ixx="0.2" ixy="0" ixz="0" iyy="0.03"'),
             SCENARIO, "robot.urdf:6", "moments no body has"),
            (text, SCENARIO.replace("      wheels:", "      body_inertia: [1, 1, 3]\n      wheels:"), "s.yaml:10",
             "no body has these moments"),
            (text, SCENARIO.replace("{left: left_wheel_joint, right: right_wheel_joint}",
                                    "{left: right_wheel_joint, right: left_wheel_joint}"), "robot.urdf:47", "swap"),
            (text.replace('<origin xyz="0 0.145 0" rpy="-1.5707963 0 0"/>', '<origin xyz="0.05 0.145 0" '
                          'rpy="-1.5707963 0 0"/>'), SCENARIO, "robot.urdf:31", "not across the base link's x"),
            (text.replace('<axis xyz="0 0 1"/>', '<axis xyz="1 0 0"/>', 1), SCENARIO, "robot.urdf:31",
             "does not roll the wheel"),
        ]
        for urdf, scenario_text, where, words in cases:
            self.write("robot.urdf", urdf)
            done = self.sanet("validate", self.write("s.yaml", scenario_text), check=False)
            self.assertEqual(done.returncode, 2, done.stderr)
            self.assertIn(where, done.stderr)
            self.assertIn(words, done.stderr)


if __name__ == "__main__":
    unittest.main()
