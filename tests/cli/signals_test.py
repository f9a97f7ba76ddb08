#!/usr/bin/env python3
"""Stops from outside: SIGINT, SIGTERM and SIGHUP end `sanet run` and `sanet serve` with their
results written and marked interrupted; `sanet launch` killed outright leaves no server, agent or
program behind."""
import json
import os
import signal
import subprocess
import sys
import tempfile
import time
import unittest

SANET = sys.argv.pop(1)
SOURCE = sys.argv.pop(1)
LONG = os.path.join(SOURCE, "scenarios", "help-request.yaml")  # 3000 s simulated: many seconds of wall time


def summary(folder):
    with open(os.path.join(folder, "summary.json")) as f:
        return json.load(f)


def alive(pid):
    try:
        with open("/proc/%d/stat" % pid) as f:
            return f.read().split()[2] != "Z"
    except FileNotFoundError:
        return False


def children_of(pid):
    out = subprocess.run(["ps", "-eo", "pid=,ppid="], capture_output=True, text=True).stdout.split()
    pairs = list(zip(map(int, out[0::2]), map(int, out[1::2])))
    found, frontier = [], [pid]
    while frontier:
        parent = frontier.pop()
        for child, p in pairs:
            if p == parent:
                found.append(child)
                frontier.append(child)
    return found


class Stops(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.tmp.cleanup()

    def stop_run(self, how, *extra):
        out = os.path.join(self.tmp.name, how.name)
        process = subprocess.Popen([SANET, "run", LONG, "-q", "-o", out, *extra], stderr=subprocess.PIPE, text=True)
        time.sleep(1.5)
        process.send_signal(how)
        _, err = process.communicate(timeout=60)
        return out, process.returncode, err

    def test_each_signal_keeps_the_results_marked_interrupted(self):
        for how in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
            with self.subTest(signal=how.name):
                out, code, err = self.stop_run(how)
                self.assertEqual(code, 128 + how, err)
                s = summary(out)
                self.assertEqual(s["status"], "interrupted")
                self.assertEqual(s["ended_by"], "interrupted by " + how.name)
                self.assertGreater(s["simulated_s"], 0)
                self.assertLess(s["simulated_s"], 3000)
                self.assertEqual(s["ended_at_s"], s["simulated_s"])
                self.assertEqual([f for f in os.listdir(out) if f.endswith(".tmp")], [])
                with open(os.path.join(out, "trajectories.csv")) as f:
                    last = f.read().splitlines()[-1]
                self.assertLessEqual(float(last.split(",")[0]), s["simulated_s"] + 1e-6)
                self.assertIn("interrupted by " + how.name, err)

    def test_two_signals_at_once_are_one_request(self):
        out = os.path.join(self.tmp.name, "at-once")
        process = subprocess.Popen([SANET, "run", LONG, "-q", "-o", out], stderr=subprocess.PIPE, text=True)
        time.sleep(1.5)
        process.send_signal(signal.SIGINT)  # as `timeout` does: the process and its group
        process.send_signal(signal.SIGTERM)
        _, said = process.communicate(timeout=60)
        self.assertIn(process.returncode, (130, 143), said)  # whichever the kernel delivered first
        self.assertNotIn("second signal", said)
        self.assertEqual(summary(out)["status"], "interrupted", "the results written whole")

    def test_two_signals_end_at_once_without_half_written_files(self):
        out = os.path.join(self.tmp.name, "twice")
        process = subprocess.Popen([SANET, "run", LONG, "-q", "-o", out], stderr=subprocess.PIPE, text=True)
        time.sleep(1.5)
        process.send_signal(signal.SIGINT)
        time.sleep(1.1)  # a second request, not the same one twice
        process.send_signal(signal.SIGINT)
        _, said = process.communicate(timeout=60)
        self.assertEqual(process.returncode, 130)
        for name in os.listdir(out):  # what is there under its own name is whole
            if name == "summary.json":
                self.assertEqual(summary(out)["status"], "interrupted")
        if "summary.json" not in os.listdir(out):  # the second came before the results: it says so
            self.assertIn("second signal: stopped at once; results not written", said)

    def test_serve_stopped_by_a_signal_says_interrupted(self):
        out = os.path.join(self.tmp.name, "serve")
        process = subprocess.Popen([SANET, "serve", os.path.join(SOURCE, "scenarios", "formation-hil.yaml"), "--port",
                                    "0", "-q", "-o", out, "--duration", "120"], stdout=subprocess.PIPE,
                                   stderr=subprocess.PIPE, text=True)
        process.stdout.readline()  # "serving ..."
        time.sleep(1.0)
        process.send_signal(signal.SIGTERM)
        process.communicate(timeout=60)
        self.assertEqual(process.returncode, 143)
        s = summary(out)
        self.assertEqual(s["status"], "interrupted")
        self.assertEqual(s["ended_by"], "interrupted by SIGTERM")
        self.assertLess(s["simulated_s"], 60)

    def test_launch_killed_outright_leaves_nothing_running(self):
        out = os.path.join(self.tmp.name, "launch")
        process = subprocess.Popen([SANET, "launch", os.path.join(SOURCE, "scenarios", "formation-hil.yaml"), "-o",
                                    out, "--duration", "120"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                   text=True)
        started = time.time()
        while time.time() - started < 30 and len(children_of(process.pid)) < 5:  # the server and four agents
            time.sleep(0.2)
        children = children_of(process.pid)
        self.assertGreaterEqual(len(children), 5, children)
        process.kill()
        process.communicate()
        deadline = time.time() + 10
        while time.time() < deadline and any(alive(c) for c in children):
            time.sleep(0.2)
        self.assertEqual([c for c in children if alive(c)], [], "orphans of a killed launch")


if __name__ == "__main__":
    unittest.main(verbosity=2)
