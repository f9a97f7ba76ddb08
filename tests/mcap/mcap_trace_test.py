#!/usr/bin/env python3
"""A run's trace.mcap read by independent tools (tests/mcap/decode_mcap.mjs: npm's @mcap/core,
@foxglove/rosmsg and @foxglove/rosmsg2-serialization): every message of every channel decodes from
the schemas in the file and writes back to the same bytes; log time = publish time = the message's
stamp; ground truth equals trajectories.csv; the topics with a CSV twin have its rows; the frames
compose (world -> R/odom -> R/base_link is the true pose); the readings are the run's; batteries'
BatteryState follows from energy.csv, with deaths and revivals among the events; and the
fingerprint is the same with and without the trace."""
import csv
import json
import math
import os
import shutil
import re
import subprocess
import sys
import tempfile
import unittest

SANET, MODULES, SOURCE = sys.argv[1:4]
del sys.argv[1:4]
DECODER = os.path.join(SOURCE, "tests", "mcap", "decode_mcap.mjs")

# A robot that steers by its odometry and looks with a laser.
ODOMETRY = """name: odometry
duration: 8
nodes:
  - name: r-1
    model: omni3
    pose: [0, 0, 0.3]
    sensors: {laser: {}}
    controller: {name: waypoint, params: {waypoints: [[2, 1]], speed: 0.5, localization: odometry}}
  - {name: m, model: mote, pose: [3, 3, 0]}
"""


def run(scenario, folder, *sets):
    done = subprocess.run([SANET, "run", scenario, "-o", folder, *sets], capture_output=True, text=True, timeout=300)
    if done.returncode != 0:
        raise AssertionError(done.stderr)
    with open(os.path.join(folder, "summary.json")) as f:
        return json.load(f)["fingerprint"]


def decode(path):
    done = subprocess.run(["node", DECODER, MODULES, path], capture_output=True, text=True, timeout=300)
    if done.returncode != 0:
        raise AssertionError(done.stderr)
    return json.loads(done.stdout)


def rows(folder, name):
    with open(os.path.join(folder, name)) as f:
        return list(csv.DictReader(f))


def yaw(q):
    return 2 * math.atan2(q["z"], q["w"])


class HelpRequest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.out = os.path.join(cls.tmp.name, "traced")
        scenario = os.path.join(SOURCE, "scenarios", "help-request.yaml")
        cls.fingerprint = run(scenario, cls.out, "--set", "outputs.trace=true")
        cls.untraced = run(scenario, os.path.join(cls.tmp.name, "plain"), "--set", "outputs.trace=false")
        cls.log = decode(os.path.join(cls.out, "trace.mcap"))

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_the_trace_does_not_change_the_run(self):
        self.assertEqual(self.fingerprint, self.untraced)
        self.assertFalse(os.path.exists(os.path.join(self.tmp.name, "plain", "trace.mcap")), "the same switch")

    def test_every_message_decodes_as_ros2_cdr_at_its_own_time(self):
        log = self.log
        self.assertEqual(log["profile"], "ros2")
        self.assertEqual(log["errorCount"], 0, log["errors"])
        self.assertEqual(log["stampMismatches"], [])
        self.assertEqual(log["backwards"], 0, "the file is in time order, for streaming readers")
        self.assertEqual(log["statistics"], sum(log["counts"].values()))
        self.assertGreater(log["chunks"], 5, "chunked, with an index per chunk")
        self.assertEqual(log["compression"], ["zstd"])
        for topic, c in log["channels"].items():
            self.assertEqual((c["schemaEncoding"], c["messageEncoding"]), ("ros2msg", "cdr"), topic)
        types = {t: c["schema"] for t, c in log["channels"].items()}
        self.assertEqual(types["/robot/ground_truth"], "nav_msgs/msg/Odometry")
        self.assertEqual(types["/robot/ir_0"], "sensor_msgs/msg/Range")
        self.assertEqual(types["/tf"], "tf2_msgs/msg/TFMessage")
        self.assertEqual(types["/world"], "visualization_msgs/msg/MarkerArray")
        self.assertEqual(types["/radio/links"], "visualization_msgs/msg/MarkerArray")
        self.assertEqual(types["/rosout"], "rcl_interfaces/msg/Log")

    def test_ground_truth_is_trajectories_csv(self):
        truth = self.log["groundTruth"]
        by_node = {}
        for r in rows(self.out, "trajectories.csv"):
            by_node.setdefault(r["node"], []).append(r)
        self.assertEqual(set(truth), set(by_node))
        for node, csv_rows in by_node.items():
            self.assertEqual(len(truth[node]), len(csv_rows), node)
            for (t, x, y, theta), r in zip(truth[node], csv_rows):
                self.assertAlmostEqual(t, float(r["time"]), places=6)
                self.assertAlmostEqual(x, float(r["x"]), places=4)
                self.assertAlmostEqual(y, float(r["y"]), places=4)
                self.assertAlmostEqual(math.remainder(theta - float(r["theta"]), 2 * math.pi), 0, places=4)

    def test_topics_with_a_csv_twin_have_its_rows(self):
        counts = self.log["counts"]
        for topic, name in [("/transitions", "transitions.csv"), ("/metrics", "metrics.csv"),
                            ("/messages", "messages.csv"), ("/rosout", "log.csv")]:
            self.assertEqual(counts.get(topic, 0), len(rows(self.out, name)), topic)
            self.assertGreater(counts.get(topic, 0), 0, topic)
        first = self.log["first"]["/transitions"]
        t = rows(self.out, "transitions.csv")[0]
        self.assertEqual((first["node"], first["from_state"], first["to_state"], first["why"]),
                         (t["node"], t["from"], t["to"], t["why"]))

    def test_the_frames_compose_to_the_true_pose(self):
        static = {(tf["header"]["frame_id"], tf["child_frame_id"]): tf["transform"]
                  for tf in self.log["first"]["/tf_static"]["transforms"]}
        start = static[("world", "robot/odom")]
        self.assertIn(("robot/base_link", "robot/ir_0"), static, "sensor mounts")
        self.assertNotIn(("world", "m0"), static, "motes are in /tf, since something may push them")
        self.assertIn("world m0", self.log["tfPairs"])
        self.assertIn("robot/odom robot/base_link", self.log["tfPairs"])
        odom_to_base = self.log["last"]["/tf"]["transforms"][0]["transform"]
        s, o = start["translation"], odom_to_base["translation"]
        a = yaw(start["rotation"])
        x = s["x"] + o["x"] * math.cos(a) - o["y"] * math.sin(a)
        y = s["y"] + o["x"] * math.sin(a) + o["y"] * math.cos(a)
        last = rows(self.out, "trajectories.csv")
        final = [r for r in last if r["node"] == "robot"][-1]
        self.assertAlmostEqual(x, float(final["x"]), places=3)
        self.assertAlmostEqual(y, float(final["y"]), places=3)

    def test_the_world_and_the_radio_are_drawn(self):
        markers = self.log["first"]["/world"]["markers"]
        spaces = [m["ns"] for m in markers]
        self.assertGreater(spaces.count("obstacles"), 0)
        self.assertEqual(spaces.count("motes"), 25, "every mote of the scenario")
        body = next(m for m in markers if m["ns"] == "bodies")
        self.assertEqual((body["header"]["frame_id"], body["frame_locked"]), ("robot/base_link", True))
        self.assertGreater(self.log["counts"]["/radio/links"], 100)
        lines = self.log["first"]["/radio/links"]["markers"][0]
        self.assertEqual(lines["type"], 5, "LINE_LIST")
        self.assertGreater(len(lines["points"]), 0)
        self.assertEqual(len(lines["points"]) % 2, 0)
        self.assertGreater(self.log["counts"]["/radio/frames"], 1000)
        self.assertGreater(self.log["counts"]["/routes"], 0)

    def test_ir_ranges_are_the_readings_the_controller_took(self):
        counts = self.log["counts"]
        self.assertTrue(all(counts[f"/robot/ir_{i}"] == counts["/robot/ir_0"] for i in range(6)))
        self.assertGreater(counts["/robot/ir_0"], 1000)
        self.assertEqual(self.log["first"]["/robot/ir_3"]["header"]["frame_id"], "robot/ir_3")


class RobotDescription(unittest.TestCase):
    def test_a_urdf_robots_description_is_the_file_and_its_links_are_in_tf(self):
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "urdf")
            run(os.path.join(SOURCE, "scenarios", "urdf-robot.yaml"), out, "--set", "outputs.trace=true",
                "--duration", "3")
            log = decode(os.path.join(out, "trace.mcap"))
            out_rows = [r for r in rows(out, "trajectories.csv") if r["node"] == "little"]
        self.assertEqual(log["errorCount"], 0, log["errors"])
        self.assertEqual(log["channels"]["/little/robot_description"]["schema"], "std_msgs/msg/String")
        self.assertEqual(log["counts"]["/little/robot_description"], 1, "latched: once, at the start")
        with open(os.path.join(SOURCE, "scenarios", "robots", "little-diff.urdf")) as f:
            self.assertEqual(log["first"]["/little/robot_description"]["data"], f.read())
        self.assertNotIn("/base/robot_description", log["channels"], "a mote from no URDF has none")
        self.tf_tree_holds_the_links(log)
        self.the_wheels_turn_as_the_robot_drives(log, out_rows)

    def tf_tree_holds_the_links(self, log):
        """little-diff.urdf by hand: base_link's origin is the axle's middle, a wheel's radius (5 cm)
        above the ground; the mast 0.05 m ahead and 0.09 m up, the laser 0.12 m above the mast."""
        statics = {(tf["header"]["frame_id"], tf["child_frame_id"]): tf["transform"]
                   for tf in log["first"]["/tf_static"]["transforms"]}
        expected = {("little/base_link", "little/urdf/base_link"): (0, 0, 0.05),
                    ("little/urdf/base_link", "little/urdf/mast"): (0.05, 0, 0.09),
                    ("little/urdf/mast", "little/urdf/laser"): (0, 0, 0.12),
                    ("little/urdf/base_link", "little/urdf/caster"): (-0.17, 0, -0.03)}
        for pair, xyz in expected.items():
            self.assertIn(pair, statics)
            t = statics[pair]["translation"]
            self.assertEqual([round(t[k], 6) for k in "xyz"], list(xyz), pair)
        wheels = [p for p in log["tfPairs"] if p.startswith("little/urdf/base_link little/urdf/")]
        self.assertEqual(wheels, ["little/urdf/base_link little/urdf/left_wheel",
                                  "little/urdf/base_link little/urdf/right_wheel"])
        self.assertNotIn(("little/urdf/base_link", "little/urdf/left_wheel"), statics, "a wheel moves: in /tf")

    def the_wheels_turn_as_the_robot_drives(self, log, trajectory):
        # Each wheel's joint turns it -90 deg about x (its axis then along +y, left).
        turned = {wheel: turn_about_joint(log["urdfTracks"]["little/urdf/" + wheel], (-math.pi / 2, 0, 0))
                  for wheel in ("left_wheel", "right_wheel")}
        path = sum(math.dist((float(a["x"]), float(a["y"])), (float(b["x"]), float(b["y"])))
                   for a, b in zip(trajectory, trajectory[1:]))
        print(f"\npath {path:.3f} m, wheels turned {turned}", file=sys.stderr)
        self.assertGreater(path, 0.3)
        self.assertAlmostEqual((turned["left_wheel"] + turned["right_wheel"]) / 2 * 0.05, path, delta=0.05 * path)

    def test_an_omni3s_wheels_roll_without_slipping_as_it_turns(self):
        """scenarios/robots/little-omni.urdf turning in place: a wheel 0.12 m out whose rim does not
        slip turns by -(the body's turn) x 0.12 / 0.035 about its own (outward) axis."""
        with tempfile.TemporaryDirectory() as tmp:
            shutil.copy(os.path.join(SOURCE, "scenarios", "robots", "little-omni.urdf"), tmp)
            scenario = os.path.join(tmp, "omni.yaml")
            with open(scenario, "w") as f:
                f.write("name: omni\nduration: 3\nworld: {size: [10, 10]}\noutputs: {trajectory_interval: 0.05}\n"
                        "nodes:\n  - name: o\n    model: omni3\n    pose: [5, 5, 0]\n    body:\n"
                        "      urdf: little-omni.urdf\n      wheels: [wheel_0_joint, wheel_1_joint, wheel_2_joint]\n"
                        "    controller: {name: constant_velocity, params: {wheel_speeds: [2, 2, 2], start: 0.5}}\n")
            out = os.path.join(tmp, "out")
            run(scenario, out)
            log = decode(os.path.join(out, "trace.mcap"))
            trajectory = [r for r in rows(out, "trajectories.csv") if r["node"] == "o"]
        thetas = [float(r["theta"]) for r in trajectory]
        body = sum(math.remainder(b - a, 2 * math.pi) for a, b in zip(thetas, thetas[1:]))
        wheel = turn_about_joint(log["urdfTracks"]["o/urdf/wheel_0"], (0, math.pi / 2, 0))
        self.assertGreater(abs(body), 1.0)
        self.assertAlmostEqual(wheel, -body * 0.12 / 0.035, delta=0.05 * abs(body) * 0.12 / 0.035)


def quaternion(roll, pitch, yaw):
    """(x, y, z, w) of URDF's rpy: about fixed x, then y, then z."""
    cr, sr, cp, sp, cy, sy = (f(a / 2) for a in (roll, pitch, yaw) for f in (math.cos, math.sin))
    return (sr * cp * cy - cr * sp * sy, cr * sp * cy + sr * cp * sy, cr * cp * sy - sr * sp * cy,
            cr * cp * cy + sr * sp * sy)


def turn_about_joint(track, rpy):
    """A wheel's total turn about its joint's axis (z of the joint's frame), unwrapped, from its
    /tf rotations over time and the joint's origin rpy."""
    ox, oy, oz, ow = quaternion(*rpy)
    angles = []
    for _, x, y, z, w in track:
        # (origin^-1 * q): its z and w parts give the angle about the joint's z.
        qz = ow * z - ox * y + oy * x - oz * w
        qw = ow * w + ox * x + oy * y + oz * z
        angles.append(2 * math.atan2(qz, qw))
    return sum(math.remainder(b - a, 2 * math.pi) for a, b in zip(angles, angles[1:]))


class FormationLayout(unittest.TestCase):
    """The Foxglove layout shipped in docs names only topics, nodes and metrics the formation's log has."""

    def test_the_layout_fits_the_formations_log(self):
        with open(os.path.join(SOURCE, "docs", "foxglove", "formation.json")) as f:
            layout = json.load(f)
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "out")
            run(os.path.join(SOURCE, "scenarios", "formation.yaml"), out, "--duration", "20")
            log = decode(os.path.join(out, "trace.mcap"))
            metrics = {(r["node"], r["name"]) for r in rows(out, "metrics.csv")}
        self.assertEqual(log["errorCount"], 0, log["errors"])
        named = set()
        for panel, config in layout["configById"].items():
            named |= set(config.get("topics", {}))
            if "topicPath" in config:
                named.add(config["topicPath"])
            for path in config.get("paths", []):
                topic = re.match(r"(/[^{.]+)", path["value"])[1]
                named.add(topic)
                node, name = re.findall(r'node=="([^"]+)"', path["value"]), re.findall(r'name=="([^"]+)"', path["value"])
                self.assertIn((node[0], name[0]), metrics, path["value"])
        self.assertGreater(len(named), 5)
        self.assertFalse(named - set(log["channels"]), "topics the log does not have")
        panels = re.findall(r'"([A-Za-z0-9 ]+![^"]+)"', json.dumps(layout["layout"]))
        self.assertEqual(set(panels), set(layout["configById"]), "every panel placed")


class Readings(unittest.TestCase):
    def test_odometry_and_scans_are_logged_as_read(self):
        with tempfile.TemporaryDirectory() as tmp:
            scenario = os.path.join(tmp, "odometry.yaml")
            with open(scenario, "w") as f:
                f.write(ODOMETRY)
            out = os.path.join(tmp, "out")
            run(scenario, out, "--set", "outputs.trace=true")
            log = decode(os.path.join(out, "trace.mcap"))
            self.assertEqual(log["errorCount"], 0, log["errors"])
            counts = log["counts"]
            # A node's name as a ROS name token in its topics (ROS 2 refuses "-"); frames keep the name.
            self.assertNotIn("/r-1/odom", counts)
            # The controller reads odometry, laser and IR at each of its steps until it arrives, once each.
            self.assertGreaterEqual(counts["/r_1/odom"], 20)
            self.assertLessEqual(abs(counts["/r_1/scan"] - counts["/r_1/odom"]), 1, "each step reads both")
            odom = log["last"]["/r_1/odom"]
            self.assertEqual((odom["header"]["frame_id"], odom["child_frame_id"]), ("r-1/odom", "r-1/base_link"))
            final = [r for r in rows(out, "trajectories.csv") if r["node"] == "r-1"][-1]
            # Odometry starts at the start pose and drifts little over 2 m.
            p = odom["pose"]["pose"]["position"]
            start = 0.3
            x = p["x"] * math.cos(start) - p["y"] * math.sin(start)
            y = p["x"] * math.sin(start) + p["y"] * math.cos(start)
            self.assertLess(math.hypot(x - float(final["x"]), y - float(final["y"])), 0.3)
            scan = log["first"]["/r_1/scan"]
            self.assertEqual(scan["header"]["frame_id"], "r-1/laser")
            self.assertGreater(len(scan["ranges"]), 10)


# Named sensor instances beside their kinds' own, and the sonar, read by a Python controller.
NAMED = """name: named
duration: 1
world:
  obstacles:
    - {box: {center: [2.2, 0], size: [0.2, 2, 1]}}
nodes:
  - name: r
    model: diffdrive
    pose: [0, 0, 0]
    sensors:
      laser_rear: {kind: laser, direction: 3.141592653589793, fov: 1.5, beams: 31, mount_x: -0.2}
      ir_low: {kind: ir, count: 4}
      sonar: {}
    controller: {python: "reader:Reader", rate: 5}
"""
READER = """class Reader:
    def __init__(self, params):
        pass

    def control_step(self, node):
        for name in ("laser", "laser_rear", "ir_low", "sonar"):
            node.sensor(name)
"""


class NamedInstances(unittest.TestCase):
    def test_each_instance_has_its_topics_and_frames(self):
        with tempfile.TemporaryDirectory() as tmp:
            for name, text in (("named.yaml", NAMED), ("reader.py", READER)):
                with open(os.path.join(tmp, name), "w") as f:
                    f.write(text)
            out = os.path.join(tmp, "out")
            run(os.path.join(tmp, "named.yaml"), out, "--set", "outputs.trace=true")
            log = decode(os.path.join(out, "trace.mcap"))
            self.assertEqual(log["errorCount"], 0, log["errors"])
            counts = log["counts"]
            for topic in ("/r/scan", "/r/laser_rear", "/r/ir_low_0", "/r/ir_low_3", "/r/sonar"):
                self.assertEqual(counts.get(topic), 6, f"{topic}: one message per step, t = 0 to 1 s at 5 Hz")
            self.assertNotIn("/r/ir_low_4", counts)
            rear = log["first"]["/r/laser_rear"]
            self.assertEqual((rear["header"]["frame_id"], len(rear["ranges"])), ("r/laser_rear", 31))
            self.assertEqual(log["first"]["/r/ir_low_2"]["header"]["frame_id"], "r/ir_low_2")
            sonar = log["first"]["/r/sonar"]
            self.assertEqual((sonar["header"]["frame_id"], sonar["radiation_type"]), ("r/sonar", 0), "ULTRASOUND")
            self.assertAlmostEqual(sonar["field_of_view"], 0.5, places=5)
            self.assertAlmostEqual(sonar["range"], 2.1 - 0.19, delta=0.05, msg="the box face, from the body edge")
            mounts = {tf["child_frame_id"]: tf["transform"]["translation"]
                      for tf in log["last"]["/tf_static"]["transforms"]}
            self.assertAlmostEqual(mounts["r/laser_rear"]["x"], -0.2)
            turned = {tf["child_frame_id"]: tf["transform"]["rotation"] for tf in log["last"]["/tf_static"]["transforms"]}
            self.assertAlmostEqual(abs(turned["r/laser_rear"]["z"]), 1.0, msg="the rear laser's frame is turned by pi")
            self.assertAlmostEqual(rear["angle_min"], -0.75, places=5, msg="its angles in its own frame")
            self.assertIn("r/laser", mounts)
            self.assertIn("r/ir_low_3", mounts)
            self.assertAlmostEqual(mounts["r/sonar"]["x"], 0.19, msg="at the body edge, body_width / 2")


class Batteries(unittest.TestCase):
    def test_battery_state_follows_from_the_battery(self):
        with tempfile.TemporaryDirectory() as tmp:
            scenario = os.path.join(SOURCE, "scenarios", "sensor-network-energy.yaml")
            run(scenario, tmp, "--set", "duration=420", "--set", "outputs.trace=true")
            log = decode(os.path.join(tmp, "trace.mcap"))
            energy = rows(tmp, "energy.csv")
        self.assertEqual(log["errorCount"], 0, log["errors"])
        self.assertEqual(log["channels"]["/m7/battery_state"]["schema"], "sensor_msgs/msg/BatteryState")
        states = {(node, round(s["t"], 6)): s for node, series in log["batteries"].items() for s in series}
        self.assertEqual(len(states), len(energy), "a message for every row of energy.csv")
        capacity = {"reporter": 26640.0}  # a lithium-ion cell: its voltage falls along its curve
        for row in energy:
            s = states[(row["node"], round(float(row["time"]), 6))]
            battery_j = capacity.get(row["node"], 300.0)
            remaining, power, volts = float(row["remaining_j"]), float(row["power_w"]), s["voltage"]
            if row["node"] == "reporter":
                self.assertTrue(3.3 < volts < 4.3, volts)
            else:
                self.assertAlmostEqual(volts, 3.0, places=5)
            self.assertAlmostEqual(s["percentage"], remaining / battery_j, places=5)
            # float32 in the message: six significant digits
            self.assertTrue(math.isclose(s["charge"], remaining / (volts * 3600), rel_tol=1e-6, abs_tol=1e-9), row)
            self.assertTrue(math.isclose(s["capacity"], battery_j / (volts * 3600), rel_tol=1e-6), row)
            self.assertAlmostEqual(s["current"], -power / volts, places=5)
            self.assertIsNone(s["temperature"], "NaN, unmeasured (JSON writes NaN as null)")
            self.assertTrue(s["present"])
            self.assertEqual(s["header"]["frame_id"], row["node"], "a mote's own frame (a robot's: R/base_link)")
            # DISCHARGING while it draws, NOT_CHARGING once dead, FULL at the start.
            expected = 4 if remaining >= battery_j else 2 if power > 0 else 3
            self.assertEqual(s["power_supply_status"], expected, row)
        kinds = [(e["node"], e["kind"]) for e in log["events"]]
        self.assertIn(("old0", "death"), kinds)
        self.assertIn(("m7", "revival"), kinds)
        self.assertLess(kinds.index(("m7", "death")), kinds.index(("m7", "revival")))


if __name__ == "__main__":
    unittest.main(verbosity=2)

