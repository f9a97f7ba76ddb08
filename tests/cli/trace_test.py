#!/usr/bin/env python3
"""The run's trace (trace.sqlite), read as a user would, with Python's own sqlite3:
- the help-request run writes one under 20 MB whose poses, messages and transitions are the
  rows of trajectories.csv, messages.csv and transitions.csv, with radio frames of every kind
  and routing-table changes;
- switching the trace off writes none and leaves the fingerprint as it was;
- by default a run of more than 200 nodes writes none, and a switch-off is an event."""
import csv
import json
import os
import sqlite3
import subprocess
import sys
import tempfile
import unittest

SANET = sys.argv.pop(1)
SOURCE = sys.argv.pop(1)


def run(scenario, out):
    subprocess.run([SANET, "run", scenario, "-q", "-o", out], check=True)
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def rows(folder, name):
    with open(os.path.join(folder, name)) as f:
        return list(csv.DictReader(f))


class Trace(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.on = os.path.join(cls.tmp.name, "on")
        cls.summary = run(os.path.join(SOURCE, "scenarios", "help-request.yaml"), cls.on)
        cls.db = sqlite3.connect(os.path.join(cls.on, "trace.sqlite"))
        cls.names = dict(cls.db.execute("SELECT id, name FROM nodes"))

    @classmethod
    def tearDownClass(cls):
        cls.db.close()
        cls.tmp.cleanup()

    def test_it_is_small_and_listed(self):
        self.assertLess(os.path.getsize(os.path.join(self.on, "trace.sqlite")), 20e6)
        self.assertIn("trace.sqlite", self.summary["files"])
        self.assertEqual(dict(self.db.execute("SELECT key, value FROM info"))["format"], "sanet trace 1")
        self.assertEqual(len(self.names), 26)
        self.assertEqual(self.db.execute("SELECT count(*) FROM obstacles").fetchone()[0], 1)

    def test_poses_messages_and_transitions_are_the_csv_rows(self):
        poses = [(round(t, 3), self.names[n], round(x, 4), round(y, 4)) for t, n, x, y in
                 self.db.execute("SELECT t, node, x, y FROM poses")]
        csv_poses = [(float(r["time"]), r["node"], float(r["x"]), float(r["y"])) for r in rows(self.on, "trajectories.csv")]
        self.assertEqual(sorted(poses), sorted(csv_poses))
        messages = self.db.execute("SELECT count(*), sum(t_received IS NOT NULL) FROM messages").fetchone()
        delivered = [r for r in rows(self.on, "messages.csv") if r["time_received"]]
        self.assertEqual(messages, (len(rows(self.on, "messages.csv")), len(delivered)))
        transitions = [(self.names[n], a, b) for n, a, b in
                       self.db.execute("SELECT node, from_state, to_state FROM transitions ORDER BY rowid")]
        self.assertEqual(transitions, [(r["node"], r["from"], r["to"]) for r in rows(self.on, "transitions.csv")])

    def test_frames_and_routes_follow_the_network(self):
        kinds = {k for (k,) in self.db.execute("SELECT DISTINCT kind FROM frames")}
        self.assertTrue({"routing", "data", "arp", "ack"} <= kinds, kinds)
        times = [t for (t,) in self.db.execute("SELECT t FROM frames ORDER BY rowid")]
        self.assertEqual(times, sorted(times), "frames in time order")
        # Nearly every data frame a node sent to a peer was received by that peer within 10 ms.
        sent, heard = self.db.execute(
            "SELECT count(*), sum(EXISTS (SELECT 1 FROM frames r WHERE r.direction = 'rx' AND r.node = s.peer AND "
            "r.peer = s.node AND r.t BETWEEN s.t AND s.t + 0.01)) FROM frames s "
            "WHERE s.direction = 'tx' AND s.kind = 'data' AND s.peer IS NOT NULL").fetchone()
        self.assertGreater(sent, 50)
        self.assertGreater(heard / sent, 0.9)
        # The robot's route to its target appears and changes as it drives past the motes.
        robot = [i for i, n in self.names.items() if n == "robot"][0]
        routes = self.db.execute("SELECT count(*) FROM routes WHERE node = ? AND next_hop IS NOT NULL", (robot,))
        self.assertGreater(routes.fetchone()[0], 5)

    def test_a_trace_left_half_written_by_a_killed_run_does_not_stop_the_next(self):
        folder = os.path.join(self.tmp.name, "again")
        os.makedirs(folder)
        with open(os.path.join(folder, "provenance.json"), "w") as f:  # what a run writes first
            f.write("{}")
        stale = sqlite3.connect(os.path.join(folder, "trace.sqlite.tmp"))
        stale.execute("CREATE TABLE info(key TEXT PRIMARY KEY, value TEXT)")
        stale.commit()
        stale.close()
        run(os.path.join(SOURCE, "scenarios", "around-the-wall.yaml"), folder)
        self.assertFalse(os.path.exists(os.path.join(folder, "trace.sqlite.tmp")))
        with sqlite3.connect(os.path.join(folder, "trace.sqlite")) as db:
            self.assertEqual(dict(db.execute("SELECT key, value FROM info"))["format"], "sanet trace 1")

    def test_switching_it_off_writes_none_and_keeps_the_fingerprint(self):
        with open(os.path.join(SOURCE, "scenarios", "help-request.yaml")) as f:
            text = f.read().replace("outputs:\n", "outputs:\n  trace: false\n")
        path = os.path.join(self.tmp.name, "off.yaml")
        with open(path, "w") as f:
            f.write(text)
        off = os.path.join(self.tmp.name, "off")
        summary = run(path, off)
        self.assertFalse(os.path.exists(os.path.join(off, "trace.sqlite")))
        self.assertEqual(summary["fingerprint"], self.summary["fingerprint"])

    def test_large_runs_have_none_by_default_and_switch_offs_are_events(self):
        path = os.path.join(self.tmp.name, "big.yaml")
        with open(path, "w") as f:
            f.write("duration: 2\nnodes:\n  - grid: {name: m, rows: 15, cols: 15, spacing: 5}\n    model: mote\n")
        printed = subprocess.run([SANET, "validate", "--print", path], check=True, capture_output=True, text=True)
        self.assertIn("trace: false", printed.stdout)
        small = os.path.join(self.tmp.name, "small.yaml")
        with open(small, "w") as f:
            f.write("duration: 2\nnodes:\n  - {name: a, model: mote, pose: [0, 0, 0]}\n"
                    "events:\n  - {time: 1, node: a, action: switch_off}\n")
        out = os.path.join(self.tmp.name, "small")
        run(small, out)
        with sqlite3.connect(os.path.join(out, "trace.sqlite")) as db:
            self.assertEqual(db.execute("SELECT t, node, kind FROM events WHERE kind = 'switch_off'").fetchall(),
                             [(1.0, 0, "switch_off")])


if __name__ == "__main__":
    unittest.main(verbosity=2)
