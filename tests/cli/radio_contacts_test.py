#!/usr/bin/env python3
"""radio_contacts.csv as a user gets it: a robot drives back and forth past a mote, both sending
periodically (the mote's pinger broadcasts, both nodes' AODV hellos). The contacts are derived
here from the frames trace.sqlite holds (docs/trace.md) and must equal the file's rows exactly;
summary.json's numbers must agree with the rows; the default is on with a 15 s silence; the
file never changes the fingerprint; and a run stopped by a signal still writes what it has."""
import csv
import json
import os
import signal
import sqlite3
import statistics
import subprocess
import sys
import tempfile
import time
import unittest

SANET = sys.argv.pop(1)
SILENCE = 3.0
# Frames cross about 21 m at 5 dBm; the robot drives at 1 m/s between x = -40 and 40, passing the
# mote at 40, 120 and 200 s: three contacts, the last one still open when the run ends.
SCENARIO = """name: pass-by
duration: 200
network: {radio: 802.11b, tx_power: 5, routing: aodv}
nodes:
  - name: mote
    model: mote
    pose: [0, 0, 0]
    controller: {name: pinger, params: {to: broadcast, interval: 2, start: 0.5}}
  - name: robot
    model: omni3
    pose: [-40, 3, 0]
    controller: {name: tour, params: {points: [[40, 3], [-40, 3]], loop: true, speed: 1.0}}
"""


def expected_contacts(trace, silence, run_end):
    """Contacts from the trace's frames: a pair's frames (either way) no more than `silence` apart."""
    db = sqlite3.connect(trace)
    names = dict(db.execute("SELECT id, name FROM nodes"))
    current, done = {}, []
    for t, receiver, transmitter in db.execute(
            "SELECT t, node, peer FROM frames WHERE direction = 'rx' AND peer IS NOT NULL ORDER BY rowid"):
        pair = (min(receiver, transmitter), max(receiver, transmitter))
        c = current.get(pair)
        if c is not None and t - c["end"] > silence:
            done.append(c)
            c = None
        if c is None:
            c = current[pair] = {"a": pair[0], "b": pair[1], "start": t, "end": t, "ab": 0, "ba": 0}
        c["end"] = t
        c["ab" if transmitter == pair[0] else "ba"] += 1
    db.close()
    for c in current.values():
        c["open"] = run_end - c["end"] <= silence
    rows = sorted(done + list(current.values()), key=lambda c: (c["start"], c["a"], c["b"]))
    return [{"a": names[c["a"]], "b": names[c["b"]], "start_s": "%.6f" % c["start"], "end_s": "%.6f" % c["end"],
             "frames": str(c["ab"] + c["ba"]), "frames_a_to_b": str(c["ab"]), "frames_b_to_a": str(c["ba"]),
             "open": "1" if c.get("open") else "0"} for c in rows]


def read_rows(folder):
    with open(os.path.join(folder, "radio_contacts.csv")) as f:
        return list(csv.DictReader(f))


def summary(folder):
    with open(os.path.join(folder, "summary.json")) as f:
        return json.load(f)


class RadioContacts(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.path = os.path.join(cls.tmp.name, "pass-by.yaml")
        with open(cls.path, "w") as f:
            f.write(SCENARIO)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def run_sanet(self, tag, *sets):
        out = os.path.join(self.tmp.name, tag)
        command = [SANET, "run", self.path, "-q", "-o", out]
        for s in sets:
            command += ["--set", s]
        subprocess.run(command, check=True)
        return out

    def test_the_file_agrees_with_the_frames_in_the_trace(self):
        out = self.run_sanet("silence3", "outputs.radio_contacts.silence_s=%g" % SILENCE)
        rows = read_rows(out)
        s = summary(out)
        self.assertEqual(rows, expected_contacts(os.path.join(out, "trace.sqlite"), SILENCE, s["simulated_s"]))
        self.assertEqual(len(rows), 3, rows)
        self.assertEqual([r["open"] for r in rows], ["0", "0", "1"])
        for r in rows:
            self.assertEqual((r["a"], r["b"]), ("mote", "robot"), "a and b in node order")
            self.assertGreater(int(r["frames_a_to_b"]), 10)
            self.assertGreater(int(r["frames_b_to_a"]), 10)
        self.check_summary(s["radio_contacts"], rows)

    def check_summary(self, contacts, rows):
        self.assertEqual(contacts["silence_s"], SILENCE)
        self.assertEqual((contacts["contacts"], contacts["open"], contacts["pairs"]), (3, 1, 1))
        durations = [float(r["end_s"]) - float(r["start_s"]) for r in rows if r["open"] == "0"]
        self.assertEqual(contacts["duration_s"]["count"], 2, "the open contact's duration is left out")
        self.assertAlmostEqual(contacts["duration_s"]["median"], statistics.median(durations), places=5)
        gaps = [float(b["start_s"]) - float(a["end_s"]) for a, b in zip(rows, rows[1:])]
        self.assertEqual(contacts["inter_contact_s"]["count"], 2)
        self.assertAlmostEqual(contacts["inter_contact_s"]["min"], min(gaps), places=5)
        self.assertAlmostEqual(contacts["inter_contact_s"]["max"], max(gaps), places=5)

    def test_on_by_default_and_never_in_the_fingerprint(self):
        default = self.run_sanet("default")
        off = self.run_sanet("off", "outputs.radio_contacts=false")
        no_trace = self.run_sanet("no-trace", "outputs.trace=false")
        s = summary(default)
        self.assertEqual(s["radio_contacts"]["silence_s"], 15)
        self.assertIn("radio_contacts.csv", s["files"])
        self.assertEqual(read_rows(default), expected_contacts(os.path.join(default, "trace.sqlite"), 15,
                                                               s["simulated_s"]))
        self.assertFalse(os.path.exists(os.path.join(off, "radio_contacts.csv")))
        self.assertNotIn("radio_contacts", summary(off))
        self.assertEqual(read_rows(no_trace), read_rows(default), "the same contacts without the trace")
        self.assertEqual({summary(f)["fingerprint"] for f in (default, off, no_trace)}, {s["fingerprint"]})

    def test_a_stopped_run_writes_the_contacts_it_had(self):
        out = os.path.join(self.tmp.name, "stopped")
        process = subprocess.Popen([SANET, "run", self.path, "-q", "-o", out, "--duration", "100000"])
        time.sleep(2.0)
        process.send_signal(signal.SIGINT)
        process.wait(timeout=60)
        s = summary(out)
        self.assertEqual(s["status"], "interrupted")
        rows = read_rows(out)
        self.assertGreater(len(rows), 0, "two seconds of wall time pass the mote at least once")
        self.assertEqual(rows, expected_contacts(os.path.join(out, "trace.sqlite"), 15, s["simulated_s"]))
        self.assertTrue(all(float(r["end_s"]) <= s["simulated_s"] for r in rows))
        self.assertEqual([f for f in os.listdir(out) if f.endswith(".tmp")], [])


if __name__ == "__main__":
    unittest.main()
