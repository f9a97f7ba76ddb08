#!/usr/bin/env python3
"""--set on the command line, provenance in every results folder, and folders that hold only
the latest run's files (an earlier run's are removed, anything else refused without --force)."""
import json
import os
import subprocess
import sys
import tempfile
import unittest

SANET = sys.argv.pop(1)
SOURCE = sys.argv.pop(1)
SCENARIO = os.path.join(SOURCE, "scenarios", "sensor-network.yaml")


def sanet(*args):
    return subprocess.run([SANET, *args], capture_output=True, text=True, timeout=300)


def summary(folder):
    with open(os.path.join(folder, "summary.json")) as f:
        return json.load(f)


class Provenance(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.out = os.path.join(self.tmp.name, "run")

    def tearDown(self):
        self.tmp.cleanup()

    def run_ok(self, *args):
        out = sanet("run", SCENARIO, "--duration", "3", "-q", "-o", self.out, *args)
        self.assertEqual(out.returncode, 0, out.stderr)
        return summary(self.out)

    def test_set_changes_the_run_and_the_folder_says_so(self):
        plain = self.run_ok()
        changed = self.run_ok("--set", "network.tx_power=33", "--set", "nodes.reporter.controller.params.size=64")
        self.assertNotEqual(plain["fingerprint"], changed["fingerprint"])
        self.assertNotEqual(plain["scenario_fingerprint"], changed["scenario_fingerprint"])
        with open(os.path.join(self.out, "scenario.yaml")) as f:
            effective = f.read()
        self.assertIn("--set network.tx_power=33", effective.splitlines()[0])
        self.assertIn("tx_power: 33", effective)
        with open(os.path.join(self.out, "provenance.json")) as f:
            provenance = json.load(f)
        self.assertEqual(provenance["command"][-4:], ["--set", "network.tx_power=33", "--set",
                                                      "nodes.reporter.controller.params.size=64"])
        self.assertEqual(provenance["scenario_fingerprint"], changed["scenario_fingerprint"])
        for key in ("sanet_version", "git_commit", "host", "started_utc"):
            self.assertTrue(provenance[key], key)
        # The effective scenario runs to the same results as the file with the options.
        again = sanet("run", os.path.join(self.out, "scenario.yaml"), "--duration", "3", "-q", "-o",
                      os.path.join(self.tmp.name, "again"))
        self.assertEqual(again.returncode, 0, again.stderr)
        self.assertEqual(summary(os.path.join(self.tmp.name, "again"))["fingerprint"], changed["fingerprint"])

    def test_a_bad_set_names_the_option(self):
        out = sanet("run", SCENARIO, "-q", "-o", self.out, "--set", "network.tx_power=loud")
        self.assertEqual(out.returncode, 2)
        self.assertIn("--set network.tx_power=loud: 'network.tx_power': must be a number", out.stderr)
        self.assertFalse(os.path.exists(self.out))

    def test_an_earlier_runs_files_are_replaced_not_mixed(self):
        first = self.run_ok("--set", "network.packet_log=true")
        self.assertIn("packets/", first["files"])
        with open(os.path.join(self.out, "log.csv.tmp"), "w") as f:  # as a killed run leaves it
            f.write("half")
        second = self.run_ok("--set", "network.packet_log=false", "--set", "network.flow_monitor=false")
        self.assertNotIn("packets/", second["files"])
        on_disk = sorted(os.listdir(self.out))
        self.assertEqual(on_disk, sorted(f.rstrip("/") for f in second["files"]))

    def test_a_folder_with_foreign_files_is_refused_unless_forced(self):
        os.makedirs(self.out)
        with open(os.path.join(self.out, "thesis.tex"), "w") as f:
            f.write("mine")
        out = sanet("run", SCENARIO, "--duration", "3", "-q", "-o", self.out)
        self.assertEqual(out.returncode, 2)
        self.assertIn("thesis.tex", out.stderr)
        self.assertIn("--force", out.stderr)
        self.assertEqual(os.listdir(self.out), ["thesis.tex"])
        self.run_ok("--force")
        self.assertIn("thesis.tex", os.listdir(self.out))
        self.run_ok("--force")  # its own earlier run is still replaced, the foreign file kept
        self.assertIn("thesis.tex", os.listdir(self.out))

    def test_a_study_folder_is_not_taken_for_a_run(self):
        os.makedirs(self.out)
        open(os.path.join(self.out, "study.sqlite"), "w").close()
        out = sanet("run", SCENARIO, "--duration", "3", "-q", "-o", self.out)
        self.assertEqual(out.returncode, 2)
        self.assertIn("study.sqlite", out.stderr)


if __name__ == "__main__":
    unittest.main()
