#!/usr/bin/env python3
"""The sanet command as a user runs it: help, validate, run, results, reproducibility, errors."""
import csv
import json
import os
import shutil
import sqlite3
import subprocess
import sys
import tempfile
import unittest
import xml.dom.minidom

SANET = sys.argv.pop(1)
SOURCE = sys.argv.pop(1)
SCENARIO = os.path.join(SOURCE, "scenarios", "around-the-wall.yaml")


def sanet(*args, **options):
    return subprocess.run([SANET, *args], capture_output=True, text=True, timeout=300, **options)


class Cli(unittest.TestCase):
    def test_help_describes_every_subcommand_and_option(self):
        out = sanet("--help")
        self.assertEqual(out.returncode, 0)
        for word in ("run", "validate", "list"):
            self.assertIn(word, out.stdout)
        run_help = sanet("run", "--help").stdout
        for option in ("--seed", "--duration", "--output", "--quiet", "--no-progress"):
            self.assertIn(option, run_help)

    def test_a_mistyped_command_is_told_the_closest_one(self):
        out = sanet("runn", SCENARIO)
        self.assertEqual(out.returncode, 2)
        self.assertIn("sanet: error: 'runn' is not a command. Did you mean run?", out.stderr)
        self.assertIn("validate", out.stderr, "the commands are listed")
        self.assertNotIn("subcommand is required", out.stderr)

    def test_test_only_options_stay_out_of_help(self):
        agent_help = sanet("agent", "--help").stdout
        self.assertIn("--shared-clock", agent_help)
        for hidden in ("--test-clock-offset", "--test-protocol-version"):
            self.assertNotIn(hidden, agent_help)

    def test_version_names_the_release_and_commit(self):
        out = sanet("--version")
        self.assertEqual(out.returncode, 0)
        self.assertRegex(out.stdout, r"^sanet \d+\.\d+\.\d+ \(")

    def test_validate_accepts_the_shipped_scenario(self):
        out = sanet("validate", SCENARIO)
        self.assertEqual(out.returncode, 0, out.stderr)
        self.assertIn("valid", out.stdout)

    def test_validate_names_file_and_line_of_a_mistake(self):
        with tempfile.NamedTemporaryFile("w", suffix=".yaml", delete=False) as f:
            f.write("duration: 10\nnodes:\n  - name: r\n    model: omni4\n    pose: [0, 0, 0]\n")
        out = sanet("validate", f.name)
        self.assertEqual(out.returncode, 2)
        self.assertIn(f"{f.name}:4: 'nodes[0].model': unknown model 'omni4'", out.stderr)
        os.unlink(f.name)

    def test_list_shows_models_and_controllers(self):
        out = sanet("list").stdout
        for word in ("omni3", "diffdrive", "mote", "waypoint", "constant_velocity"):
            self.assertIn(word, out)

    def test_list_prints_one_section_on_request(self):
        sensors = sanet("list", "--sensors").stdout
        self.assertTrue(sensors.startswith("sensors (keys under a node's `sensors`"), sensors[:80])
        for line in ("  laser        a planar laser scanner", "reading                      RangeScan (ranges in m",
                     "ROS 2                        sensor_msgs/msg/LaserScan on /<robot>/scan",
                     "ROS 2                        sensor_msgs/msg/Range (ULTRASOUND) on /<robot>/sonar",
                     "reading                      Pose2D (x, y in m, theta in rad)", "ROS 2                        none",
                     "accelerometer_noise_density  number (m/s²/√Hz)",  # the longest key keeps its column
                     "ROS 2                        sensor_msgs/msg/NavSatFix on /<robot>/fix"):
            self.assertIn(line, sensors)
        self.assertNotIn("waypoint", sensors)
        self.assertNotIn("models (", sensors)
        models = sanet("list", "--models").stdout
        self.assertTrue(models.startswith("models ("), models[:40])
        self.assertIn("carries                      ir, odometry, ground_truth", models, "omni3 carries these")
        self.assertIn("drive limits                 1.2 m/s, 3 rad/s", models, "diffdrive's")
        self.assertNotIn("sensors (keys", models)
        both = sanet("list", "--models", "--sensors").stdout
        self.assertEqual(both, models + sensors)
        self.assertEqual(sanet("list").stdout, both + sanet("list", "--controllers").stdout)

    def test_run_writes_results_that_are_byte_identical_for_the_same_seed(self):
        """Two processes, one in another locale, time zone and working folder, write the same
        bytes; another seed writes others (so the comparison can fail)."""
        with tempfile.TemporaryDirectory() as tmp:
            a, b, c = (os.path.join(tmp, x) for x in "abc")
            elsewhere = dict(os.environ, LC_ALL="C.UTF-8", LANG="de_DE.UTF-8", TZ="Asia/Kathmandu")
            for folder, seed, options in ((a, "3", {}), (b, "3", {"env": elsewhere, "cwd": tmp}), (c, "4", {})):
                out = sanet("run", SCENARIO, "-o", folder, "--seed", seed, "--duration", "30", "-q", **options)
                self.assertEqual(out.returncode, 0, out.stderr)
                self.assertEqual(out.stdout, "")
            results = sorted(n for n in os.listdir(a) if n.endswith(".csv"))
            self.assertGreaterEqual(len(results), 4, results)
            for name in results:
                with open(os.path.join(a, name), "rb") as fa, open(os.path.join(b, name), "rb") as fb:
                    self.assertEqual(fa.read(), fb.read(), name)
            summary, same, other = (json.load(open(os.path.join(d, "summary.json"))) for d in (a, b, c))
            for key in ("duration_s", "wall_time_s", "real_time_factor", "events", "seed", "fingerprint"):
                self.assertIn(key, summary)
            self.assertEqual(summary["seed"], 3)
            self.assertEqual(summary["status"], "completed")
            self.assertEqual(summary["fingerprint"], same["fingerprint"])
            self.assertNotEqual(summary["fingerprint"], other["fingerprint"], "another seed, another run")
            self.assertFalse([n for n in os.listdir(a) if n.endswith(".tmp")])

    def test_two_threads_give_the_results_of_one_and_other_counts_are_refused(self):
        with tempfile.TemporaryDirectory() as tmp:
            runs = {}
            for threads in ("1", "2"):
                folder = os.path.join(tmp, threads)
                out = sanet("run", SCENARIO, "-o", folder, "--threads", threads, "--duration", "30", "-q")
                self.assertEqual(out.returncode, 0, out.stderr)
                runs[threads] = json.load(open(os.path.join(folder, "summary.json")))
                with open(os.path.join(folder, "trajectories.csv"), "rb") as f:
                    runs[threads]["bytes"] = f.read()
            self.assertEqual(runs["1"]["fingerprint"], runs["2"]["fingerprint"])
            self.assertEqual(runs["1"]["bytes"], runs["2"]["bytes"])
            self.assertEqual(runs["1"]["profile_s"]["physics_wait"], 0)
        bad = sanet("run", SCENARIO, "--threads", "3")
        self.assertEqual(bad.returncode, 2)
        self.assertIn("--threads", bad.stderr)

    def test_the_readme_scenario_reaches_its_way_point(self):
        with tempfile.TemporaryDirectory() as tmp:
            out = sanet("run", SCENARIO, "-o", tmp, "-q")
            self.assertEqual(out.returncode, 0, out.stderr)
            log = open(os.path.join(tmp, "log.csv")).read()
            self.assertIn("robot,arrived", log)
            # The first run shows something: the map, whose PNG the README says to open.
            self.assertIn("map.svg", json.load(open(os.path.join(tmp, "summary.json")))["files"])
            if shutil.which("rsvg-convert"):
                with open(os.path.join(tmp, "map.png"), "rb") as png:
                    self.assertEqual(png.read(8), b"\x89PNG\r\n\x1a\n")

    def test_the_sensor_network_scenario_carries_messages_over_many_hops(self):
        with tempfile.TemporaryDirectory() as tmp:
            out = sanet("run", os.path.join(SOURCE, "scenarios", "sensor-network.yaml"), "-o", tmp, "-q")
            self.assertEqual(out.returncode, 0, out.stderr)
            summary = json.load(open(os.path.join(tmp, "summary.json")))
            self.assertEqual(summary["network"]["routing"], "aodv")
            self.assertGreater(summary["network"]["route_discoveries"]["established"], 0)
            rows = list(csv.DictReader(open(os.path.join(tmp, "messages.csv"))))
            corner = [r for r in rows if r["from"] == "reporter" and r["to"] == "m24"]
            self.assertGreater(len(corner), 5)
            self.assertTrue(all(int(r["hops"]) >= 8 for r in corner), corner)
            for name in ("packets.csv", "routes.csv", "flowmon.xml", "packets/m12.csv"):
                self.assertTrue(os.path.exists(os.path.join(tmp, name)), name)

    def test_sweep_runs_each_seed_and_summarises_the_end_times(self):
        with tempfile.TemporaryDirectory() as tmp:
            out = sanet("sweep", SCENARIO, "--seeds", "1-2,5", "-o", tmp)
            self.assertEqual(out.returncode, 0, out.stderr)
            self.assertIn("3 of 3 runs done: 3 completed, 0 failed", out.stdout)
            self.assertIn("the end condition was met in 3 of 3 completed runs, at ", out.stdout)
            with sqlite3.connect(os.path.join(tmp, "study.sqlite")) as db:
                runs = list(db.execute("SELECT seed, ended_by FROM runs ORDER BY id"))
            self.assertEqual([r[0] for r in runs], [1, 2, 5])
            self.assertTrue(all(r[1] != "duration" for r in runs), runs)
            self.assertTrue(os.path.exists(os.path.join(tmp, "runs", "seed=5", "trajectories.csv")))
        bad = sanet("sweep", SCENARIO, "--seeds", "3-x")
        self.assertEqual(bad.returncode, 2)
        self.assertIn("'3-x' is not a seed", bad.stderr)

    def test_the_help_request_case_study_runs_to_arrival_with_its_figures(self):
        with tempfile.TemporaryDirectory() as tmp:
            out = sanet("run", os.path.join(SOURCE, "scenarios", "help-request.yaml"), "-o", tmp, "-q")
            self.assertEqual(out.returncode, 0, out.stderr)
            summary = json.load(open(os.path.join(tmp, "summary.json")))
            self.assertEqual(summary["ended_by"], "'arrived' logged by robot")
            self.assertEqual(summary["transitions_to"]["done"], 1)
            for key in ("min", "q1", "median", "q3", "max"):
                self.assertIn(key, summary["network"]["route_discoveries"]["time_s"])
                self.assertIn(key, summary["message_delay_s"])
            self.assertIn("hop_time", summary["metrics"]["robot"])
            self.assertIn("time_avoiding_obstacles", summary["metrics"]["robot"])
            for figure in ("map.svg", "packets.svg"):
                document = xml.dom.minidom.parse(os.path.join(tmp, figure))
                self.assertEqual(document.documentElement.tagName, "svg")
            marks = xml.dom.minidom.parse(os.path.join(tmp, "map.svg")).getElementsByTagName("circle")
            self.assertGreater(len(marks), 15, "a mark every 50 s over about 1100 s")

    def test_missing_scenario_file_is_an_error_not_a_crash(self):
        out = sanet("run", "/no/such/file.yaml")
        self.assertEqual(out.returncode, 2)
        self.assertIn("/no/such/file.yaml", out.stderr)
        self.assertIn("cannot open", out.stderr)

    def test_a_port_file_that_cannot_be_written_says_why(self):
        with tempfile.TemporaryDirectory() as tmp:
            for where, why in ((tmp, "Is a directory"), (os.path.join(tmp, "no", "p"), "No such file or directory")):
                out = sanet("serve", SCENARIO, "--port", "0", "--port-file", where, "-q", "-o", os.path.join(tmp, "o"))
                self.assertEqual(out.returncode, 2, out.stderr)
                self.assertIn("--port-file: cannot write", out.stderr)
                self.assertIn(why, out.stderr)


if __name__ == "__main__":
    unittest.main(verbosity=2)
