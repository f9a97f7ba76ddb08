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


if __name__ == "__main__":
    unittest.main(verbosity=2)
