#!/usr/bin/env python3
"""Inputs that must not cost a run its results: text that is not valid UTF-8 (a scenario path here;
log lines, state names and reasons go through the same writer) leaves valid JSON files."""
import json
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

SANET = sys.argv.pop(1)
SOURCE = sys.argv.pop(1)


class Inputs(unittest.TestCase):
    def test_a_path_that_is_not_utf8_leaves_valid_json(self):
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(os.fsencode(tmp), b"caf\xe9-\xff.yaml")
            shutil.copy(os.path.join(SOURCE, "scenarios", "sensor-network.yaml"), path)
            out = os.path.join(tmp, "out")
            run = subprocess.run([os.fsencode(SANET), b"run", path, b"--duration", b"2", b"-q", b"-o",
                                  os.fsencode(out)], capture_output=True, timeout=120)
            self.assertEqual(run.returncode, 0, run.stderr)
            for name in ("summary.json", "provenance.json"):
                with open(os.path.join(out, name), encoding="utf-8") as f:
                    j = json.load(f)
                text = j["scenario"] if name == "summary.json" else j["command"][2]
                self.assertTrue(text.endswith("caf\ufffd-\ufffd.yaml"), text)
            with open(os.path.join(out, "summary.json")) as f:
                self.assertEqual(json.load(f)["status"], "completed")

    def test_a_node_switched_off_twice_stays_off(self):
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "off.yaml")
            with open(path, "w") as f:  # ns-3 aborted on the second switch-off of a radio
                f.write("duration: 5\nnetwork: {}\nnodes:\n"
                        "  - {name: a, model: mote, pose: [0, 0, 0], controller: {name: pinger, params: {to: b}}}\n"
                        "  - {name: b, model: mote, pose: [5, 0, 0]}\nevents:\n"
                        "  - {time: 1, node: b, action: switch_off}\n  - {time: 2, node: b, action: switch_off}\n")
            out = os.path.join(tmp, "out")
            run = subprocess.run([SANET, "run", path, "-q", "-o", out], capture_output=True, text=True, timeout=60)
            self.assertEqual(run.returncode, 0, run.stderr)
            with open(os.path.join(out, "log.csv")) as f:
                self.assertEqual(f.read().count("switched off"), 1)

    def test_more_nodes_than_can_be_addressed_or_held_are_refused(self):
        swarm = os.path.join(SOURCE, "scenarios", "swarm-1k.yaml")
        for rows, says in [(300, "a network has room for 65534 nodes"), (1000, "a scenario holds at most 100000")]:
            with self.subTest(rows=rows):
                out = subprocess.run([SANET, "validate", swarm, "--set", "nodes.r.grid.rows=%d" % rows, "--set",
                                      "nodes.r.grid.cols=%d" % rows], capture_output=True, text=True, timeout=60)
                self.assertEqual(out.returncode, 2, out.stdout)
                self.assertIn(says, out.stderr)

    def test_values_that_would_hang_or_exhaust_the_run_are_refused(self):
        scenario = os.path.join(SOURCE, "scenarios", "sensor-network.yaml")
        for setting, says in [("world.physics_step=1e-9", "must be between 0.0001 and 0.1"),
                              ("outputs.figure_tick=1e-9", "must be between 0.1 and"),
                              ("nodes.reporter.pose=[1e300, 0, 0]", "more than 1e6 m from the origin"),
                              ("nodes.m.grid.spacing=5e5", "more than 1e6 m from the origin"),
                              ("world.size=[1e300, 1]", "at most 1e6 m")]:
            with self.subTest(setting):
                out = subprocess.run([SANET, "validate", scenario, "--set", setting], capture_output=True, text=True,
                                     timeout=30)
                self.assertEqual(out.returncode, 2, out.stdout)
                self.assertIn(says, out.stderr)

    def test_a_folder_a_long_name_and_an_alias_bomb_are_clear_errors(self):
        with tempfile.TemporaryDirectory() as tmp:
            out = subprocess.run([SANET, "validate", tmp], capture_output=True, text=True, timeout=30)
            self.assertEqual(out.returncode, 2)
            self.assertIn("is a folder, not a scenario file", out.stderr)
            out = subprocess.run([SANET, "validate", os.path.join(tmp, "x" * 300 + ".yaml")], capture_output=True,
                                 text=True, timeout=30)
            self.assertEqual(out.returncode, 2)
            self.assertIn("File name too long", out.stderr)
            bomb = os.path.join(tmp, "bomb.yaml")
            levels = ["        l0: &l0 [1, 1, 1, 1, 1, 1, 1, 1, 1]"]
            for i in range(1, 9):
                levels.append("        l%d: &l%d [%s]" % (i, i, ", ".join(["*l%d" % (i - 1)] * 9)))
            with open(bomb, "w") as f:  # 9^9 values from 9 lines
                f.write("duration: 1\nnodes:\n  - name: a\n    model: omni3\n    pose: [0, 0, 0]\n"
                        "    controller:\n      name: waypoint\n      params:\n" + "\n".join(levels) + "\n")
            out = subprocess.run([SANET, "validate", bomb], capture_output=True, text=True, timeout=30)
            self.assertEqual(out.returncode, 2)
            self.assertIn("more than 1,000,000 values once its aliases", out.stderr)

    def test_a_file_per_node_needs_no_descriptor_per_node(self):
        import resource
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "many.yaml")
            with open(path, "w") as f:  # 600 motes, each with its packets/NODE.csv
                f.write("duration: 1\nnetwork: {routing: none, packet_log: true}\nworld: {size: [1000, 1000]}\n"
                        "nodes:\n  - grid: {name: m, rows: 20, cols: 30, spacing: 30}\n    model: mote\n")
            out = os.path.join(tmp, "out")

            def few_descriptors():
                resource.setrlimit(resource.RLIMIT_NOFILE, (128, 128))

            run = subprocess.run([SANET, "run", path, "-q", "-o", out], capture_output=True, text=True, timeout=120,
                                 preexec_fn=few_descriptors)
            self.assertEqual(run.returncode, 0, run.stderr)
            self.assertEqual(len(os.listdir(os.path.join(out, "packets"))), 600)


if __name__ == "__main__":
    unittest.main(verbosity=2)
