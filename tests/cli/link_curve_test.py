#!/usr/bin/env python3
"""`sanet link-curve` against the model it measures, as a user runs it.

Zuniga and Krishnamachari (SECON 2004) derive that with log-distance path loss and log-normal
shadowing of deviation sigma, the share of links at distance d whose packet reception ratio is at
least 0.5 is Q((P50 - Pbar(d)) / sigma), P50 being the received power at which the PRR is 0.5
without shadowing. The test measures P50 with the command (sigma 0), then the share at sigma 2, 4
and 8 dB over 1,000 links per distance, against the formula within 0.05. It also checks the
regions, the files, reproducibility, walls (--along), fading, errors and an interrupted curve."""
import csv
import json
import math
import os
import signal
import subprocess
import sys
import tempfile
import time
import unittest
import xml.etree.ElementTree as ET

SANET = sys.argv.pop(1)
SCENARIO = """name: radio
duration: 10
world:
  obstacles:
    - wall: {from: [15, -5], to: [15, 5], height: 2, radio_loss_db: 10}
network:
  tx_power: 5
nodes:
  - {name: a, model: mote, pose: [0, 0, 0]}
"""


def q_function(x):
    return 0.5 * math.erfc(x / math.sqrt(2))


class LinkCurve(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.scenario = os.path.join(cls.tmp.name, "radio.yaml")
        with open(cls.scenario, "w") as f:
            f.write(SCENARIO)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def curve(self, name, *args, check=True, scenario=None):
        out = os.path.join(self.tmp.name, name)
        done = subprocess.run([SANET, "link-curve", scenario or self.scenario, "-o", out, "--force", *args],
                              capture_output=True, text=True)
        if check:
            self.assertEqual(done.returncode, 0, done.stderr)
        rows = []
        if os.path.exists(os.path.join(out, "link_curve.csv")):
            with open(os.path.join(out, "link_curve.csv")) as f:
                rows = [{k: float(v) if v else None for k, v in row.items()} for row in csv.DictReader(f)]
        summary = None
        if os.path.exists(os.path.join(out, "link_curve.json")):
            with open(os.path.join(out, "link_curve.json")) as f:
                summary = json.load(f)
        return done, rows, summary, out

    def test_share_of_good_links_follows_the_q_function(self):
        _, rows, summary, _ = self.curve("p50", "--links", "1", "--frames", "4", "--from", "18", "--to", "26",
                                         "--step", "0.25")
        self.assertEqual([r["prr"] for r in rows if r["mean_dbm"] > -81.9], [1.0] * sum(r["mean_dbm"] > -81.9 for r in rows))
        p50 = summary["p50_dbm"]
        self.assertAlmostEqual(p50, -82, delta=0.3, msg="without shadowing, half the frames arrive at rx_threshold")
        table = []
        for sigma in (2, 4, 8):
            _, rows, _, _ = self.curve(f"sigma{sigma}", "--links", "1000", "--frames", "4", "--from", "5", "--to",
                                       "65", "--step", "5", "--set", f"network.propagation.shadowing.sigma_db={sigma}")
            for r in rows:
                expected = q_function((p50 - r["mean_dbm"]) / sigma)
                table.append((sigma, r["distance_m"], expected, r["share_prr_ge_50"]))
                self.assertAlmostEqual(r["share_prr_ge_50"], expected, delta=0.05,
                                       msg=f"sigma {sigma} dB at {r['distance_m']} m")
        transitional = [t for t in table if 0.1 < t[2] < 0.9]
        self.assertGreater(len(transitional), 8, "the distances cover the transitional regions")

    def test_regions_files_and_figure(self):
        done, rows, summary, out = self.curve("regions", "--links", "200", "--frames", "10", "--set",
                                              "network.propagation.shadowing.sigma_db=4")
        self.assertIn("connected up to", done.stdout)
        self.assertEqual(summary["status"], "completed")
        connected, disconnected = summary["regions"]["connected_to_m"], summary["regions"]["disconnected_from_m"]
        self.assertLess(connected, disconnected)
        for r in rows:
            self.assertEqual(r["links"], 200)
            self.assertEqual(r["frames_sent"], 2000)
            if r["distance_m"] <= connected:
                self.assertGreaterEqual(r["share_prr_ge_90"], 0.95)
            if r["distance_m"] >= disconnected:
                self.assertLessEqual(r["share_prr_gt_10"], 0.05)
        self.assertLess(rows[0]["distance_m"], connected, "the default distances start in the connected region")
        self.assertGreater(rows[-1]["distance_m"], disconnected, "... and end in the disconnected one")
        with open(os.path.join(out, "link_curve_links.csv")) as f:
            links = list(csv.DictReader(f))
        self.assertEqual(len(links), 200 * len(rows))
        svg = ET.parse(os.path.join(out, "link_curve.svg")).getroot()
        texts = [t.text for t in svg.iter("{http://www.w3.org/2000/svg}text")]
        for region in ("connected", "transitional", "disconnected"):
            self.assertIn(region, texts)

    def test_an_802154_network_is_measured_on_its_own_radio(self):
        """0 dBm against -95 dBm over the log-distance path loss: 10^((0 + 95 - 46.6777) / 30) = 40.8 m."""
        scenario = os.path.join(self.tmp.name, "lr-wpan.yaml")
        with open(scenario, "w") as f:
            f.write("name: motes\nduration: 10\nnetwork: {radio: 802.15.4}\n"
                    "nodes:\n  - {name: a, model: mote, pose: [0, 0, 0]}\n")
        done, rows, summary, _ = self.curve("lr-wpan", "--links", "5", "--frames", "5", scenario=scenario)
        self.assertEqual(summary["status"], "completed", done.stderr)
        edge = 10 ** ((0 + 95 - 46.6777) / 30)
        for r in rows:
            self.assertEqual(r["prr"], 1.0 if r["distance_m"] < edge else 0.0, r)
            if r["prr"] == 1.0:
                self.assertAlmostEqual(r["rssi_median_dbm"], r["mean_dbm"], places=3)
        self.assertGreater(rows[-1]["distance_m"], edge)
        self.assertAlmostEqual(summary["p50_dbm"], -95, delta=0.7)

    def test_the_same_seed_gives_the_same_curve_and_another_another(self):
        args = ["--links", "30", "--frames", "5", "--set", "network.propagation.shadowing.sigma_db=6"]
        outs = [self.curve(name, *args, *extra)[3] for name, extra in
                (("seed-a", []), ("seed-b", []), ("seed-c", ["--seed", "99"]))]
        text = []
        for o in outs:
            with open(os.path.join(o, "link_curve_links.csv")) as f:
                text.append(f.read())
        self.assertEqual(text[0], text[1])
        self.assertNotEqual(text[0], text[2])

    def test_fading_spreads_each_links_reception_and_strength(self):
        args = ["--links", "50", "--frames", "40", "--from", "5", "--to", "25", "--step", "5"]
        _, steady, _, _ = self.curve("steady", *args)
        _, faded, _, _ = self.curve("faded", *args, "--set", "network.propagation.fading.model=rayleigh")
        self.assertTrue(all(r["prr"] in (0.0, 1.0) for r in steady), "without fading a link is all or nothing")
        partial = [r for r in faded if 0.1 < r["prr"] < 0.9]
        self.assertTrue(partial, "with Rayleigh fading, links near the edge deliver some frames")
        near = lambda rows: next(r for r in rows if r["distance_m"] == 5)
        self.assertLess(near(steady)["rssi_q3_dbm"] - near(steady)["rssi_q1_dbm"], 0.01)
        self.assertGreater(near(faded)["rssi_q3_dbm"] - near(faded)["rssi_q1_dbm"], 3,
                           "Rayleigh power's quartiles lie 6.7 dB apart")

    def test_frames_asked_faster_than_the_air_takes_them_are_not_counted_as_sent(self):
        _, rows, _, _ = self.curve("hurried", "--links", "2", "--frames", "2000", "--interval", "0.0001", "--from",
                                   "10", "--to", "10", "--step", "10")
        self.assertLess(rows[0]["frames_sent"], 2 * 2000, "a 64-byte broadcast takes over a millisecond at 1 Mbps")
        self.assertGreater(rows[0]["prr"], 0.99, "what was sent arrived, 10 m away")

    def test_along_a_line_through_a_wall(self):
        args = ["--links", "1", "--frames", "4", "--from", "5", "--to", "30", "--step", "5"]
        _, open_air, _, _ = self.curve("open", *args)
        _, walled, summary, _ = self.curve("walled", *args, "--along", "0,0,1,0")
        self.assertEqual(summary["along"], [0, 0, 1, 0])
        for a, w in zip(open_air, walled):
            if a["distance_m"] < 15:
                self.assertEqual(a["rssi_median_dbm"], w["rssi_median_dbm"])
            elif w["rssi_median_dbm"] is not None:
                self.assertAlmostEqual(a["rssi_median_dbm"] - w["rssi_median_dbm"], 10, places=6)
        self.assertLess(sum(r["prr"] for r in walled), sum(r["prr"] for r in open_air))

    def test_bad_input_is_refused_clearly(self):
        no_network = os.path.join(self.tmp.name, "quiet.yaml")
        with open(no_network, "w") as f:
            f.write("duration: 5\nnodes:\n  - {name: a, model: mote, pose: [0, 0, 0]}\n")
        done = subprocess.run([SANET, "link-curve", no_network], capture_output=True, text=True)
        self.assertEqual(done.returncode, 2)
        self.assertIn("has no `network`", done.stderr)
        done, _, _, _ = self.curve("bad-along", "--along", "1,2,3", check=False)
        self.assertEqual(done.returncode, 2)
        self.assertIn("--along", done.stderr)
        done, _, _, _ = self.curve("bad-range", "--from", "40", "--to", "20", check=False)
        self.assertIn("--from", done.stderr)
        done, _, _, _ = self.curve("bad-step", "--step", "0.001", "--to", "100", check=False)
        self.assertEqual(done.returncode, 2)
        self.assertIn("longer step", done.stderr)
        done, _, _, _ = self.curve("zero-step", "--step", "0", check=False)
        self.assertEqual(done.returncode, 2)
        self.assertIn("--step", done.stderr)
        done, _, _, _ = self.curve("same-points", "--along", "5,5,5,5", check=False)
        self.assertIn("the same", done.stderr)
        other = os.path.join(self.tmp.name, "other")
        os.makedirs(other, exist_ok=True)
        open(os.path.join(other, "notes.txt"), "w").close()
        done = subprocess.run([SANET, "link-curve", self.scenario, "-o", other], capture_output=True, text=True)
        self.assertEqual(done.returncode, 2)
        self.assertIn("other files", done.stderr)

    def test_an_interrupted_curve_keeps_what_it_measured(self):
        out = os.path.join(self.tmp.name, "stopped")
        process = subprocess.Popen([SANET, "link-curve", self.scenario, "-o", out, "--links", "100000"],
                                   stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        time.sleep(2)
        process.send_signal(signal.SIGINT)
        _, err = process.communicate(timeout=60)
        self.assertEqual(process.returncode, 130)
        self.assertIn("interrupted", err)
        with open(os.path.join(out, "link_curve.json")) as f:
            summary = json.load(f)
        self.assertEqual(summary["status"], "interrupted")
        self.assertGreater(summary["sets"]["done"], 0)
        with open(os.path.join(out, "link_curve.csv")) as f:
            rows = list(csv.DictReader(f))
        self.assertEqual(int(rows[0]["links"]), summary["sets"]["done"])


if __name__ == "__main__":
    unittest.main()
