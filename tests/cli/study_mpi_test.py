#!/usr/bin/env python3
"""Studies under MPI at the sizes users reach: many more runs than ranks x jobs give the same rows
as `--jobs`, again and again, on 2 and 3 ranks; runs that fail, crash or are killed are recorded as
failed and the study completes; a rank with nothing left to do costs almost no CPU; a sweep stopped
with SIGINT or SIGTERM to mpirun completes when run again, without redoing finished runs."""
import glob
import json
import os
import shutil
import signal
import sqlite3
import subprocess
import sys
import tempfile
import time
import unittest

SANET = sys.argv.pop(1)
SOURCE = sys.argv.pop(1)
LIBRARY = os.path.abspath(sys.argv.pop(1))
SCENARIO = os.path.join(SOURCE, "scenarios", "sensor-network.yaml")
# 18 runs of about a quarter of a second each: many ends that come close together.
GRID = ["--vary", "network.tx_power=28,30,33", "--seeds", "1-6", "--duration", "5"]
# Under AddressSanitizer (the sanitize build): OpenMPI unloads its components before
# LeakSanitizer looks, so what they keep cannot even be named; leaks are not checked here.
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           ASAN_OPTIONS=os.environ.get("ASAN_OPTIONS", "") + ":detect_leaks=0:handle_segv=0:abort_on_error=0")
CRASHING = """name: crashing
duration: 3
nodes:
  - name: a
    model: diffdrive
    pose: [0, 0, 0]
    controller: {{name: crash_after, library: {library}, params: {{after: 100, how: segfault}}}}
"""


def mpirun(ranks, *args):
    return ["mpirun", "-n", str(ranks), "--oversubscribe", SANET, "sweep", *args]


def rows(folder, sql):
    with sqlite3.connect(os.path.join(folder, "study.sqlite")) as db:
        return list(db.execute(sql))


def count(folder, where):
    """Runs in that state so far; 0 while the sweep has created the file but not yet its tables."""
    try:
        return rows(folder, f"SELECT count(*) FROM runs WHERE {where}")[0][0]
    except sqlite3.OperationalError:
        return 0


def wait_for(condition, seconds, what):
    deadline = time.time() + seconds
    while time.time() < deadline:
        if condition():
            return
        time.sleep(0.1)
    raise AssertionError(f"not within {seconds} s: {what}")


def rank_pid(rank):
    """The pid of the sweep's MPI rank `rank` (from the environment mpirun gives it)."""
    for environ in glob.glob("/proc/[0-9]*/environ"):
        try:
            with open(environ, "rb") as f:
                variables = f.read().split(b"\0")
            with open(environ.replace("environ", "cmdline"), "rb") as f:
                command = f.read().split(b"\0")
        except OSError:
            continue
        if f"OMPI_COMM_WORLD_RANK={rank}".encode() in variables and b"sweep" in command:
            return int(environ.split("/")[2])
    return None


def cpu_seconds(pid):
    with open(f"/proc/{pid}/stat") as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")  # utime + stime


@unittest.skipUnless(shutil.which("mpirun"), "no mpirun (./setup installs openmpi-bin)")
def completed_folder(folder):
    """Whether a run's folder holds the whole results of a completed run."""
    try:
        with open(os.path.join(folder, "summary.json")) as f:
            return json.load(f).get("status") == "completed"
    except (OSError, ValueError):
        return False


class MpiSweep(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.tmp.cleanup()

    def folder(self, name):
        return os.path.join(self.tmp.name, name)

    def test_many_more_runs_than_slots_give_the_rows_of_local_jobs_every_time(self):
        local = self.folder("local")
        out = subprocess.run([SANET, "sweep", SCENARIO, *GRID, "--jobs", "2", "-o", local, "-q"], timeout=300)
        self.assertEqual(out.returncode, 0)
        query = "SELECT name, seed, status, fingerprint, scenario_fingerprint FROM runs ORDER BY name"
        scalars = "SELECT r.name, s.name, s.value FROM scalars s JOIN runs r ON r.id = s.run " \
                  "WHERE s.name LIKE 'network.%' ORDER BY 1, 2"
        expected = rows(local, query)
        self.assertEqual(len(expected), 18)
        # What a worker rank killed outright leaves behind: the next MPI sweep removes it.
        gone = subprocess.Popen(["true"])
        gone.wait()
        stale = os.path.join(tempfile.gettempdir(), f"sanet-rank-1-{gone.pid}")
        os.makedirs(os.path.join(stale, "tx_power=28,seed=1"), exist_ok=True)
        for ranks, jobs, attempt in ((2, 2, 1), (2, 1, 2), (3, 1, 1), (3, 2, 2)):
            with self.subTest(ranks=ranks, jobs=jobs, attempt=attempt):
                study = self.folder(f"mpi-{ranks}-{jobs}-{attempt}")
                out = subprocess.run(mpirun(ranks, SCENARIO, *GRID, "--jobs", str(jobs), "-o", study),
                                     capture_output=True, text=True, timeout=300, env=ENV)
                self.assertEqual(out.returncode, 0, out.stdout + out.stderr)
                self.assertIn(f"on {ranks} MPI ranks", out.stdout)
                self.assertIn("18 of 18 runs done: 18 completed, 0 failed (18 run by this command)", out.stdout)
                self.assertEqual(rows(study, query), expected)
                self.assertEqual(rows(study, scalars), rows(local, scalars))
                self.assertEqual({r[0] for r in rows(study, "SELECT rank FROM runs")}, set(range(ranks)),
                                 "every rank ran")
                self.assertEqual(sorted(os.listdir(os.path.join(study, "runs"))), [r[0] for r in expected])
                self.assertFalse(os.path.exists(stale), "the folder of a rank that is gone was removed")

    def test_failed_crashed_and_killed_runs_are_recorded_and_the_study_completes(self):
        scenario = self.folder("crashing.yaml")
        with open(scenario, "w") as f:
            f.write(CRASHING.format(library=LIBRARY))
        # after=1 crashes (a segmentation fault) or exits with status 3; after=100 outlives the run.
        study = self.folder("crashes")
        out = subprocess.run(mpirun(3, scenario, "--vary", "nodes.a.controller.params.after=1,100", "--vary",
                                    "nodes.a.controller.params.how=segfault,exit", "--seeds", "1-3", "--jobs", "1",
                                    "-o", study), capture_output=True, text=True, timeout=300, env=ENV)
        self.assertEqual(out.returncode, 1, out.stdout + out.stderr)
        self.assertIn("12 of 12 runs done: 6 completed, 6 failed", out.stdout)
        failed = dict(rows(study, "SELECT name, error FROM runs WHERE status = 'failed'"))
        self.assertEqual(sorted(failed), sorted(f"after=1,how={how},seed={s}" for how in ("segfault", "exit")
                                                for s in (1, 2, 3)))
        for name, error in failed.items():
            cause = "killed by signal 11" if "segfault" in name else "exited with status 3"
            self.assertIn(cause, error, name)
        self.assertEqual(count(study, "status = 'completed' AND name LIKE 'after=100,%'"), 6)
        self.assertGreater(count(study, "status = 'failed' AND rank > 0"), 0, "other ranks reported failures")

    def test_a_run_killed_on_another_rank_is_failed_and_the_others_complete(self):
        study = self.folder("killed")
        sweep = subprocess.Popen(mpirun(2, SCENARIO, "--vary", "network.tx_power=28,33", "--seeds", "1-3",
                                        "--duration", "300", "--jobs", "1", "-o", study, "-q"),
                                 stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=ENV)
        victim = None

        def remote_run():  # a `sanet run` started by rank 1, from its scratch folder
            nonlocal victim
            for cmdline in glob.glob("/proc/[0-9]*/cmdline"):
                try:
                    with open(cmdline, "rb") as f:
                        command = f.read().split(b"\0")
                except OSError:
                    continue
                if len(command) > 2 and command[1] == b"run" and b"/sanet-rank-1-" in command[2]:
                    victim = (int(cmdline.split("/")[2]), command[2].decode().split("/")[-2])
                    return True
            return False
        wait_for(remote_run, 60, "a run on rank 1")
        os.kill(victim[0], signal.SIGKILL)
        output, _ = sweep.communicate(timeout=300)
        self.assertEqual(sweep.returncode, 1, output)
        self.assertEqual(count(study, "status = 'completed'"), 5)
        error = rows(study, f"SELECT status, error, rank FROM runs WHERE name = '{victim[1]}'")[0]
        self.assertEqual(error[0], "failed")
        self.assertIn("killed by signal 9", error[1])
        self.assertEqual(error[2], 1)

    def test_a_rank_with_nothing_left_to_do_costs_almost_no_cpu(self):
        # Rank 0 runs the long run itself (it starts its own first); rank 1 runs the three short
        # ones and then waits for the study's end.
        study = self.folder("idle")
        sweep = subprocess.Popen(mpirun(2, SCENARIO, "--vary", "duration=1500,20,30,40", "--seeds", "1", "--jobs",
                                        "1", "-o", study, "-q"), stdout=subprocess.PIPE,
                                 stderr=subprocess.STDOUT, text=True, env=ENV)
        try:
            wait_for(lambda: count(study, "status = 'completed'") == 3, 120, "the three short runs")
            self.assertEqual(count(study, "status = 'running' AND name = 'duration=1500,seed=1'"), 1)
            worker = rank_pid(1)
            self.assertIsNotNone(worker)
            cpu, wall = cpu_seconds(worker), time.monotonic()
            time.sleep(3)
            self.assertEqual(count(study, "status = 'running'"), 1, "the long run outlasted the measurement")
            used, waited = cpu_seconds(worker) - cpu, time.monotonic() - wall
            print(f"idle rank 1: {used:.2f} s of CPU in {waited:.2f} s", file=sys.stderr)
            self.assertLess(used, 0.1 * waited)
        finally:
            output, _ = sweep.communicate(timeout=300)
        self.assertEqual(sweep.returncode, 0, output)

    def test_stopped_half_way_it_completes_without_redoing_finished_runs(self):
        grid = ["--vary", "network.tx_power=28,30,33", "--seeds", "1-4", "--duration", "60", "--jobs", "1"]
        for how in (signal.SIGINT, signal.SIGTERM):
            with self.subTest(signal=how.name):
                study = self.folder(how.name)
                sweep = subprocess.Popen(mpirun(2, SCENARIO, *grid, "-o", study, "-q"), stdout=subprocess.PIPE,
                                         stderr=subprocess.STDOUT, text=True, env=ENV)
                wait_for(lambda: count(study, "status = 'completed'") >= 3, 120, "three runs")
                sweep.send_signal(how)
                output, _ = sweep.communicate(timeout=120)
                self.assertNotEqual(sweep.returncode, 0, output)
                before = dict(rows(study, "SELECT name, finished_utc FROM runs WHERE status = 'completed'"))
                self.assertGreaterEqual(len(before), 3)
                self.assertLess(len(before), 12)
                for log in glob.glob(os.path.join(study, "logs", "*.txt")):
                    with open(log) as f:
                        self.assertNotIn("second signal", f.read(), "a run got the stop twice")
                # A run whose results folder was complete when the stop came, but not yet recorded,
                # is taken from its folder, not run again.
                adopted = [name for name in os.listdir(os.path.join(study, "runs")) if name not in before and
                           completed_folder(os.path.join(study, "runs", name))]
                again = subprocess.run(mpirun(2, SCENARIO, *grid, "-o", study), capture_output=True, text=True,
                                       timeout=300, env=ENV)
                self.assertEqual(again.returncode, 0, again.stdout + again.stderr)
                self.assertIn(f"({12 - len(before) - len(adopted)} run by this command)", again.stdout)
                after = dict(rows(study, "SELECT name, finished_utc FROM runs WHERE status = 'completed'"))
                self.assertEqual(len(after), 12)
                for name, stamp in before.items():
                    self.assertEqual(after[name], stamp, f"{name} was run again")
                leftovers = [f for f in os.listdir(os.path.join(study, "runs")) if f not in after]
                self.assertEqual(leftovers, [])


if __name__ == "__main__":
    unittest.main(verbosity=2)
