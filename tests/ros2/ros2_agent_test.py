#!/usr/bin/env python3
"""The third mode without hardware: `sanet serve --ros2` plays the robots (the ROS 2 face) and each
robot's controller runs in `sanet agent --ros2`, as on a real ROS 2 robot with no simulator: the
team and peers from the scenario file, sensors and motion over DDS, messages between the agents
over UDP with the team's key, every agent with its own results folder.
- the formation (scenarios/formation.yaml, shortened) keeps its distances, with the same plugin
  as `sanet run`;
- an agent whose odometry stops, or whose controller fails, stops its robot (a zero cmd_vel) and
  says why; its Network() is the kernel's; all against a robot's
  driver written from ROS 2's definitions (ros2_driver.c), as is the remapping test: topics under
  other names, read reliable, and cmd_vel as TwistStamped;
- `sanet merge` puts a team's folders on one time line: on /clock as they are, on computers'
  clocks each moved from its time 0 (agents started 1.5 s apart);
- mistakes (no key, no scenario, a bad remapping, folders of no team) are refused, named."""
import csv
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import unittest

SANET, DRIVER, LIBRARY, SOURCE = sys.argv.pop(1), sys.argv.pop(1), os.path.abspath(sys.argv.pop(1)), sys.argv.pop(1)
DOMAIN = 22  # its own: tests run side by side (ros2_face has 21; launches take 101 down)
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
        # Ports of its own: the formation's loop.udp_port is 47000, which launches on loopback take.
        cls.agents = {r: agent(FORMATION, r, os.path.join(cls.tmp.name, r), "--use-sim-time", "--duration", "40",
                               "--udp-base", "52650")
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

    def test_merge_takes_one_clock_as_it_is_and_counts_every_link(self):
        folders = [os.path.join(self.tmp.name, r) for r in ("leader", "f1", "f2", "f3")]
        team = os.path.join(self.tmp.name, "team")
        done = merge(team, *folders)
        self.assertEqual(done.returncode, 0, done.stderr)
        s = summary(team)
        self.assertEqual(s["clocks"]["moved_by_s"], {"leader": 0, "f1": 0, "f2": 0, "f3": 0})
        links = {(r["from"], r["to"]): r for r in csv_rows(os.path.join(team, "links.csv"))}
        self.assertEqual(set(links), {("leader", "f1"), ("leader", "f2"), ("f1", "f3")})
        for link in links.values():
            self.assertGreater(int(link["sent"]), 300)
            self.assertGreaterEqual(int(link["received"]), int(link["sent"]) - 5, link)
        received = csv_rows(os.path.join(team, "messages.csv"))
        self.assertEqual(len(received), s["messages"]["received"])
        each = sum(len(csv_rows(os.path.join(f, "messages.csv"))) for f in folders)
        self.assertEqual(len(received), each, "every agent's messages, none lost or doubled")
        times = [float(r["time_received"]) for r in received]
        self.assertEqual(times, sorted(times))


def merge(out, *folders):
    return subprocess.run([SANET, "merge", *folders, "-o", out], capture_output=True, text=True, timeout=60)


def csv_rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


ONE_ROBOT = """name: one
duration: 60
world: {size: [20, 20]}
loop: {udp_port: 52630}  # away from launches' loopback ports (47000 up)
nodes:
  - name: r1
    model: diffdrive
    pose: [0, 0, 0]
    controller: {name: constant_velocity, rate: 10, params: {vx: 0.2}}
"""


def driver(odom, cmd_vel, kind, seconds, *silent):
    return subprocess.Popen([DRIVER, str(DOMAIN), odom, cmd_vel, kind, str(seconds), *map(str, silent)],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)


def driven(said):
    """The driver's commands as (time, vx) and its last values."""
    commands = [(float(w[1]), float(w[2])) for w in (line.split() for line in said.splitlines()) if w[0] == "cmd_vel"]
    last = dict(line.split() for line in said.splitlines() if line.split()[0] in ("x", "y", "yaw", "commands"))
    return commands, {k: float(v) for k, v in last.items()}


def written(tmp, name, text):
    path = os.path.join(tmp, name)
    with open(path, "w") as f:
        f.write(text)
    return path


def one_robot(tmp):
    return written(tmp, "one.yaml", ONE_ROBOT)


class Safety(unittest.TestCase):
    def test_an_agent_whose_odometry_stops_stops_its_robot_and_says_why(self):
        with tempfile.TemporaryDirectory() as tmp:
            robot = driver("/r1/odom", "/r1/cmd_vel", "twist", 12, 4, 7)  # the driver hangs from 4 s to 7 s
            controller = agent(one_robot(tmp), "r1", os.path.join(tmp, "r1"), "--duration", "9")
            said = controller.communicate(timeout=60)[0]
            commands, _ = driven(robot.communicate(timeout=60)[0])
            self.assertEqual(controller.returncode, 0, said)
            self.assertIn("no odometry for 0.5 s: the robot is stopped", said)
            # Commands read in one batch share a time: order by index, not by time.
            stop = next(i for i, (t, vx) in enumerate(commands) if t > 4 and vx == 0)
            self.assertLess(commands[stop][0], 4 + 0.5 + 0.3, "stopped within odom_timeout (and a step) of the last odometry")
            while_silent = [vx for t, vx in commands[stop:] if t < 7]
            self.assertEqual(set(while_silent), {0}, f"no motion while odometry is missing: {commands}")
            self.assertTrue(any(vx == 0.2 for t, vx in commands if t < 4), "it drove before")
            self.assertTrue(any(vx == 0.2 for t, vx in commands if 7 < t < 8), "and drives again once odometry is back")
            self.assertEqual(commands[-1][1], 0, "and stops the robot at its end")
            log = csv_rows(os.path.join(tmp, "r1", "log.csv"))
            self.assertIn("no odometry for 0.5 s: the robot is stopped", [r["text"] for r in log])
            self.assertIn("odometry is back: the controller drives again", [r["text"] for r in log])
            s = summary(os.path.join(tmp, "r1"))
            self.assertEqual(s["ros2"]["odometry_stops"], 1)
            self.assertGreater(s["steps"]["missed"], 20, "no control step while odometry was missing (2.5 s at 10 Hz)")


def one_robot_with(tmp, controller):
    return written(tmp, "one.yaml", ONE_ROBOT.replace(
        "{name: constant_velocity, rate: 10, params: {vx: 0.2}}", controller))


class Failure(unittest.TestCase):
    def test_a_controller_that_fails_stops_its_robot_and_says_why(self):
        with tempfile.TemporaryDirectory() as tmp:
            scenario = one_robot_with(tmp, f"{{name: crash_after, library: {LIBRARY}, params: {{after: 2, how: throw}}}}")
            robot = driver("/r1/odom", "/r1/cmd_vel", "twist", 6)
            controller = agent(scenario, "r1", os.path.join(tmp, "r1"))
            said = controller.communicate(timeout=60)[0]
            commands, _ = driven(robot.communicate(timeout=60)[0])
            self.assertEqual(controller.returncode, 1, said)
            self.assertIn("controller failed", said)
            self.assertIn("crash_after: thrown at 2", said)
            self.assertTrue(any(vx == 0.2 for _, vx in commands), "it drove until it failed")
            self.assertEqual(commands[-1][1], 0, "then the robot was stopped")
            self.assertIn("controller failed", summary(os.path.join(tmp, "r1"))["ended_by"])


class NetworkView(unittest.TestCase):
    def test_on_a_ros2_robot_network_is_the_kernels(self):
        with tempfile.TemporaryDirectory() as tmp:
            scenario = one_robot_with(tmp, f"{{name: network_probe, library: {LIBRARY}, params: {{towards: r1}}}}")
            robot = driver("/r1/odom", "/r1/cmd_vel", "twist", 5)
            controller = agent(scenario, "r1", os.path.join(tmp, "r1"), "--duration", "2")
            said = controller.communicate(timeout=60)[0]
            robot.communicate(timeout=60)
            self.assertEqual(controller.returncode, 0, said)
            views = {r["text"].strip() for r in csv_rows(os.path.join(tmp, "r1", "log.csv"))}
            self.assertEqual(views, {"net kernel routes neighbours"}, "docs/controllers.md: loopback, empty tables")


class WhatTheAgentSays(unittest.TestCase):
    def test_a_robot_that_never_comes_ends_the_agent_at_the_duration(self):
        with tempfile.TemporaryDirectory() as tmp:
            done = agent(one_robot(tmp), "r1", os.path.join(tmp, "r1"), "--duration", "2")
            said = done.communicate(timeout=60)[0]
            self.assertEqual(done.returncode, 3, said)
            self.assertIn("the robot never came: no odometry on /r1/odom before 2", said)
            self.assertIn("the robot never came", summary(os.path.join(tmp, "r1"))["ended_by"])

    def test_silent_sensors_and_a_cmd_vel_no_one_takes_are_warned(self):
        with tempfile.TemporaryDirectory() as tmp:
            scenario = written(tmp, "omni.yaml", ONE_ROBOT.replace("model: diffdrive", "model: omni3"))
            robot = driver("/r1/odom", "/r1/cmd_vel", "twist", 8)  # a driver on Twist, and no IR topics
            controller = agent(scenario, "r1", os.path.join(tmp, "r1"), "--duration", "5", "--ros2-cmd-vel-stamped")
            said = controller.communicate(timeout=60)[0]
            _, last = driven(robot.communicate(timeout=60)[0])
            self.assertEqual(controller.returncode, 0, said)
            self.assertIn("warning: no one subscribes to /r1/cmd_vel as TwistStamped: the robot does not move", said)
            self.assertIn("warning: nothing on /r1/ir_0 (an IR sensor)", said)
            self.assertEqual(last["commands"], 0, "the driver took no command")
            warnings = summary(os.path.join(tmp, "r1"))["warnings"]
            self.assertEqual(len([w for w in warnings if "IR sensor" in w]), 6, "each of the omni3's six IR topics")


TB4 = """# a robot whose driver names its topics otherwise
namespace: tb4_1
odom: {topic: wheel/odom, qos: reliable}
ground_truth: none
"""


class Remapping(unittest.TestCase):
    def test_a_robot_under_other_names_with_twist_stamped(self):
        with tempfile.TemporaryDirectory() as tmp:
            robot_file = written(tmp, "tb4_1.yaml", TB4)
            robot = driver("/tb4_1/wheel/odom", "/tb4_1/base/cmd_vel_in", "stamped", 10)
            controller = agent(one_robot(tmp), "r1", os.path.join(tmp, "r1"), "--duration", "7", "--ros2-robot",
                               robot_file, "--ros2-remap", "cmd_vel=base/cmd_vel_in", "--ros2-cmd-vel-stamped")
            said = controller.communicate(timeout=60)[0]
            commands, last = driven(robot.communicate(timeout=60)[0])
            self.assertEqual(controller.returncode, 0, said)
            self.assertGreater(len(commands), 50, said)
            self.assertGreater(last["x"], 0.2 * 5, "the robot drove at 0.2 m/s for most of 7 s")
            s = summary(os.path.join(tmp, "r1"))
            self.assertGreater(s["ros2"]["odometry"], 100)
            self.assertEqual(s["ros2"]["ground_truth"], 0)


PAIR = """name: pair
duration: 60
loop: {udp_port: 52610}
nodes:
  - name: r1
    model: diffdrive
    pose: [0, 0, 0]
    controller: {name: pinger, rate: 10, params: {to: r2, interval: 0.1, start: 0.5}}
  - name: r2
    model: diffdrive
    pose: [3, 0, 0]
    controller: {name: echo, rate: 10}
"""


class ComputersClocks(unittest.TestCase):
    """Two agents on their computers' clocks, the second started 1.5 s after the first."""

    def test_merge_moves_each_agent_from_its_time_zero(self):
        with tempfile.TemporaryDirectory() as tmp:
            scenario = written(tmp, "pair.yaml", PAIR)
            robots = [driver(f"/{r}/odom", f"/{r}/cmd_vel", "twist", 12) for r in ("r1", "r2")]
            first = agent(scenario, "r1", os.path.join(tmp, "r1"), "--duration", "8")
            time.sleep(1.5)
            second = agent(scenario, "r2", os.path.join(tmp, "r2"), "--duration", "6.5")
            for process in (first, second, *robots):
                process.communicate(timeout=60)
            raw = [float(r["delay"]) for r in csv_rows(os.path.join(tmp, "r2", "messages.csv"))]
            self.assertGreater(len(raw), 40)
            self.assertLess(max(raw), -1.0, "on its own clock, r2 hears r1's pings before they were sent")
            done = merge(os.path.join(tmp, "team"), os.path.join(tmp, "r1"), os.path.join(tmp, "r2"))
            self.assertEqual(done.returncode, 0, done.stderr)
            s = summary(os.path.join(tmp, "team"))
            self.assertAlmostEqual(s["clocks"]["moved_by_s"]["r2"], 1.5, delta=0.4)
            self.assertEqual(s["clocks"]["moved_by_s"]["r1"], 0)
            delays = [float(r["delay"]) for r in csv_rows(os.path.join(tmp, "team", "messages.csv"))]
            self.assertEqual(len(delays), len(raw) + len(csv_rows(os.path.join(tmp, "r1", "messages.csv"))))
            self.assertGreater(min(delays), -0.005, "on one time line no message arrives before it is sent")
            self.assertLess(sorted(delays)[len(delays) // 2], 0.02)
            both_ways = [p for p in s["clocks"]["from_messages"] if "to_clock_ahead_by_s" in p]
            self.assertEqual(len(both_ways), 2)
            for p in both_ways:
                self.assertLess(abs(p["to_clock_ahead_by_s"]), 0.01, "one computer: the clocks agree")
            self.assertIn("r2's clock is ahead of r1's", done.stdout)
            again = merge(os.path.join(tmp, "team"), os.path.join(tmp, "r1"), os.path.join(tmp, "r2"))
            self.assertEqual(again.returncode, 0, "a team folder is written again in place: " + again.stderr)


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

    def test_one_commands_results_are_not_cleared_by_another(self):
        with tempfile.TemporaryDirectory() as tmp:
            run = os.path.join(tmp, "run")
            subprocess.run([SANET, "run", os.path.join(SOURCE, "scenarios", "around-the-wall.yaml"), "-q", "-o", run,
                            "--duration", "1"], check=True, capture_output=True)
            before = sorted(os.listdir(run))
            out = agent(one_robot(tmp), "r1", run, "--duration", "1").communicate(timeout=30)[0]
            self.assertIn("holds the results of a simulation's run, not of an agent's on a ROS 2 robot", out)
            out = merge(run, run).stderr
            self.assertIn("not an agent's summary", out)
            self.assertEqual(sorted(os.listdir(run)), before, "nothing of the run's was touched")

    def test_folders_of_no_team_are_refused_naming_them(self):
        with tempfile.TemporaryDirectory() as tmp:
            empty = os.path.join(tmp, "empty")
            os.mkdir(empty)
            out = merge(os.path.join(tmp, "team"), empty)
            self.assertEqual(out.returncode, 2)
            self.assertIn(empty + "/summary.json: cannot read it", out.stderr)
            run = subprocess.run([SANET, "run", os.path.join(SOURCE, "scenarios", "around-the-wall.yaml"), "-q",
                                  "-o", os.path.join(tmp, "run"), "--duration", "1"], capture_output=True, timeout=60)
            self.assertEqual(run.returncode, 0)
            out = merge(os.path.join(tmp, "team"), os.path.join(tmp, "run"))
            self.assertIn("not an agent's summary", out.stderr)
            twice = os.path.join(tmp, "twice")
            os.mkdir(twice)
            with open(os.path.join(twice, "summary.json"), "w") as f:
                json.dump({"mode": "ros2", "robot": "r1", "scenario": "one", "clock": "/clock (use_sim_time)",
                           "ended_by": "duration"}, f)
            for name in ("log.csv", "transitions.csv", "metrics.csv", "messages.csv", "sent.csv"):
                with open(os.path.join(twice, name), "w") as f:
                    f.write("x\n")
            out = merge(os.path.join(tmp, "team"), twice, twice)
            self.assertIn("robot 'r1' again", out.stderr)
            out = merge(os.path.join(tmp, "team"), twice)
            self.assertIn(twice + "/sent.csv: header 'x', expected 'time_sent,from,to,delivery,bytes'", out.stderr)
            other = os.path.join(tmp, "other")
            shutil.copytree(twice, other)
            for folder, robot, fingerprint in ((twice, "r1", "aaaa"), (other, "r2", "bbbb")):
                with open(os.path.join(folder, "summary.json"), "w") as f:
                    json.dump({"mode": "ros2", "robot": robot, "scenario": "one", "clock": "/clock (use_sim_time)",
                               "ended_by": "duration", "scenario_fingerprint": fingerprint}, f)
            out = merge(os.path.join(tmp, "team"), twice, other)
            self.assertIn("the agents ran different scenario files", out.stderr)
            self.assertFalse(os.path.exists(os.path.join(tmp, "team", "summary.json")), "nothing half-written")


if __name__ == "__main__":
    unittest.main(verbosity=2)
