#!/usr/bin/env python3
"""Controller API 6 in every mode: Node::Sensor reads a named sensor instance (a second laser) and
nothing for a name the node does not have; Node::SetRadioSleep silences the node's 802.11 radio
both ways while it sleeps (what it sends meanwhile waits in the MAC's queue); Controller::Finish
runs once at the end of the run and what it measures and logs reaches the results. The same
controller runs in-process (`sanet run`), in its own process (`--isolate-controllers`) and as an
agent of `sanet launch` whose datagrams cross the simulated radio (`loop.network: simulated`; the
server tells it END and records its Finish before writing). Without root that mode is skipped."""
import csv
import os
import subprocess
import sys
import tempfile
import unittest

SANET, LIBRARY = sys.argv.pop(1), os.path.abspath(sys.argv.pop(1))
SLEEP_FROM, SLEEP_TO = 4.0, 6.0  # late enough for agents that start slowly (sanitizer builds)

SCENARIO = f"""name: api6
duration: 8
network: {{routing: none}}
loop: {{network: simulated}}
nodes:
  - name: a
    model: diffdrive
    pose: [0, 0, 0]
    sensors:
      laser_rear: {{kind: laser, fov: 1.5, beams: 31, mount_x: -0.2}}
      sonar: {{}}
    controller: {{name: api_probe, library: {LIBRARY}, rate: 20,
                  params: {{sleep_from: {SLEEP_FROM}, sleep_to: {SLEEP_TO}}}}}
  - name: b
    model: diffdrive
    pose: [3, 0, 0]
    sensors:
      ir2: {{kind: ir, count: 4}}
    controller: {{name: api_probe, library: {LIBRARY}, rate: 17}}
"""


def read_csv(folder, name):
    with open(os.path.join(folder, name)) as f:
        return list(csv.DictReader(f))


class ControllerApi(unittest.TestCase):
    def check(self, folder, sonar_in_process=None):
        metrics = read_csv(folder, "metrics.csv")

        def values(node, name):
            return [float(m["value"]) for m in metrics if m["node"] == node and m["name"] == name]

        self.assertEqual(values("a", "rear_beams"), [31.0], "the named laser, through Node::Sensor")
        self.assertEqual(values("b", "rear_beams"), [-1.0], "b has no such instance")
        self.assertEqual(values("a", "unknown_sensor"), [0.0])
        self.assertEqual(values("a", "truth_is_pose"), [1.0])
        sonar = values("a", "sonar_range")
        self.assertEqual(len(sonar), 1)
        self.assertTrue(0 < sonar[0] < 4, f"b's body, 3 m ahead, within the sonar's 4 m: {sonar}")
        if sonar_in_process is not None:
            self.assertAlmostEqual(sonar[0], sonar_in_process, delta=0.02, msg="the same echo, however it was read")
        self.assertEqual(values("b", "sonar_range"), [-1.0], "b has no sonar")
        self.assertEqual(values("b", "ir2_sensors"), [4.0], "a named ring, its lines its own (ir2_0 ...)")
        self.assertEqual(values("a", "ir2_sensors"), [-1.0])
        self.assertEqual(values("a", "sleep_taken"), [1.0])
        self.assertEqual(values("a", "wake_taken"), [1.0])
        margin = 0.15
        asleep = lambda t: SLEEP_FROM + margin < t < SLEEP_TO - margin
        heard_by_a, heard_by_b = values("a", "heard_b"), values("b", "heard_a")
        for heard, who in ((heard_by_a, "a heard b"), (heard_by_b, "b heard a")):
            self.assertTrue([t for t in heard if t < SLEEP_FROM], f"{who} before the sleep")
            self.assertTrue([t for t in heard if t > SLEEP_TO], f"{who} after it")
            self.assertEqual([t for t in heard if asleep(t)], [], f"{who} while a's radio slept")
        for node, heard in (("a", heard_by_a), ("b", heard_by_b)):
            self.assertEqual(values(node, "finished_heard"), [float(len(heard))], f"{node}'s Finish ran once")
        log = [row for row in read_csv(folder, "log.csv") if row["text"].startswith("finished at")]
        self.assertEqual(sorted(row["node"] for row in log), ["a", "b"])
        return sonar[0]

    def test_every_mode(self):
        with tempfile.TemporaryDirectory() as tmp:
            scenario = os.path.join(tmp, "api6.yaml")
            with open(scenario, "w") as f:
                f.write(SCENARIO)
            sonar = None
            for mode, command in (("in-process", ["run", "-q"]), ("isolated", ["run", "-q", "--isolate-controllers"]),
                                  ("agents", ["launch"])):
                with self.subTest(mode=mode):
                    folder = os.path.join(tmp, mode)
                    out = subprocess.run([SANET, *command, scenario, "-o", folder], capture_output=True, text=True,
                                         timeout=180)
                    if mode == "agents" and "needs network namespaces" in out.stderr:
                        self.skipTest("sanet launch across the simulated radio needs root: " + out.stderr.strip())
                    self.assertEqual(out.returncode, 0, out.stdout + out.stderr)
                    sonar = self.check(folder, sonar)


if __name__ == "__main__":
    unittest.main(verbosity=2)
