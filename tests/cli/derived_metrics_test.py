#!/usr/bin/env python3
"""`sanet report` over the data-mule scenario's study: a derived ratio equals the same ratio
computed by hand from each run's metrics.csv; folded per-node metrics equal the sums and means a
script computes from the same files; several metrics share a plot with the labels given; and
sanet.Study's frames merge on run_id. Mistakes in expressions are refused with their place."""
import csv
import os
import statistics
import subprocess
import sys
import tempfile
import unittest
import xml.dom.minidom

SANET, SOURCE, MODULES = sys.argv[1:4]
del sys.argv[1:4]
SCENARIO = os.path.join(SOURCE, "scenarios", "data-mule.yaml")
SPEED = "nodes.mule.controller.params.speed"
DELIVERY = "delivery=metrics.mule.delivered.count / sum(metrics.m*.created.count)"


def sanet(*args):
    return subprocess.run([SANET, *args], capture_output=True, text=True, timeout=600)


def metric_rows(run_folder):
    with open(os.path.join(run_folder, "metrics.csv")) as f:
        return list(csv.DictReader(f))


def csv_rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


class DerivedMetrics(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.study = os.path.join(cls.tmp.name, "study")
        done = sanet("sweep", SCENARIO, "--vary", f"{SPEED}=1,2", "--set", "nodes.mule.body.max_speed=2",
                     "--seeds", "1-3", "--duration", "400", "-o", cls.study, "-q")
        assert done.returncode == 0, done.stderr
        cls.runs = {r["run_name"]: r for r in csv_rows(cls.export(cls, "all.csv"))}

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def export(self, name, *args):
        path = os.path.join(self.tmp.name, name)
        done = sanet("report", self.study, "--csv", path, *args)
        assert done.returncode == 0, done.stderr
        return path

    def folder(self, run_name):
        return os.path.join(self.study, "runs", run_name)

    def by_hand(self, run_name):
        """created per mote and the mule's deliveries, from the run's metrics.csv"""
        created, delivered, held = {}, 0, {}
        for row in metric_rows(self.folder(run_name)):
            if row["name"] == "created":
                created[row["node"]] = created.get(row["node"], 0) + 1
            elif row["name"] == "delivered" and row["node"] == "mule":
                delivered += 1
            elif row["name"] == "held_at_end":
                held[row["node"]] = float(row["value"])
        return created, delivered, held

    def test_a_derived_ratio_equals_the_ratio_computed_from_metrics_csv(self):
        table = csv_rows(self.export("ratio.csv", "--derive", DELIVERY, "-m", "delivery"))
        self.assertEqual(len(table), 6)
        ratios = {}
        for row in table:
            created, delivered, _ = self.by_hand(row["run_name"])
            self.assertEqual(len(created), 30)
            self.assertGreater(delivered, 0)
            self.assertAlmostEqual(float(row["delivery"]), delivered / sum(created.values()), places=5)
            ratios.setdefault(row[SPEED], []).append(delivered / sum(created.values()))
        spaced = DELIVERY.replace("=", " = ", 1)  # spaces around NAME and EXPRESSION are allowed
        printed = sanet("report", self.study, "--derive", spaced, "-m", "delivery", "--by", "speed")
        self.assertEqual(printed.returncode, 0, printed.stderr)
        for speed, values in ratios.items():
            line = next(l.split() for l in printed.stdout.splitlines() if l.split()[:1] == [speed])
            self.assertEqual(int(line[1]), 3)
            self.assertAlmostEqual(float(line[2]), statistics.mean(values), places=5)

    def test_folded_per_node_metrics_are_the_sum_and_mean_of_the_nodes(self):
        listed = sanet("report", self.study, "--list")
        self.assertIn("sum(metrics.*.created.count)", listed.stdout)
        self.assertIn("(30 nodes)", listed.stdout)
        self.assertNotIn("metrics.m7.created.count", listed.stdout, "folded by default")
        self.assertIn("metrics.mule.delivered.count", listed.stdout, "one node's metric keeps its name")
        self.assertIn("metrics.m7.created.count", sanet("report", self.study, "--list", "--per-node").stdout)
        for run_name, row in self.runs.items():
            created, _, held = self.by_hand(run_name)
            self.assertEqual(float(row["sum(metrics.*.created.count)"]), sum(created.values()))
            self.assertAlmostEqual(float(row["mean(metrics.*.held_at_end.mean)"]), statistics.mean(held.values()))
            self.assertEqual(float(row["max(metrics.*.held_at_end.max)"]), max(held.values()))
            self.assertNotIn("metrics.m7.created.count", row)
            self.assertEqual(list(row).count("seed"), 1, "summary.json's seed is the seed column")
        per_node = csv_rows(self.export("per-node.csv", "--per-node"))
        self.assertIn("metrics.m7.created.count", per_node[0])

    def test_every_reading_made_is_delivered_held_or_overflowed(self):
        """A reading whose acknowledgement was lost, or was on its way when the run ended, is both
        delivered and held: at most one batch (20) per mote."""
        for run_name in self.runs:
            rows = metric_rows(self.folder(run_name))
            total = lambda name: sum(float(r["value"]) for r in rows if r["name"] == name)
            self.assertGreater(total("delivered"), 0)
            both = total("delivered") + total("held_at_end") + total("overflowed") - total("created")
            self.assertGreaterEqual(both, 0, run_name)
            self.assertLessEqual(both, 20 * 30, run_name)
            for name in ("held_at_end", "overflowed", "motes_heard"):
                nodes = [r["node"] for r in rows if r["name"] == name]
                self.assertEqual(len(nodes), len(set(nodes)), f"{name}: Finish reports once per node")
            self.assertEqual(len([r for r in rows if r["name"] == "overflowed"]), 30, "even when 0")
        row = csv_rows(self.export("overflow.csv", "-m", "sum(metrics.m*.overflowed.sum)"))[0]
        self.assertEqual(float(row["sum(metrics.m*.overflowed.sum)"]), 0)

    def test_several_metrics_share_one_plot_with_its_labels(self):
        svg = os.path.join(self.tmp.name, "two.svg")
        done = sanet("report", self.study, "--derive", DELIVERY, "-m", "delivery", "-m",
                     "sum(metrics.*.held_at_end.sum) / sum(metrics.*.created.count)", "--plot", svg,
                     "--title", "A mule's harvest", "--ylabel", "share of readings")
        self.assertEqual(done.returncode, 0, done.stderr)
        def text(node):  # PLplot's SVG puts a label's text in nested tspans
            return "".join(c.data if c.nodeType == c.TEXT_NODE else text(c) for c in node.childNodes)
        texts = [text(t) for t in xml.dom.minidom.parse(svg).getElementsByTagName("text")]
        for label in ("A mule's harvest", "share of readings", "speed", "delivery",
                      "sum(metrics.*.held_at_end.sum) / sum(metrics.*.created.count)"):
            self.assertIn(label, texts)
        self.assertNotIn(SPEED, texts, "the axis says the parameter's last part")

    def test_mistakes_are_refused_with_their_place(self):
        for args, message in [(["-m", "metrics.*.created.count"], "aggregate it, e.g. sum(metrics.*.created.count)"),
                              (["-m", "sum(metrics.*.craeted.count)"], "did you mean"),
                              (["--derive", "d=sum(", "-m", "d"], "at character 5"),
                              (["--derive", "ended_at_s=1", "-m", "ended_at_s"], "already a metric"),
                              (["--derive", "nothing", "-m", "x"], "NAME=EXPRESSION"),
                              (["--derive", "2x=1", "-m", "2x"], "is not a name")]:
            done = sanet("report", self.study, *args)
            self.assertNotEqual(done.returncode, 0, args)
            self.assertIn(message, done.stderr, args)

    def test_study_frames_merge_on_run_id(self):
        code = f"""
import sys; sys.path.insert(0, {MODULES!r})
import sanet
s = sanet.Study({self.study!r})
runs, scalars = s.runs, s.scalars
assert "run_id" in runs.columns and "run_name" in runs.columns and "run" not in runs.columns, runs.columns
assert scalars.index.name == "run_id"
merged = runs.merge(scalars, left_on="run_id", right_index=True, suffixes=("", "_summary"))
assert len(merged) == 6 and (merged["seed"] == merged["seed_summary"]).all(), merged
values = s.values("delivery", derive={{"delivery": {DELIVERY.split("=", 1)[1]!r}}})
assert len(values) == 6 and values.index.name == "run_id"
table = s.report("delivery", by="speed")
assert list(table["runs"]) == [3, 3], table
assert "sum(metrics.*.created.count)" in s.metrics and "metrics.m7.created.count" in s.per_node_metrics
print("ok")
"""
        done = subprocess.run(["/usr/bin/python3", "-c", code], capture_output=True, text=True, timeout=120)
        self.assertEqual(done.stdout.strip(), "ok", done.stderr)


if __name__ == "__main__":
    unittest.main()
