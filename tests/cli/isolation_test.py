#!/usr/bin/env python3
"""--isolate-controllers: each controller in a child process of its own. A run gives the same
bytes with and without it; a plugin that crashes (segmentation fault, abort, exit) ends the run
with its results kept and the cause named, where without isolation it takes the process."""
import json
import os
import subprocess
import sys
import tempfile
import unittest

SANET, LIBRARY = sys.argv.pop(1), os.path.abspath(sys.argv.pop(1))

SCENARIO = """name: isolated
duration: {duration}
nodes:
  - name: a
    model: diffdrive
    pose: [0, 0, 0]
    controller: {{name: {controller}, library: {library}{params}}}
  - name: b
    model: diffdrive
    pose: [0, 2, 0]
    controller: {{name: wander, library: {library}}}
"""


def read(*path):
    with open(os.path.join(*path)) as f:
        return f.read()


class Isolation(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.tmp.cleanup()

    def run_scenario(self, name, controller, *options, params="", duration=5):
        path = os.path.join(self.tmp.name, name + ".yaml")
        with open(path, "w") as f:
            f.write(SCENARIO.format(duration=duration, controller=controller, library=LIBRARY, params=params))
        out = os.path.join(self.tmp.name, name)
        # Under AddressSanitizer (the sanitize build) the crash must stay a crash, not its report.
        env = dict(os.environ, ASAN_OPTIONS=os.environ.get("ASAN_OPTIONS", "") + ":handle_segv=0:abort_on_error=0")
        done = subprocess.run([SANET, "run", path, "-o", out, "-q", *options], capture_output=True, text=True,
                              timeout=120, env=env)
        return done, out

    def test_the_same_bytes_with_and_without_isolation(self):
        _, inside = self.run_scenario("inside", "wander")
        done, apart = self.run_scenario("apart", "wander", "--isolate-controllers")
        self.assertEqual(done.returncode, 0, done.stderr)
        first, second = (json.loads(read(d, "summary.json")) for d in (inside, apart))
        self.assertEqual(first["fingerprint"], second["fingerprint"])
        for name in ("trajectories.csv", "metrics.csv", "transitions.csv", "log.csv", "messages.csv"):
            self.assertEqual(read(inside, name), read(apart, name), name)
        self.assertIn("wandering from a", read(apart, "log.csv"))

    def test_a_crashing_plugin_ends_the_run_with_its_results(self):
        for how, cause in (("segfault", "signal 11 (Segmentation fault)"), ("abort", "signal 6 (Aborted)"),
                           ("exit", "exited with status 3")):
            done, out = self.run_scenario(how, "crash_after", "--isolate-controllers",
                                          params=f", params: {{after: 1, how: {how}}}")
            self.assertNotEqual(done.returncode, 0, how)
            self.assertIn(cause, done.stderr, how)
            summary = json.loads(read(out, "summary.json"))
            self.assertTrue(summary["status"].startswith("failed: controller of a failed: its process"), summary)
            self.assertIn(cause, summary["status"])
            self.assertAlmostEqual(summary["simulated_s"], 1.0, delta=0.15)
            rows = read(out, "trajectories.csv").splitlines()
            self.assertGreater(len(rows), 10, "the trajectories up to the crash are kept")

    def test_without_isolation_the_crash_takes_the_process(self):
        done, out = self.run_scenario("unisolated", "crash_after", params=", params: {after: 1}")
        self.assertEqual(done.returncode, -11, "the trade-off the option is for")
        self.assertFalse(os.path.exists(os.path.join(out, "summary.json")))


if __name__ == "__main__":
    unittest.main(verbosity=2)
