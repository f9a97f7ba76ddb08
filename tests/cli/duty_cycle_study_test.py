#!/usr/bin/env python3
"""studies/duty-cycle/run at small size (always awake and awake 2 s of 10, two seeds, 450 s): the
sweep and its reports complete; every mote dies; the duty-cycled motes live longer and wait
longer; the derived delivery ratio is in [0, 1] and equals the ratio counted from each run's
files; the figures carry their labels; run again, the study runs nothing."""
import csv
import json
import os
import subprocess
import sys
import tempfile
import unittest
import xml.dom.minidom

SANET, SOURCE = sys.argv[1:3]
del sys.argv[1:3]
RUN = os.path.join(SOURCE, "studies", "duty-cycle", "run")
AWAKE = "nodes.m.radio.duty_cycle.awake_s"


def study(out):
    return subprocess.run([RUN, "--awake", "10,2", "--seeds", "1-2", "--duration", "450", "--jobs", "2", "-o", out],
                          capture_output=True, text=True, timeout=600, env={**os.environ, "SANET": SANET})


def svg_texts(path):
    def text(node):  # PLplot's SVG puts a label's text in nested tspans
        return "".join(c.data if c.nodeType == c.TEXT_NODE else text(c) for c in node.childNodes)
    return [text(t) for t in xml.dom.minidom.parse(path).getElementsByTagName("text")]


class DutyCycleStudy(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.out = os.path.join(cls.tmp.name, "duty-cycle")
        cls.done = study(cls.out)
        assert cls.done.returncode == 0, cls.done.stdout + cls.done.stderr
        with open(os.path.join(cls.out, "runs.csv")) as f:
            cls.rows = list(csv.DictReader(f))

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def by_seed(self, metric):
        """{seed: {awake_s: value}}"""
        table = {}
        for row in self.rows:
            table.setdefault(row["seed"], {})[float(row[AWAKE])] = float(row[metric])
        return table

    def test_every_run_completes_and_every_mote_dies(self):
        self.assertEqual(len(self.rows), 4)
        for row in self.rows:
            self.assertEqual(row["status"], "completed", row["run_name"])
            with open(os.path.join(self.out, "runs", row["run_name"], "summary.json")) as f:
                lifetime = json.load(f)["energy"]["lifetime"]
            self.assertEqual(lifetime["nodes"], 12, row["run_name"])
            self.assertEqual(lifetime["dead"], 12, row["run_name"])
            self.assertAlmostEqual(float(row["first_death_s"]), lifetime["first_death_s"], places=3)
            self.assertAlmostEqual(float(row["half_dead_s"]), lifetime["half_dead_s"], places=3)
        for name in ("first_death_s by", "half_dead_s by", "delivery_ratio by", "delay_s by"):
            self.assertIn(name, self.done.stdout)

    def test_a_duty_cycled_mote_lives_longer_and_waits_longer(self):
        deaths, halves, delays = self.by_seed("first_death_s"), self.by_seed("half_dead_s"), self.by_seed("delay_s")
        for seed in deaths:
            self.assertGreater(deaths[seed][2], 2 * deaths[seed][10], seed)
            self.assertGreaterEqual(halves[seed][2], deaths[seed][2], seed)
            self.assertGreater(delays[seed][2], delays[seed][10], seed)
            self.assertLess(delays[seed][2], 10, f"{seed}: a report waits at most about a period")

    def test_the_delivery_ratio_is_the_share_of_reports_received(self):
        for row in self.rows:
            ratio = float(row["delivery_ratio"])
            self.assertGreaterEqual(ratio, 0)
            self.assertLessEqual(ratio, 1)
            folder = os.path.join(self.out, "runs", row["run_name"])
            with open(os.path.join(folder, "messages.csv")) as f:
                received = sum(1 for r in csv.DictReader(f) if r["to"] == "sink")
            sent = 0
            for name in os.listdir(os.path.join(folder, "packets")):
                if name != "sink.csv":
                    with open(os.path.join(folder, "packets", name)) as f:
                        sent += sum(1 for r in csv.DictReader(f) if r["event"] == "sent")
            self.assertGreater(sent, 0)
            self.assertAlmostEqual(ratio, received / sent, places=5, msg=row["run_name"])
            self.assertEqual(float(row["network.packets.messages_sent"]), sent)

    def test_the_figures_carry_their_labels(self):
        for figure, labels in (("lifetime.svg", ["first_death_s", "half_dead_s", "lifetime (s)"]),
                               ("delivery.svg", ["reports received / sent"]),
                               ("delay.svg", ["mean delay of a report (s)"])):
            texts = svg_texts(os.path.join(self.out, figure))
            for label in labels + ["radio awake per 10 s period (s)"]:
                self.assertIn(label, texts, figure)

    def test_run_again_it_runs_nothing(self):
        again = study(self.out)
        self.assertEqual(again.returncode, 0, again.stderr)
        self.assertIn("(0 run by this command)", again.stdout + again.stderr)


if __name__ == "__main__":
    unittest.main()
