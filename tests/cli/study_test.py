#!/usr/bin/env python3
"""Studies: `sanet sweep` over a grid of values and seeds into one database, resumed after a
kill without redoing finished runs, the same rows under MPI, and `sanet report`."""
import csv
import os
import shutil
import signal
import sqlite3
import subprocess
import sys
import tempfile
import time
import unittest
import xml.dom.minidom

SANET = sys.argv.pop(1)
SOURCE = sys.argv.pop(1)
SCENARIO = os.path.join(SOURCE, "scenarios", "sensor-network.yaml")
GRID = ["--vary", "network.tx_power=28,33", "--vary", "nodes.reporter.controller.params.size=32,256",
        "--seeds", "1-2"]


def sanet(*args, **kwargs):
    return subprocess.run([SANET, *args], capture_output=True, text=True, timeout=600, **kwargs)


def rows(folder, sql):
    with sqlite3.connect(os.path.join(folder, "study.sqlite")) as db:
        return list(db.execute(sql))


def completed_runs(folder):
    """Runs completed so far; 0 while the sweep has created the file but not yet its tables."""
    try:
        return rows(folder, "SELECT count(*) FROM runs WHERE status = 'completed'")[0][0]
    except sqlite3.OperationalError:
        return 0


class Sweep(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.study = os.path.join(self.tmp.name, "study")

    def tearDown(self):
        self.tmp.cleanup()

    def sweep(self, *extra, study=None):
        out = sanet("sweep", SCENARIO, *GRID, "--duration", "20", "-o", study or self.study, *extra)
        self.assertEqual(out.returncode, 0, out.stdout + out.stderr)
        return out

    def test_a_grid_gives_every_run_once_and_again_nothing(self):
        first = self.sweep("--jobs", "2")
        self.assertIn("8 of 8 runs done: 8 completed, 0 failed (8 run by this command)", first.stdout)
        runs = rows(self.study, "SELECT r.seed, p1.number, p2.number, r.status, r.fingerprint FROM runs r "
                                "JOIN parameters p1 ON p1.run = r.id AND p1.name = 'network.tx_power' "
                                "JOIN parameters p2 ON p2.run = r.id AND p2.name = "
                                "'nodes.reporter.controller.params.size' ORDER BY r.id")
        self.assertEqual([r[:3] for r in runs], [(s, p, z) for p in (28, 33) for z in (32, 256) for s in (1, 2)])
        self.assertTrue(all(r[3] == "completed" for r in runs))
        self.assertEqual(len({r[4] for r in runs}), 8, "every run differs")
        # Each run's folder holds its effective scenario with its values.
        with open(os.path.join(self.study, "runs", "tx_power=33,size=256,seed=2", "scenario.yaml")) as f:
            effective = f.read()
        self.assertIn("tx_power: 33", effective)
        self.assertIn("size: 256", effective)
        self.assertIn("seed: 2", effective)
        # Every number of every summary is in the database.
        received = rows(self.study, "SELECT count(*) FROM scalars WHERE name = 'network.packets.received'")
        self.assertEqual(received[0][0], 8)
        finished = rows(self.study, "SELECT name, finished_utc FROM runs ORDER BY name")
        again = self.sweep("--jobs", "2")
        self.assertIn("(0 run by this command)", again.stdout)
        self.assertEqual(rows(self.study, "SELECT name, finished_utc FROM runs ORDER BY name"), finished)

    def test_killed_half_way_it_completes_without_redoing_finished_runs(self):
        for how in (signal.SIGKILL, signal.SIGINT):
            with self.subTest(signal=how.name):
                study = os.path.join(self.tmp.name, how.name)
                command = [SANET, "sweep", SCENARIO, *GRID, "--duration", "60", "--jobs", "1", "-o", study, "-q"]
                process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
                database = os.path.join(study, "study.sqlite")
                deadline = time.time() + 120
                while time.time() < deadline:
                    time.sleep(0.2)
                    if os.path.exists(database) and completed_runs(study) >= 3:
                        break
                process.send_signal(how)
                process.wait(timeout=60)
                self.assertNotEqual(process.returncode, 0)
                time.sleep(0.5)  # the runs it started die with it (and do not go on writing)
                before = dict(rows(study, "SELECT name, finished_utc FROM runs WHERE status = 'completed'"))
                self.assertGreaterEqual(len(before), 3)
                self.assertLess(len(before), 8)
                out = sanet("sweep", SCENARIO, *GRID, "--duration", "60", "--jobs", "2", "-o", study)
                self.assertEqual(out.returncode, 0, out.stderr)
                self.assertIn(f"({8 - len(before)} run by this command)", out.stdout)
                after = dict(rows(study, "SELECT name, finished_utc FROM runs WHERE status = 'completed'"))
                self.assertEqual(len(after), 8)
                for name, stamp in before.items():
                    self.assertEqual(after[name], stamp, f"{name} was run again")
                leftovers = [f for f in os.listdir(os.path.join(study, "runs")) if not f.startswith("tx_power=")]
                self.assertEqual(leftovers, [])

    @unittest.skipUnless(shutil.which("mpirun"), "no mpirun (./setup installs openmpi-bin)")
    def test_mpi_gives_the_same_rows_as_local_jobs(self):
        local = os.path.join(self.tmp.name, "local")
        self.sweep("--jobs", "2", study=local)
        # Under AddressSanitizer (the sanitize build): OpenMPI unloads its components before
        # LeakSanitizer looks, so what they keep cannot even be named; leaks are not checked here.
        env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
                   ASAN_OPTIONS=os.environ.get("ASAN_OPTIONS", "") + ":detect_leaks=0")
        out = subprocess.run(["mpirun", "-n", "2", "--oversubscribe", SANET, "sweep", SCENARIO, *GRID, "--duration",
                              "20", "--jobs", "1", "-o", self.study], capture_output=True, text=True, timeout=600,
                             env=env)
        self.assertEqual(out.returncode, 0, out.stdout + out.stderr)
        self.assertIn("on 2 MPI ranks", out.stdout)
        query = "SELECT name, seed, status, fingerprint, scenario_fingerprint FROM runs ORDER BY name"
        self.assertEqual(rows(self.study, query), rows(local, query))
        self.assertEqual({r[0] for r in rows(self.study, "SELECT rank FROM runs")}, {0, 1}, "both ranks ran")
        scalars = "SELECT r.name, s.name, s.value FROM scalars s JOIN runs r ON r.id = s.run " \
                  "WHERE s.name LIKE 'network.%' ORDER BY 1, 2"
        self.assertEqual(rows(self.study, scalars), rows(local, scalars))

    def test_mistakes_are_named(self):
        out = sanet("sweep", SCENARIO, "--vary", "network.tx_power=28,loud", "-o", self.study)
        self.assertEqual(out.returncode, 2)
        self.assertIn("--vary network.tx_power: 'network.tx_power': the value 'loud': must be a number", out.stderr)
        out = sanet("sweep", SCENARIO, "--vary", "network.tx_power", "-o", self.study)
        self.assertEqual(out.returncode, 2)
        self.assertIn("expected PATH=V1,V2", out.stderr)
        out = sanet("sweep", SCENARIO, "--seeds", "3-x", "-o", self.study)
        self.assertEqual(out.returncode, 2)
        self.assertIn("'3-x' is not a seed", out.stderr)
        os.makedirs(self.study)
        open(os.path.join(self.study, "notes.txt"), "w").close()
        out = sanet("sweep", SCENARIO, "--seeds", "1", "-o", self.study)
        self.assertEqual(out.returncode, 2)
        self.assertIn("notes.txt", out.stderr)

    def test_a_failing_run_is_recorded_with_its_error_and_not_redone(self):
        scenario = os.path.join(self.tmp.name, "pinger.yaml")
        with open(scenario, "w") as f:  # a pinger whose target does not exist fails when it starts
            f.write("duration: 5\nnodes:\n  - {name: a, model: mote, pose: [0, 0, 0], "
                    "controller: {name: pinger, params: {to: b, start: 1}}}\n  - {name: b, model: mote, pose: [5, 0, 0]}\n")
        command = ["sweep", scenario, "--vary", "nodes.a.controller.params.to=b,nobody", "--seeds", "1-2", "-o",
                   self.study]
        out = sanet(*command)
        self.assertEqual(out.returncode, 1, out.stderr)
        self.assertIn("4 of 4 runs done: 2 completed, 2 failed (4 run by this command)", out.stdout)
        failed = rows(self.study, "SELECT name, error FROM runs WHERE status = 'failed'")
        self.assertEqual(sorted(f[0] for f in failed), ["to=nobody,seed=1", "to=nobody,seed=2"])
        self.assertIn("pinger: no node named 'nobody'", failed[0][1])
        again = sanet(*command)
        self.assertIn("(0 run by this command)", again.stdout)
        retried = sanet(*command, "--retry-failed")
        self.assertIn("2 completed, 2 failed (2 run by this command)", retried.stdout)

    def test_a_changed_scenario_runs_its_finished_runs_again(self):
        self.sweep("--jobs", "2")
        out = sanet("sweep", SCENARIO, *GRID, "--duration", "10", "-o", self.study)
        self.assertEqual(out.returncode, 0, out.stderr)
        self.assertIn("8 finished runs of an earlier version of the scenario", out.stdout)
        self.assertIn("(8 run by this command)", out.stdout)
        self.assertEqual(rows(self.study, "SELECT DISTINCT simulated_s FROM runs"), [(10.0,)])
        other = sanet("sweep", SCENARIO, *GRID, "--set", "network.data_rate=2", "-o", self.study)
        self.assertEqual(other.returncode, 2)
        self.assertIn("holds a study with other sets (none, not network.data_rate=2)", other.stderr)

    def test_a_run_stopped_half_way_leaves_nothing_in_the_way(self):
        # What a killed run leaves: its provenance, temporary files, a folder of them.
        folder = os.path.join(self.tmp.name, "run")
        self.assertEqual(sanet("run", SCENARIO, "--duration", "5", "-q", "-o", folder).returncode, 0)
        for name in os.listdir(folder):
            path = os.path.join(folder, name)
            if name not in ("provenance.json", "scenario.yaml"):
                shutil.rmtree(path) if os.path.isdir(path) else os.unlink(path)
        os.makedirs(os.path.join(folder, "packets"))
        open(os.path.join(folder, "packets", "m0.csv.tmp"), "w").close()
        open(os.path.join(folder, "log.csv.tmp"), "w").close()
        run = sanet("run", SCENARIO, "--duration", "5", "-q", "-o", folder)
        self.assertEqual(run.returncode, 0, run.stderr)


class Report(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.study = os.path.join(cls.tmp.name, "study")
        out = sanet("sweep", SCENARIO, *GRID, "--duration", "20", "-o", cls.study, "--tables", "routes,messages")
        assert out.returncode == 0, out.stderr

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_a_metric_against_a_parameter_with_intervals(self):
        out = sanet("report", self.study, "-m", "network.packets.received")
        self.assertEqual(out.returncode, 0, out.stderr)
        self.assertIn("network.packets.received by network.tx_power (nodes.reporter.controller.params.size=32)",
                      out.stdout)
        values = rows(self.study, "SELECT p.number, s.value FROM scalars s JOIN parameters p ON p.run = s.run "
                                  "AND p.name = 'network.tx_power' JOIN parameters q ON q.run = s.run AND "
                                  "q.name = 'nodes.reporter.controller.params.size' AND q.number = 32 "
                                  "WHERE s.name = 'network.packets.received'")
        mean_28 = sum(v for p, v in values if p == 28) / 2
        line = [l for l in out.stdout.splitlines() if l.split()[:2] == ["28", "2"]][0]
        self.assertAlmostEqual(float(line.split()[2]), mean_28, places=3)
        # Two seeds a group: the report says the intervals mean little.
        self.assertIn("warning: 4 of 4 groups have fewer than 5 runs (the fewest: 2)", out.stderr)
        self.assertEqual(out.stderr.count("warning:"), 1, "once, whatever the metrics")

    def test_plots_and_csv(self):
        svg = os.path.join(self.tmp.name, "plot.svg")
        png = os.path.join(self.tmp.name, "plot.png")
        table = os.path.join(self.tmp.name, "runs.csv")
        for plot in (svg, png):
            out = sanet("report", self.study, "-m", "message_delay_s.median", "--plot", plot, "--csv", table)
            self.assertEqual(out.returncode, 0, out.stderr)
        document = xml.dom.minidom.parse(svg)
        self.assertGreater(len(document.getElementsByTagName("polyline")) +
                           len(document.getElementsByTagName("path")), 4)
        with open(png, "rb") as f:
            self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")
        with open(table) as f:
            runs = list(csv.DictReader(f))
        self.assertEqual(len(runs), 8)
        self.assertEqual(set(runs[0]), {"run_id", "run_name", "seed", "status", "network.tx_power",
                                        "nodes.reporter.controller.params.size", "message_delay_s.median"})

    def test_the_python_example_of_the_docs_reads_the_same_numbers(self):
        example = os.path.join(SOURCE, "examples", "study_in_python.py")
        out = subprocess.run([sys.executable, example, self.study, "network.packets.received"], capture_output=True,
                             text=True, timeout=60)
        self.assertEqual(out.returncode, 0, out.stderr)
        for power in (28, 33):
            values = [v for (v,) in rows(self.study, "SELECT s.value FROM scalars s JOIN parameters p ON p.run = s.run "
                                                     "JOIN parameters q ON q.run = s.run WHERE p.name = "
                                                     "'network.tx_power' AND p.number = %d AND q.number = 256 AND "
                                                     "s.name = 'network.packets.received'" % power)]
            line = [l for l in out.stdout.splitlines() if l.split()[:1] == [str(power)] and l.endswith("=256")][0]
            self.assertAlmostEqual(float(line.split("mean")[1].split()[0]), sum(values) / len(values), places=2)
        wrong = subprocess.run([sys.executable, example, self.study, "network.packets.recieved"], capture_output=True,
                               text=True, timeout=60)
        self.assertNotEqual(wrong.returncode, 0)
        self.assertIn("no run has a metric", wrong.stderr)

    def test_per_event_tables_carry_their_run(self):
        routes = rows(self.study, "SELECT count(DISTINCT run), count(*) FROM routes")
        self.assertEqual(routes[0][0], 8)
        self.assertGreater(routes[0][1], 8)

    def test_mistakes_are_named(self):
        out = sanet("report", self.study, "-m", "network.packets.recieved")
        self.assertEqual(out.returncode, 2)
        self.assertIn("did you mean network.packets.received", out.stderr)
        out = sanet("report", self.study, "-m", "events", "--by", "network.txpower")
        self.assertEqual(out.returncode, 2)
        self.assertIn("does not vary 'network.txpower'", out.stderr)
        out = sanet("report", os.path.join(self.study, "runs"))
        self.assertEqual(out.returncode, 2)
        self.assertIn("is not a study", out.stderr)


if __name__ == "__main__":
    unittest.main(verbosity=2)
