#!/usr/bin/env python3
"""Wheel encoders (`sensors.encoders`) as a controller reads them: a diffdrive driving straight
at 4 rad/s reads its wheels turning at 4 rad/s, and their angles times the wheel's radius are the
distance its odometry says it went; a tick `resolution` counts whole ticks; a URDF robot's joints
keep the file's names; trace.mcap's /<robot>/joint_states (sensor_msgs/msg/JointState) decodes
with the independent MCAP reader; a mote is refused."""
import csv
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

from mcap_log import decoded

SANET, SOURCE = sys.argv.pop(1), sys.argv.pop(1)
MODULES = os.path.join(SOURCE, "build", "npm", "node_modules")

READER = """
class Reader:
    # Drives both wheels at 4 rad/s from 1 s to 4 s; logs the encoders and the odometry.
    def __init__(self, params):
        pass

    def control_step(self, node):
        t = node.now()
        node.set_wheel_speeds([4.0, 4.0] if 1 <= t < 4 else [0.0, 0.0])
        joints, odo = node.sensor("encoders"), node.odometry()
        node.log("enc %.2f %s %s %s %.6f" % (t, ",".join(joints.names), ",".join("%.6f" % a for a in joints.angles),
                                            ",".join("%.6f" % s for s in joints.speeds), odo.x))
"""


def scenario(folder, sensors, body=""):
    with open(os.path.join(folder, "reader.py"), "w") as f:
        f.write(READER)
    path = os.path.join(folder, "s.yaml")
    with open(path, "w") as f:
        f.write("name: enc\nduration: 6\nworld: {size: [20, 20]}\nnodes:\n  - name: r\n    model: diffdrive\n"
                "    pose: [2, 2, 0]\n" + body + "    sensors: " + sensors + "\n"
                "    controller: {python: \"reader:Reader\", rate: 10}\n")
    return path


def logged(folder):
    rows = []
    with open(os.path.join(folder, "log.csv")) as f:
        for r in csv.DictReader(f):
            if r["text"].startswith("enc "):
                _, t, names, angles, speeds, x = r["text"].split(" ")
                rows.append((float(t), names.split(","), [float(a) for a in angles.split(",")],
                             [float(s) for s in speeds.split(",")], float(x)))
    return rows


class Encoders(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp()

    def tearDown(self):
        shutil.rmtree(self.tmp)

    def run_sanet(self, *args, check=True):
        done = subprocess.run([SANET, *args], capture_output=True, text=True, timeout=120)
        if check:
            self.assertEqual(done.returncode, 0, done.stderr)
        return done

    def test_the_angles_integrate_to_the_odometrys_distance(self):
        out = os.path.join(self.tmp, "out")
        self.run_sanet("run", scenario(self.tmp, "{encoders: {}}"), "-q", "-o", out)
        rows = logged(out)
        self.assertEqual(rows[0][1], ["left_wheel_joint", "right_wheel_joint"])
        t, _, angles, _, x = rows[-1]
        radius = 0.0975  # the diffdrive's default wheel
        travelled = x - 2  # odometry from the start pose, x = 2
        self.assertGreater(travelled, 1.0)
        self.assertAlmostEqual(sum(angles) / 2 * radius, travelled, delta=0.01 * travelled)
        cruising = [s for t, _, _, speeds, _ in rows if 2 <= t < 3.9 for s in speeds]
        self.assertTrue(cruising)
        for s in cruising:
            self.assertAlmostEqual(s, 4.0, delta=0.1)
        self.assertTrue(all(abs(s) < 0.1 for t, _, _, speeds, _ in rows if t >= 5 for s in speeds), "stopped")
        if os.path.isdir(MODULES):
            self.joint_states_decode(out)

    def joint_states_decode(self, out):
        log = decoded(SOURCE, MODULES, os.path.join(out, "trace.mcap"))
        self.assertEqual(log["channels"]["/r/joint_states"]["schema"], "sensor_msgs/msg/JointState")
        self.assertEqual(log["counts"]["/r/joint_states"], 6 * 50 + 1, "every sample of 6 s at 50 Hz")
        last = log["last"]["/r/joint_states"]
        self.assertEqual(last["name"], ["left_wheel_joint", "right_wheel_joint"])
        self.assertEqual(len(last["position"]), 2)
        self.assertEqual(last["effort"], [])

    def test_a_resolution_counts_whole_ticks(self):
        out = os.path.join(self.tmp, "out")
        self.run_sanet("run", scenario(self.tmp, "{encoders: {resolution: 0.01}}"), "-q", "-o", out)
        for _, _, angles, _, _ in logged(out):
            for a in angles:
                self.assertAlmostEqual(a / 0.01, round(a / 0.01), places=6)

    def test_a_urdf_robots_joints_keep_their_names_and_a_mote_has_none(self):
        with open(os.path.join(SOURCE, "scenarios", "robots", "little-diff.urdf")) as f:
            text = f.read().replace("left_wheel_joint", "wheel_l").replace("right_wheel_joint", "wheel_r")
        with open(os.path.join(self.tmp, "robot.urdf"), "w") as f:
            f.write(text)
        body = "    body:\n      urdf: robot.urdf\n      wheels: {left: wheel_l, right: wheel_r}\n"
        out = os.path.join(self.tmp, "out")
        self.run_sanet("run", scenario(self.tmp, "{encoders: {}}", body), "-q", "-o", out)
        self.assertEqual(logged(out)[0][1], ["wheel_l", "wheel_r"])
        path = os.path.join(self.tmp, "mote.yaml")
        with open(path, "w") as f:
            f.write("name: m\nduration: 1\nnodes:\n  - {name: m, model: mote, sensors: {encoders: {}}}\n")
        done = self.run_sanet("validate", path, check=False)
        self.assertEqual(done.returncode, 2)
        self.assertIn("mote.yaml:4", done.stderr)
        self.assertIn("no encoders", done.stderr)


if __name__ == "__main__":
    unittest.main()
