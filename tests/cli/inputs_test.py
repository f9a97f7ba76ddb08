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


if __name__ == "__main__":
    unittest.main(verbosity=2)
