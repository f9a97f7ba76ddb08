#!/usr/bin/env python3
"""Python controllers (docs/python.md), through the sanet command as a user runs them, with the
controllers of tests/python/probe.py:
- the node API as a controller sees it, in process, isolated (the same fingerprint) and under
  launch (the same behaviour);
- determinism: the same seed, the same run, Python's random and numpy's included;
- an exception ends the run with its results and the traceback; a syntax error, a missing
  module or class, unknown, missing and mistyped parameters are found by validate with the
  scenario's file:line;
- `sanet list --python` shows the parameters; an agent whose module differs from the server's
  is refused;
- the built-in waypoint controller written again in Python (examples/python/waypoint.py) gives
  the C++ one's trajectories."""
import csv
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
import unittest

SANET, SOURCE = os.path.abspath(sys.argv.pop(1)), os.path.abspath(sys.argv.pop(1))
HERE = os.path.join(SOURCE, "tests", "python")
EXAMPLES = os.path.join(SOURCE, "examples", "python")

PAIR = """name: pair
seed: 3
duration: 4
network: {{radio: 802.11b, routing: aodv}}
nodes:
  - name: a
    model: omni3
    pose: [0, 0, 0]
    sensors: {{bearing: {{range: 10}}}}
    controller: {{python: "{controller}", rate: 10, params: {{{params_a}}}}}
  - name: b
    model: omni3
    pose: [3, 0, 0]
    sensors: {{bearing: {{range: 10}}}}
    controller: {{python: "{controller}", rate: 10, params: {{{params_b}}}}}
"""


def write(folder, name, text):
    path = os.path.join(folder, name)
    with open(path, "w") as f:
        f.write(text)
    return path


def pair(folder, controller="probe:Talker", extra="", peers=True):
    """Two robots 3 m apart with `controller`, each told of the other (`peer`) unless not `peers`."""
    shutil.copy(os.path.join(HERE, "probe.py"), folder)
    params_a, params_b = ("peer: b" + extra, "peer: a" + extra) if peers else (extra.lstrip(", "),) * 2
    return write(folder, "pair.yaml", PAIR.format(controller=controller, params_a=params_a, params_b=params_b))


def sanet(*args, timeout=120):
    return subprocess.run([SANET, *args], capture_output=True, text=True, timeout=timeout)


def rows(folder, name):
    with open(os.path.join(folder, name)) as f:
        return list(csv.DictReader(f))


def summary(folder):
    with open(os.path.join(folder, "summary.json")) as f:
        return json.load(f)


def texts(folder, node):
    return [r["text"] for r in rows(folder, "log.csv") if r["node"] == node]


class EveryMode(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.scenario = pair(cls.tmp.name)
        cls.runs = {}
        for tag, extra in (("first", []), ("again", []), ("isolated", ["--isolate-controllers"])):
            out = os.path.join(cls.tmp.name, tag)
            done = sanet("run", cls.scenario, "-o", out, "-q", *extra)
            assert done.returncode == 0, done.stderr
            cls.runs[tag] = out

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_the_node_api_as_a_python_controller_sees_it(self):
        a = texts(self.runs["first"], "a")
        self.assertEqual(a[0], "start a id=0 nodes=2 peer=1 nobody=None name_of_peer=b unknown_name='' holonomic=True")
        poses = [t for t in a if t.startswith("t=")]
        self.assertEqual(len(poses), 8, "every fifth step of 4 s at 10 Hz")
        self.assertIn("scan=ndarray/float64/", poses[0])
        self.assertIn("odo=True", poses[0])
        self.assertIn("net aodv routes b>b/1 neighbours [1]", a, "AODV's table after the first exchange")
        heard = [r["why"] for r in rows(self.runs["first"], "transitions.csv") if r["node"] == "b"]
        self.assertIn("a unicast to you 5 to=1 hops=1 late=True", heard)
        self.assertIn("a broadcast all to=None hops=1 late=True", heard)
        metrics = rows(self.runs["first"], "metrics.csv")
        xs = [float(m["value"]) for m in metrics if m["node"] == "a" and m["name"] == "x"]
        self.assertGreater(xs[-1], xs[0] + 0.3, "it drove")
        distances = [float(m["value"]) for m in metrics if m["name"] == "bearing_distance"]
        self.assertTrue(distances and all(2 < d < 4 for d in distances), distances)
        finish = [t for t in a if t.startswith("finish")]
        self.assertEqual(len(finish), 1, "finish runs once")
        self.assertRegex(finish[0], r"^finish steps=41 truth=Pose ir=RangeScan nothing=None bearings=\[\('b', \d\)\] "
                                    r"wake=True$", "after the last step, every sensor by name")

    def test_isolated_and_again_give_the_same_run(self):
        prints = {tag: summary(out)["fingerprint"] for tag, out in self.runs.items()}
        self.assertEqual(prints["first"], prints["again"])
        self.assertEqual(prints["first"], prints["isolated"], "each controller in a process of its own")

    def test_under_launch_the_same_behaviour(self):
        out = os.path.join(self.tmp.name, "launched")
        done = sanet("launch", self.scenario, "-o", out, timeout=60)
        self.assertEqual(done.returncode, 0, done.stdout + done.stderr)
        a = texts(out, "a")
        self.assertIn(texts(self.runs["first"], "a")[0], a, "the same start")
        self.assertGreaterEqual(len([t for t in a if t.startswith("t=")]), 7, "the last step may fall after the end")
        self.assertIn("net kernel routes  neighbours []", a, "over loopback the kernel's empty view (controllers.md)")
        heard = {r["why"].split(" to=")[0] for r in rows(out, "transitions.csv") if r["node"] == "b"}
        self.assertIn("a unicast to you 5", heard)
        self.assertIn("a broadcast all", heard)
        finish = [t for t in a if t.startswith("finish")]
        self.assertEqual(len(finish), 1, "the agent's finish reaches the server's log before the results")
        self.assertRegex(finish[0], r"truth=Pose ir=RangeScan nothing=None bearings=\[\('b', \d\)\]")


class Determinism(unittest.TestCase):
    def test_the_same_seed_gives_the_same_python_random_numbers(self):
        with tempfile.TemporaryDirectory() as tmp:
            scenario = pair(tmp, extra=", draws: true")
            draws = {}
            for tag, seed in (("one", "3"), ("two", "3"), ("other", "4")):
                out = os.path.join(tmp, tag)
                done = sanet("run", scenario, "-o", out, "-q", "--seed", seed)
                self.assertEqual(done.returncode, 0, done.stderr)
                draws[tag] = ([m["value"] for m in rows(out, "metrics.csv") if "random" in m["name"]],
                              summary(out)["fingerprint"])
            self.assertEqual(draws["one"], draws["two"])
            self.assertNotEqual(draws["one"][0], draws["other"][0])
            a_python = [m["value"] for m in rows(os.path.join(tmp, "one"), "metrics.csv")
                        if m["name"] == "python_random" and m["node"] == "a"]
            b_python = [m["value"] for m in rows(os.path.join(tmp, "one"), "metrics.csv")
                        if m["name"] == "python_random" and m["node"] == "b"]
            self.assertNotEqual(a_python, b_python, "one stream in process, drawn in node order")


class Failures(unittest.TestCase):
    def test_an_exception_ends_the_run_with_its_results_and_the_traceback(self):
        with tempfile.TemporaryDirectory() as tmp:
            scenario = pair(tmp, controller="probe:Crash", peers=False)
            out = os.path.join(tmp, "out")
            done = sanet("run", scenario, "-o", out, "-q")
            self.assertEqual(done.returncode, 1)
            status = summary(out)["status"]
            self.assertTrue(status.startswith("failed: controller of a failed: Python controller probe:Crash, in "
                                              "control_step:"), status)
            self.assertIn('probe.py", line', status)
            self.assertIn("in deeper", status)
            self.assertIn("KeyError: 'missing key'", status)
            self.assertGreater(len(rows(out, "trajectories.csv")), 2, "the results up to the failure are kept")
            self.assertEqual(summary(out)["ended_at_s"], 1.0)

    def test_reading_params_after_init_is_an_error_saying_so(self):
        with tempfile.TemporaryDirectory() as tmp:
            scenario = pair(tmp, controller="probe:Picky", extra="k: 1", peers=False)
            done = sanet("run", scenario, "-o", os.path.join(tmp, "out"), "-q")
            self.assertEqual(done.returncode, 1, done.stderr)
            self.assertIn("read while it is built (in __init__), not later", done.stderr)

    def test_mistakes_are_found_by_validate_with_file_line_and_field(self):
        cases = [
            ("broken_syntax:Broken", "", "'nodes[0].controller.python': Python module 'broken_syntax' does not import",
             'broken_syntax.py", line 2'),
            ("nosuch:X", "", "'nodes[0].controller.python': no Python module 'nosuch' in", "--python-path"),
            ("probe:Nope", "", "has no class 'Nope'", "controller classes there: Crash, Gauge, Lister, Picky, Refusals, Talker"),
            ("probe:NotAController", "", "is not a controller class", "control_step"),
            ("probe:Picky", "", "'nodes[0].controller.params.k': parameter 'k' is required", ""),
            ("probe:Picky", "k: 1, speed: 3", "'nodes[0].controller.params.speed': unknown parameter 'speed'",
             "(this controller reads: k, n, fast)"),
            ("probe:Picky", "k: 1, n: 2.5", "'nodes[0].controller.params.n': parameter 'n' must be a whole number", ""),
            ("probe:Picky", "k: 1, fast: maybe", "parameter 'fast' must be true or false, not 'maybe'", ""),
            ("probe", "", "'nodes[0].controller.python': must be MODULE:CLASS", ""),
        ]
        with tempfile.TemporaryDirectory() as tmp:
            shutil.copy(os.path.join(HERE, "broken_syntax.py"), tmp)
            for controller, extra, says, also in cases:
                scenario = pair(tmp, controller=controller, extra=extra, peers=False)
                done = sanet("validate", scenario)
                self.assertEqual(done.returncode, 2, controller + extra)
                self.assertIn(scenario + ":10: ", done.stderr)
                self.assertIn(says, done.stderr)
                self.assertIn(also, done.stderr)

    def test_a_module_named_as_pythons_own_is_refused_saying_so(self):
        with tempfile.TemporaryDirectory() as tmp:
            write(tmp, "random.py", "class Random:\n    def control_step(self, node):\n        pass\n")
            scenario = pair(tmp, controller="random:Random", peers=False)
            done = sanet("validate", scenario)
            self.assertEqual(done.returncode, 2)
            self.assertIn("'random' is a module of Python's own", done.stderr)
            self.assertIn(os.path.join(tmp, "random.py") + " cannot replace: name your module otherwise", done.stderr)
            scenario = pair(tmp, peers=False, extra="")  # Talker beside a random.py: seeding still works
            done = sanet("run", scenario, "-o", os.path.join(tmp, "out"), "-q")
            self.assertEqual(done.returncode, 0, done.stderr)

    def test_the_node_refuses_what_cpp_refuses(self):
        with tempfile.TemporaryDirectory() as tmp:
            scenario = pair(tmp, controller="probe:Refusals", peers=False)
            out = os.path.join(tmp, "out")
            done = sanet("run", scenario, "-o", out, "-q")
            self.assertEqual(done.returncode, 0, done.stderr)
            a = texts(out, "a")
            self.assertIn("nan drive False", a)
            self.assertIn("wheel speeds False", a, "an omni3 has three wheels")
            self.assertIn("send text: TypeError", a)


class Tools(unittest.TestCase):
    def test_sanet_list_shows_a_python_controllers_parameters(self):
        done = sanet("list", "--python", "probe:Lister", "--python-path", HERE)
        self.assertEqual(done.returncode, 0, done.stderr)
        lines = done.stdout[done.stdout.index("probe:Lister"):].splitlines()
        self.assertIn("For sanet list: the parameters as it reads them.", lines[0])
        self.assertRegex(lines[1], r"gain\s+number, default 1.5")
        self.assertRegex(lines[2], r"label\s+text, default robot")
        self.assertRegex(lines[3], r"points\s+list, default \[\]")

    def test_an_agent_whose_module_is_not_the_servers_is_refused(self):
        with tempfile.TemporaryDirectory() as tmp:
            scenario = pair(tmp)
            port_file = os.path.join(tmp, "port")
            server = subprocess.Popen([SANET, "serve", scenario, "--port", "0", "--port-file", port_file, "-q", "-o",
                                       os.path.join(tmp, "served"), "--duration", "30"])
            try:
                for _ in range(600):  # a loaded CI machine starts the server slowly
                    if os.path.exists(port_file) and open(port_file).read().strip():
                        break
                    self.assertIsNone(server.poll(), "the server ended before it listened")
                    time.sleep(0.1)
                else:
                    self.fail("the server wrote no port file in 60 s")
                elsewhere = os.path.join(tmp, "elsewhere")
                os.mkdir(elsewhere)
                with open(os.path.join(elsewhere, "probe.py"), "w") as f:
                    f.write(open(os.path.join(HERE, "probe.py")).read() + "\n# changed\n")
                server_at = "127.0.0.1:" + open(port_file).read().strip()
                agent = subprocess.run([SANET, "agent", "--server", server_at, "--robot", "a", "--python-path",
                                        elsewhere], capture_output=True, text=True, timeout=30, cwd=elsewhere)
                self.assertNotEqual(agent.returncode, 0)
                self.assertIn("this robot's controller is not the server's: Python module: the server's", agent.stderr)
                self.assertIn("copy the server's file here, or point --python-path at it", agent.stderr)
            finally:
                server.terminate()
                server.wait(timeout=30)


BATTERY = """name: battery
duration: 6
network: {radio: 802.11b, routing: none}
nodes:
  - name: r
    model: omni3
    pose: [0, 0, 0]
    energy: {battery_j: 10, voltage: 3, electronics_w: 0.2}
    controller: {python: "probe:Gauge", rate: 10, params: {low: 0.5}}
"""


class Battery(unittest.TestCase):
    """A Python controller reads its battery in sanet run and, through the robot protocol's SEN
    line, as an agent under sanet launch: the same charge, falling at the radio's idle draw plus
    the electronics' and the standing robot's drive idle (docs/energy.md#motion)."""

    def test_the_battery_drains_as_the_controller_reads_it_in_run_and_launch(self):
        watts = 3 * 0.273 + 0.2 + 0.5
        with tempfile.TemporaryDirectory() as tmp:
            shutil.copy(os.path.join(HERE, "probe.py"), tmp)
            scenario = write(tmp, "battery.yaml", BATTERY)
            for command in ("run", "launch"):
                out = os.path.join(tmp, command)
                done = sanet(command, scenario, "-o", out, timeout=120)
                self.assertEqual(done.returncode, 0, done.stdout + done.stderr)
                metrics = rows(out, "metrics.csv")
                charge = [(float(m["time"]), float(m["value"])) for m in metrics if m["name"] == "battery_j"]
                self.assertGreaterEqual(len(charge), 5, command)
                for t, joules in charge:
                    # An agent reads the SEN line the server sent at or before its step.
                    self.assertAlmostEqual(joules, 10 - watts * t, delta=watts * 0.25, msg=f"{command} at {t}")
                power = [float(m["value"]) for m in metrics if m["name"] == "battery_w"]
                self.assertTrue(all(abs(w - watts) < 0.05 for w in power), f"{command}: {power}")
                low = [t for t in texts(out, "r") if t.startswith("low battery")]
                self.assertEqual(low, ["low battery: " + low[0].split(": ")[1]], command)
                self.assertIn("of 10 J at 3.0 V", low[0])
                self.assertEqual(summary(out)["energy"]["nodes"]["r"]["battery_j"], 10)


LASER_COURSE = """name: laser-course
seed: 2
duration: 120
world:
  size: [30, 20]
  obstacles:
    - box: {{center: [6, 0.3], size: [1.5, 3, 0.5]}}
    - wall: {{from: [12, -4], to: [12, 3], height: 0.5, thickness: 0.3}}
nodes:
  - name: pioneer
    model: diffdrive
    pose: [0, 0, 0]
    controller:
      {controller}
      rate: 10
      params: {{waypoints: [[10, 0], [16, 1], [20, -3]], speed: 0.4, localization: odometry}}
end:
  when_logged: arrived
"""


class WaypointInPython(unittest.TestCase):
    def same_run(self, scenario_cpp, scenario_python):
        with tempfile.TemporaryDirectory() as tmp:
            cpp, python = os.path.join(tmp, "cpp"), os.path.join(tmp, "python")
            for scenario, out in ((scenario_cpp, cpp), (scenario_python, python)):
                done = sanet("run", scenario, "-o", out, "-q", "--python-path", EXAMPLES)
                self.assertEqual(done.returncode, 0, done.stderr)
            self.assertEqual(summary(cpp)["ended_by"], "'arrived' logged by robot" if "wall" in scenario_cpp else
                             "'arrived' logged by pioneer")
            self.assertEqual(rows(cpp, "trajectories.csv"), rows(python, "trajectories.csv"))
            self.assertEqual(rows(cpp, "log.csv"), rows(python, "log.csv"))
            self.assertEqual(summary(cpp)["fingerprint"], summary(python)["fingerprint"])

    def test_around_the_wall_omni3_with_ir(self):  # the shipped example, its module beside it
        self.same_run(os.path.join(SOURCE, "scenarios", "around-the-wall.yaml"),
                      os.path.join(EXAMPLES, "around-the-wall.yaml"))

    def test_a_laser_diffdrive_on_odometry_round_two_obstacles(self):
        with tempfile.TemporaryDirectory() as tmp:
            cpp = write(tmp, "cpp.yaml", LASER_COURSE.format(controller="name: waypoint"))
            python = write(tmp, "python.yaml", LASER_COURSE.format(controller='python: "waypoint:Waypoint"'))
            log = os.path.join(tmp, "check")
            done = sanet("run", cpp, "-o", log, "-q")
            self.assertIn("obstacle: following its boundary", [r["text"] for r in rows(log, "log.csv")])
            self.same_run(cpp, python)


if __name__ == "__main__":
    unittest.main(verbosity=2)
