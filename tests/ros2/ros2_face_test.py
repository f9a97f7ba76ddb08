#!/usr/bin/env python3
"""sanet serve --ros2 against an independent DDS client (tests/ros2/ros2_client.c: C on Cyclone
DDS, types from IDL written from ROS 2's definitions):
- the client reads a robot's odom, scan, an IR range, its battery (BatteryState), /tf, /tf_static
  and /clock with ROS 2's names, frames and types, publishes cmd_vel, and sees the robot move accordingly while /clock
  advances; TwistStamped with --ros2-cmd-vel-stamped;
- one owner per robot: a robot a USARSim client claimed does not take cmd_vel (refused, counted);
- bad input: cmd_vel that is not a number, samples of another type under Twist's name, two
  publishers on one cmd_vel: counted in summary.json, said once, never a crash;
- a domain that cannot be used (out of range, ROS_DOMAIN_ID not a number, no interface for DDS)
  and a robot name that is no ROS name are clear errors at start."""
import json
import os
import socket
import subprocess
import sys
import tempfile
import threading
import time
import unittest

from socket_drain import drain

SANET, CLIENT, BAD_CLIENT, SOURCE = sys.argv.pop(1), sys.argv.pop(1), sys.argv.pop(1), sys.argv.pop(1)
DOMAIN = 21  # its own: tests run side by side (ros2_agent has 22; launches take 101 down)

SCENARIO = """name: ros2-face
duration: {duration}
nodes:
  - {{name: r1, model: diffdrive, pose: [0, 0, 0], energy: {{battery_j: 360, voltage: 3, electronics_w: 0.2}}}}
  - {{name: r2, model: omni3, pose: [0, 4, 0]}}
  - {{name: m0, model: mote, pose: [6, 0, 0]}}
"""


class Served:
    def __init__(self, tmp, duration, *extra, path=None):
        if path is None:
            path = os.path.join(tmp, "s.yaml")
            with open(path, "w") as f:
                f.write(SCENARIO.format(duration=duration))
            extra = ("--ros2",) + extra
        else:
            extra = ("--duration", str(duration)) + extra
        self.out = os.path.join(tmp, "out")
        port_file = os.path.join(tmp, "port")
        self.process = subprocess.Popen([SANET, "serve", path, "--port", "0", "--port-file", port_file, "-o", self.out,
                                         "--ros2-domain", str(DOMAIN), *extra],
                                        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        deadline = time.time() + 30
        while not os.path.exists(port_file):
            assert time.time() < deadline and self.process.poll() is None, self.process.communicate()
            time.sleep(0.02)
        with open(port_file) as f:
            self.port = int(f.read())

    def finish(self):
        self.stdout, self.stderr = self.process.communicate(timeout=60)
        assert self.process.returncode == 0, self.stderr
        with open(os.path.join(self.out, "summary.json")) as f:
            return json.load(f)


def client(robot, seconds, vx, omega, mode=""):
    out = subprocess.run([CLIENT, str(DOMAIN), robot, str(seconds), str(vx), str(omega)] + ([mode] if mode else []),
                         capture_output=True, text=True, timeout=seconds + 30)
    assert out.returncode == 0, out.stderr
    seen = dict(line.split(" ", 1) for line in out.stdout.splitlines())
    return {k: (float(v) if k not in ("odom_frame", "odom_child", "scan_frame", "range_frame", "tf_child", "tf_parent") else v)
            for k, v in seen.items()}


class Face(unittest.TestCase):
    def test_a_ros2_client_reads_the_robot_and_drives_it(self):
        with tempfile.TemporaryDirectory() as tmp:
            served = Served(tmp, 9)
            seen = client("r1", 5, 0.3, 0)
            summary = served.finish()
        self.assertEqual(seen["odom_frame"], "r1/odom")
        self.assertEqual(seen["odom_child"], "r1/base_link")
        self.assertEqual(seen["scan_frame"], "r1/laser")
        self.assertEqual((seen["tf_parent"], seen["tf_child"]), ("r1/odom", "r1/base_link"))
        self.assertEqual(seen["static_has_odom"], 1, "world -> r1/odom on /tf_static (transient local)")
        self.assertGreater(seen["odom"], 30, "10 Hz for about 5 s")
        self.assertGreater(seen["scan"], 30)
        self.assertAlmostEqual(seen["first_x"], 0, delta=0.1)
        # 0.3 m/s for most of 5 s; odometry is relative to the start pose
        self.assertGreater(seen["last_x"], 0.8)
        self.assertLess(seen["last_x"], 1.6)
        self.assertAlmostEqual(seen["last_y"], 0, delta=0.1)
        self.assertGreater(seen["clock"], 300, "/clock at 200 Hz")
        # The battery drains at the electronics' 0.2 W, the drive's idle 0.5 W and the drive's work at
        # 0.3 m/s (about 0.4 W: docs/energy.md#motion); no network, no radio.
        self.assertGreater(seen["battery"], 30)
        self.assertAlmostEqual(seen["battery_voltage"], 3, places=5)
        self.assertLess(seen["battery_current"], -0.7 / 3 + 1e-6, "negative while discharging")
        self.assertGreater(seen["battery_current"], -1.7 / 3)
        self.assertAlmostEqual(seen["battery_capacity"], 360 / (3 * 3600), places=6, msg="Ah")
        self.assertEqual(seen["battery_status"], 2, "POWER_SUPPLY_STATUS_DISCHARGING")
        drop = seen["first_percentage"] - seen["last_percentage"]
        self.assertGreater(drop, 0.7 * 5 / 360 - 0.001)
        self.assertLess(drop, 1.7 * 5 / 360 + 0.001)
        self.assertAlmostEqual(seen["last_clock"] - seen["first_clock"], 5, delta=1.0)
        r1 = summary["ros2"]["robots"]["r1"]
        self.assertGreater(r1["cmd_vel_taken"], 100)
        self.assertEqual(r1["cmd_vel_refused_owned"], 0)

    def test_a_robot_stops_when_cmd_vel_goes_quiet(self):
        with tempfile.TemporaryDirectory() as tmp:
            served = Served(tmp, 8)
            client("r1", 1.5, 0.4, 0)  # drives, then stops publishing
            time.sleep(2)
            after = client("r1", 1, 0, 0)  # a still robot reads the same pose throughout
            summary = served.finish()
        self.assertGreater(after["last_x"], 0.2, "it had moved")
        self.assertAlmostEqual(after["last_x"], after["first_x"], delta=0.01, msg="and then stood still")
        self.assertGreaterEqual(summary["ros2"]["robots"]["r1"]["stopped_by_cmd_vel_timeout"], 1)

    def test_a_urdf_robots_description_and_links(self):
        """scenarios/urdf-robot.yaml's robots: little-diff's file on robot_description (latched: a client that
        comes later gets it), its links on /tf_static (the root and little-diff's three fixed
        joints) and its two wheels on /tf as it drives."""
        with tempfile.TemporaryDirectory() as tmp:
            served = Served(tmp, 6, "--ros2", path=os.path.join(SOURCE, "scenarios", "urdf-robot.yaml"))
            time.sleep(1)
            omni = {}  # every robot with a controller needs a driver in a served world: the face drives both
            other = threading.Thread(target=lambda: omni.update(client("omni", 3, 0, 0.5)))
            other.start()
            seen = client("little", 3, 0.2, 0)
            other.join()
            served.finish()
        with open(os.path.join(SOURCE, "scenarios", "robots", "little-diff.urdf"), "rb") as f:
            self.assertEqual(seen["description_bytes"], len(f.read()))
        self.assertEqual(seen["description"], 1)
        self.assertEqual(seen["urdf_static"], 4, "base_link -> root, mast, laser, caster")
        self.assertGreater(seen["urdf_moving"], 2 * 20, "two wheels at 10 Hz for 3 s")
        self.assertEqual(omni["urdf_static"], 1, "base_link -> root: little-omni has no fixed joint")
        self.assertGreater(omni["urdf_moving"], 3 * 20, "three wheels")

    def test_ir_ranges_and_twist_stamped(self):
        with tempfile.TemporaryDirectory() as tmp:
            served = Served(tmp, 7, "--ros2-cmd-vel-stamped")
            seen = client("r2", 3, 0, 0.5, "stamped")
            summary = served.finish()
        self.assertGreater(seen["range"], 15)
        self.assertEqual(seen["range_frame"], "r2/ir_0")
        self.assertEqual(seen["range_type"], 1, "INFRARED")
        self.assertGreater(abs(seen["last_yaw"]), 0.5, "turned at 0.5 rad/s")
        self.assertGreater(summary["ros2"]["robots"]["r2"]["cmd_vel_taken"], 50)

    def test_a_robot_another_client_drives_refuses_cmd_vel(self):
        with tempfile.TemporaryDirectory() as tmp:
            served = Served(tmp, 7)
            usarsim = socket.create_connection(("127.0.0.1", served.port))
            usarsim.sendall(b"INIT {Name r1}\r\n")
            # A client that reads what the server sends keeps its robot (one that stops reading is dropped).
            threading.Thread(target=drain, args=(usarsim,), daemon=True).start()
            time.sleep(0.5)
            seen = client("r1", 3, 0.5, 0)
            usarsim.close()
            summary = served.finish()
        self.assertAlmostEqual(seen["last_x"], 0, delta=0.05, msg="the robot stayed where its client keeps it")
        self.assertGreater(seen["odom"], 10, "its topics still tell what its owner reads")
        r1 = summary["ros2"]["robots"]["r1"]
        self.assertGreater(r1["cmd_vel_refused_owned"], 50)
        self.assertEqual(r1["cmd_vel_taken"], 0)
        self.assertEqual(served.stderr.count("cmd_vel refused"), 1, served.stderr)

    def test_bad_commands_are_counted_and_said_once(self):
        with tempfile.TemporaryDirectory() as tmp:
            served = Served(tmp, 8)
            bad = subprocess.Popen([BAD_CLIENT, str(DOMAIN), "r2", "3"], stdout=subprocess.PIPE, text=True)
            nan = client("r1", 3, 0, 0, "nan")
            bad.communicate(timeout=30)
            two = [subprocess.Popen([CLIENT, str(DOMAIN), "r2", "2", "0.1", "0"], stdout=subprocess.PIPE)
                   for _ in range(2)]
            for p in two:
                p.communicate(timeout=30)
            summary = served.finish()
        self.assertAlmostEqual(nan["last_x"], 0, delta=0.05, msg="a command that is not a number moves nothing")
        r1, r2 = summary["ros2"]["robots"]["r1"], summary["ros2"]["robots"]["r2"]
        self.assertGreater(r1["cmd_vel_not_finite"], 50)
        self.assertGreater(r2["cmd_vel_undecodable"], 50)
        self.assertGreater(r2["cmd_vel_publisher_switches"], 0)
        self.assertGreater(r2["cmd_vel_taken"], 50, "the well-formed ones still drive it")
        self.assertEqual(served.stderr.count("does not decode"), 1, served.stderr)
        self.assertEqual(served.stderr.count("more than one publisher"), 1, served.stderr)

    def test_the_shipped_scenario_turns_the_face_on_with_its_names_and_rates(self):
        shipped = os.path.join(SOURCE, "scenarios", "ros2-robots.yaml")
        with tempfile.TemporaryDirectory() as tmp:
            served = Served(tmp, 6, path=shipped)
            rover = client("rover", 3, 0.2, 0)  # the omni3 'omni' under its namespace, at 20 Hz
            summary = served.finish()
        self.assertEqual(rover["odom_frame"], "rover/odom")
        self.assertEqual(rover["range_frame"], "rover/ir_0")
        self.assertGreater(rover["odom"], 45, "20 Hz for about 3 s")
        self.assertGreater(summary["ros2"]["robots"]["omni"]["cmd_vel_taken"], 50)
        self.assertGreater(rover["last_x"], 0.3, "driven forward in its odom frame")
        with tempfile.TemporaryDirectory() as tmp:
            served = Served(tmp, 4, "--no-ros2", path=shipped)
            silent = client("rover", 2, 0, 0)
            summary = served.finish()
        self.assertEqual(silent["odom"], 0)
        self.assertNotIn("ros2", summary)

    def test_a_domain_out_of_range_is_refused_at_start(self):
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "s.yaml")
            with open(path, "w") as f:
                f.write(SCENARIO.format(duration=1))
            out = subprocess.run([SANET, "serve", path, "--port", "0", "-o", os.path.join(tmp, "o"), "--ros2",
                                  "--ros2-domain", "300"], capture_output=True, text=True, timeout=30)
            self.assertNotEqual(out.returncode, 0)
            self.assertIn("--ros2-domain", out.stderr)
            env = dict(os.environ, ROS_DOMAIN_ID="banana")
            out = subprocess.run([SANET, "serve", path, "--port", "0", "-o", os.path.join(tmp, "o"), "--ros2"],
                                 capture_output=True, text=True, timeout=30, env=env)
            self.assertNotEqual(out.returncode, 0)
            self.assertIn("ROS_DOMAIN_ID: 'banana' is not a DDS domain", out.stderr)
            env = dict(os.environ, CYCLONEDDS_URI="<CycloneDDS><Domain><General><Interfaces>"
                       "<NetworkInterface name=\"nosuch0\"/></Interfaces></General></Domain></CycloneDDS>")
            out = subprocess.run([SANET, "serve", path, "--port", "0", "-o", os.path.join(tmp, "o"), "--ros2"],
                                 capture_output=True, text=True, timeout=30, env=env)
            self.assertNotEqual(out.returncode, 0)
            self.assertIn("cannot join DDS domain 0", out.stderr)
            for interface, says in [("nosuch0", "cannot join DDS domain 0 on interface nosuch0"),
                                    ('lo"/><x', "is not a network interface's name or address")]:
                out = subprocess.run([SANET, "serve", path, "--port", "0", "-o", os.path.join(tmp, "o"), "--ros2",
                                      "--ros2-interface", interface], capture_output=True, text=True, timeout=30)
                self.assertEqual(out.returncode, 2, out.stderr)
                self.assertIn(says, out.stderr)
            with open(path, "w") as f:
                f.write(SCENARIO.format(duration=1).replace("r1", "r-1"))
            out = subprocess.run([SANET, "serve", path, "--port", "0", "-o", os.path.join(tmp, "o"), "--ros2"],
                                 capture_output=True, text=True, timeout=30)
            self.assertNotEqual(out.returncode, 0)
            self.assertIn("robot 'r-1': its name is no ROS name", out.stderr)


if __name__ == "__main__":
    unittest.main(verbosity=2)
