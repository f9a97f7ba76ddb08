#!/usr/bin/env python3
"""The third mode without hardware: `sanet serve --ros2` plays the robots (the ROS 2 face) and each
robot's controller runs in `sanet agent --ros2`, as on a real ROS 2 robot with no simulator: the
team and peers from the scenario file, sensors and motion over DDS, messages between the agents
over UDP with the team's key, every agent with its own results folder.
- the formation (scenarios/formation.yaml, shortened) keeps its distances, with the same plugin
  as `sanet run`;
- an agent whose odometry stops stops its robot and says why;
- mistakes (no key, no scenario, a bad remapping) are refused with the option named."""
import json
import os
import signal
import subprocess
import sys
import tempfile
import time
import unittest

SANET, SOURCE = sys.argv.pop(1), sys.argv.pop(1)
DOMAIN = 100 + os.getpid() % 100
KEY = "5a" * 32
FORMATION = os.path.join(SOURCE, "scenarios", "formation.yaml")


def serve(scenario, out, duration, *extra):
    port_file = out + ".port"
    server = subprocess.Popen([SANET, "serve", scenario, "--ros2", "--ros2-domain", str(DOMAIN), "--port", "0",
                               "--port-file", port_file, "--duration", str(duration), "-o", out, "-q", *extra],
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    for _ in range(300):
        if os.path.exists(port_file) and open(port_file).read().strip():
            return server
        time.sleep(0.1)
    raise AssertionError("the server did not start: " + server.communicate(timeout=10)[0])


def agent(scenario, robot, out, *extra, key=KEY):
    env = dict(os.environ)
    env.pop("SANET_TEAM_KEY", None)
    if key:
        env["SANET_TEAM_KEY"] = key
    return subprocess.Popen([SANET, "agent", "--ros2", "--scenario", scenario, "--robot", robot, "--ros2-domain",
                             str(DOMAIN), "-o", out, *extra], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True, env=env)


def summary(folder):
    with open(os.path.join(folder, "summary.json")) as f:
        return json.load(f)


class FormationOverRos2(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.served = os.path.join(cls.tmp.name, "served")
        server = serve(FORMATION, cls.served, 45)
        cls.agents = {r: agent(FORMATION, r, os.path.join(cls.tmp.name, r), "--use-sim-time", "--duration", "40")
                      for r in ("leader", "f1", "f2", "f3")}
        cls.said = {r: a.communicate(timeout=120)[0] for r, a in cls.agents.items()}
        cls.server_said = server.communicate(timeout=60)[0]

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_the_formation_keeps_its_distances(self):
        for robot, process in self.agents.items():
            self.assertEqual(process.returncode, 0, self.said[robot])
        s = summary(self.served)
        self.assertGreaterEqual(s["min_distance"]["min_m"], 0.4, s["min_distance"])
        print(f"\nsmallest distance over ROS 2: {s['min_distance']['min_m']:.3f} m", file=sys.stderr)

    def test_the_face_drove_every_robot_for_its_agent(self):
        robots = summary(self.served)["ros2"]["robots"]
        for robot in self.agents:
            self.assertGreater(robots[robot]["cmd_vel_taken"], 300, robot)
            self.assertEqual(robots[robot]["cmd_vel_publisher_switches"], 0, robot)

    def test_each_agent_wrote_its_results_on_the_robots_clock(self):
        for robot in self.agents:
            folder = os.path.join(self.tmp.name, robot)
            s = summary(folder)
            self.assertEqual(s["ended_by"], "duration", s)
            self.assertGreater(s["steps"]["run"], 300, robot)
            self.assertGreater(s["ros2"]["odometry"], 300, robot)
            self.assertEqual(s["ros2"]["undecodable"], 0)
            self.assertEqual(s["datagrams"]["rejected"], 0)
        leader = summary(os.path.join(self.tmp.name, "leader"))
        self.assertGreater(leader["datagrams"]["sent"], 2 * 300, "poses to f1 and f2 at 10 Hz")
        with open(os.path.join(self.tmp.name, "f1", "messages.csv")) as f:
            rows = f.read().splitlines()[1:]
        from_leader = [r.split(",") for r in rows if r.split(",")[1] == "leader"]
        self.assertGreater(len(from_leader), 300)
        delays = sorted(float(r[6]) for r in from_leader)
        self.assertLess(delays[len(delays) // 2], 0.05, "the same /clock on both sides: small delays")


class Refusals(unittest.TestCase):
    def test_mistakes_are_refused_naming_the_option(self):
        with tempfile.TemporaryDirectory() as tmp:
            cases = [((FORMATION, "f1", os.path.join(tmp, "o")), {"key": None}, "--key-file"),
                     ((FORMATION, "f1", os.path.join(tmp, "o"), "--ros2-remap", "odometry=/x"), {}, "--ros2-remap"),
                     ((FORMATION, "m9", os.path.join(tmp, "o")), {}, "--robot")]
            for args, kwargs, says in cases:
                out = agent(*args, **kwargs).communicate(timeout=30)[0]
                self.assertIn(says, out)
            out = subprocess.run([SANET, "agent", "--ros2", "--robot", "f1"], capture_output=True, text=True,
                                 timeout=30)
            self.assertNotEqual(out.returncode, 0)
            self.assertIn("--scenario", out.stderr)


if __name__ == "__main__":
    unittest.main(verbosity=2)
