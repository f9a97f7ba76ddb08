#!/usr/bin/env python3
"""No silent success: a run in the loop that lost one of its robots says so.
- `sanet launch` with an agent whose controller throws at its first step (a plugin), one whose
  Python controller raises as it starts, and one that cannot reach the server: exit status
  3, summary.json's status is not `completed`, and it names each robot and its agent's own last
  error line; the robot whose agent ran is unaffected;
- `sanet serve` of a scenario with controllers that no client drives ends with exit status 3 and
  says which robots;
- `serve`'s first line is its serving line, also while another process holds the Foxglove port;
  launch says nothing of Foxglove."""
import json
import os
import socket
import subprocess
import sys
import tempfile
import unittest

SANET, LIBRARY = sys.argv.pop(1), os.path.abspath(sys.argv.pop(1))

# Built fine (launch checks that a Python controller can be made before it starts anything), it
# fails as it starts on its robot.
BROKEN = """class Broken:
    def __init__(self, params):
        pass

    def start(self, node):
        raise ValueError("no calibration file for robot " + node.name())

    def control_step(self, node):
        pass
"""

SCENARIO = """name: verdict
duration: {duration}
nodes:
  - name: good
    model: diffdrive
    pose: [0, 0, 0]
    controller: {{name: wander, library: {library}}}
  - name: thrower
    model: diffdrive
    pose: [0, 3, 0]
    controller: {{name: crash_after, library: {library}, params: {{after: 0, how: throw}}}}
  - name: pythonic
    model: diffdrive
    pose: [0, 6, 0]
    controller: {{python: "broken:Broken"}}
  - name: lost
    model: diffdrive
    pose: [0, 9, 0]
    controller: {{name: wander, library: {library}}}
"""


def write(path, text):
    with open(path, "w") as f:
        f.write(text)


def summary_of(folder):
    with open(os.path.join(folder, "summary.json")) as f:
        return json.load(f)


class LaunchWithoutItsRobots(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        write(os.path.join(cls.tmp.name, "broken.py"), BROKEN)
        path = os.path.join(cls.tmp.name, "verdict.yaml")
        # Longer than the agent's 10 s wait for an unreachable server, so that it gives up by itself.
        write(path, SCENARIO.format(duration=16, library=LIBRARY))
        cls.out = os.path.join(cls.tmp.name, "out")
        cls.launch = subprocess.run([SANET, "launch", path, "-o", cls.out, "--test-unreachable", "lost"],
                                    capture_output=True, text=True, timeout=120)
        cls.summary = summary_of(cls.out)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_the_exit_status_and_the_status_say_it_failed(self):
        self.assertEqual(self.launch.returncode, 3, self.launch.stdout + self.launch.stderr)
        status = self.summary["status"]
        self.assertTrue(status.startswith("failed: "), status)
        for robot in ("thrower", "pythonic", "lost"):
            self.assertIn("robot " + robot, status)
        self.assertNotIn("robot good", status)
        self.assertIn("the run failed without", self.launch.stderr)
        # Said as it happened, not only at the end.
        self.assertIn("sanet: the agent of thrower exited with status 1: the run goes on without thrower and will "
                      "end failed", self.launch.stderr)

    def test_each_robot_is_named_with_its_agents_last_error_line(self):
        attendance = self.summary["attendance"]
        self.assertIn("crash_after: thrown at", attendance["thrower"]["cause"])
        self.assertIn("no calibration file for robot pythonic", attendance["pythonic"]["cause"])
        lost = attendance["lost"]
        self.assertIn("cannot reach the server at 127.0.0.1:9", lost["cause"])
        self.assertIn("before driving it", lost["cause"])
        self.assertEqual(lost["driven"], [])
        self.assertEqual(lost["agent"]["ended"], "exited with status 1")
        # Their agents' stderr reached launch's own.
        self.assertIn("cannot reach the server", self.launch.stderr)
        self.assertIn("no calibration file", self.launch.stderr)

    def test_the_robot_whose_agent_ran_was_driven_to_the_end(self):
        good = self.summary["attendance"]["good"]
        self.assertNotIn("cause", good)
        self.assertEqual(len(good["driven"]), 1)
        self.assertIsNone(good["driven"][0]["to_s"])
        self.assertLess(good["driven"][0]["from_s"], 5)
        self.assertGreater(self.summary["agents"]["good"]["steps"], 50)

    def test_launch_says_nothing_of_foxglove(self):
        self.assertNotIn("Foxglove", self.launch.stdout + self.launch.stderr)
        self.assertNotIn("foxglove", self.summary)


class ServeWithoutItsRobots(unittest.TestCase):
    def test_no_client_drove_them_exit_3(self):
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "two.yaml")
            write(path, SCENARIO.split("  - name: pythonic")[0].format(duration=2, library=LIBRARY))
            out = subprocess.run([SANET, "serve", path, "--port", "0", "-o", os.path.join(tmp, "out"), "-q",
                                  "--no-foxglove"], capture_output=True, text=True, timeout=60)
            self.assertEqual(out.returncode, 3, out.stdout + out.stderr)
            self.assertIn("no client drove good, thrower", out.stderr)
            summary = summary_of(os.path.join(tmp, "out"))
            self.assertEqual(summary["status"], "failed: no client drove good, thrower, so their controllers never ran")
            self.assertEqual(summary["attendance"]["good"]["driven"], [])

    def test_the_serving_line_comes_first_while_the_foxglove_port_is_taken(self):
        holder = socket.socket()
        try:
            holder.bind(("127.0.0.1", 8765))
            holder.listen()
        except OSError:
            pass  # another process holds it already: the same case
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "empty.yaml")
            write(path, "duration: 1\nnodes:\n  - {name: r, model: diffdrive, pose: [0, 0, 0]}\n")
            out = subprocess.run([SANET, "serve", path, "--port", "0", "-o", os.path.join(tmp, "out"),
                                  "--wss-port", "0"], capture_output=True, text=True, timeout=60)
        holder.close()
        lines = out.stdout.splitlines()
        self.assertEqual(out.returncode, 0, out.stdout + out.stderr)
        self.assertTrue(lines[0].startswith("sanet: serving "), lines)
        later = "\n".join(lines[1:])
        self.assertIn("Foxglove port 8765 is taken", later)
        self.assertIn("Foxglove stream at ws://127.0.0.1:", later)
        self.assertIn("wireless simulation server (WSS) on", later)


if __name__ == "__main__":
    unittest.main(verbosity=2)
