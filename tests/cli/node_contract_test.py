#!/usr/bin/env python3
"""The Node contract holds in one place for every kind of node: a controller that gives its node
drive commands and wheel speeds that are not numbers has them refused, with a line in the run's
log, by the simulated node (`sanet run`), by the proxy of a controller in its own process
(`--isolate-controllers`) and by the remote node of an agent (`sanet launch`: the server refuses
such a DRIVE with an ERR and no log line, so the log line there is the remote node's own); the
commands that are numbers between them are taken."""
import csv
import os
import subprocess
import sys
import tempfile
import unittest

SANET, LIBRARY = sys.argv.pop(1), os.path.abspath(sys.argv.pop(1))

SCENARIO = f"""name: nan
duration: 3
nodes:
  - name: r
    model: diffdrive
    pose: [0, 0, 0]
    controller: {{name: nan_driver, library: {LIBRARY}}}
"""


def read_csv(folder, name):
    with open(os.path.join(folder, name)) as f:
        return list(csv.DictReader(f))


class NodeContract(unittest.TestCase):
    def test_every_kind_of_node_refuses_what_is_not_a_number(self):
        with tempfile.TemporaryDirectory() as tmp:
            scenario = os.path.join(tmp, "nan.yaml")
            with open(scenario, "w") as f:
                f.write(SCENARIO)
            for mode, command in (("simulated", ["run"]), ("isolated", ["run", "--isolate-controllers"]),
                                  ("remote", ["launch"])):
                with self.subTest(node=mode):
                    folder = os.path.join(tmp, mode)
                    out = subprocess.run([SANET, *command, scenario, "-o", folder, *(["-q"] if mode != "remote"
                                                                                      else [])],
                                         capture_output=True, text=True, timeout=120)
                    self.assertEqual(out.returncode, 0, out.stdout + out.stderr)
                    log = [row["text"] for row in read_csv(folder, "log.csv") if row["node"] == "r"]
                    refused_drive = [t for t in log if t.startswith("drive refused: a velocity that is not a finite")]
                    refused_wheels = [t for t in log if t.startswith("wheel speeds refused: a speed that is not a")]
                    self.assertGreater(len(refused_drive), 3, log[:5])
                    self.assertEqual(len(refused_drive), len(refused_wheels))
                    metrics = read_csv(folder, "metrics.csv")
                    taken = [float(m["value"]) for m in metrics if m["name"] == "non_finite_taken"]
                    self.assertEqual(len(taken), len(refused_drive))
                    self.assertEqual(set(taken), {0.0})
                    finite = [float(m["value"]) for m in metrics if m["name"] == "finite_taken"]
                    self.assertEqual(set(finite), {1.0})
                    last = [row for row in read_csv(folder, "trajectories.csv") if row["node"] == "r"][-1]
                    self.assertGreater(float(last["x"]), 0.3, "the finite commands moved the robot")


if __name__ == "__main__":
    unittest.main(verbosity=2)
