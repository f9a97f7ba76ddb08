#!/usr/bin/env python3
"""The abstract radio (network.radio_model: abstract) as a user meets it from the command line.

- Its delivery against distance matches the table it was calibrated with: the full 802.11 model's
  link curve (Nakagami fading, no shadowing) is written as calibration.csv by `sanet link-curve`,
  given to a scenario as network.calibration, and the abstract radio's own link curve delivers
  at each distance the table's PRR at that distance's mean power, within four binomial standard
  deviations; beyond the full curve's last distance with anything delivered, nothing arrives.
- With shadowing, both models' curves agree within 0.05 at every distance.
- `validate` and `validate --print` say where the calibration comes from; a file's rows travel in
  the effective scenario, which runs to the same fingerprint; bad files are refused with the file,
  line and column."""
import bisect
import csv
import json
import math
import os
import subprocess
import sys
import tempfile
import unittest

SANET = sys.argv.pop(1)
RADIO = """name: grey
duration: 20
network:
  tx_power: 10
  propagation:
    fading: {model: nakagami, m: 1.5}
nodes:
  - {name: a, model: mote, pose: [0, 0, 0]}
"""
LINKS = ["--links", "60", "--frames", "50"]


def read_curve(folder):
    with open(os.path.join(folder, "link_curve.csv")) as f:
        return [{k: float(v) if v else None for k, v in row.items()} for row in csv.DictReader(f)]


def read_table(path):
    with open(path) as f:
        rows = [line for line in f if not line.startswith("#")]
    return [(float(r["mean_dbm"]), float(r["prr"])) for r in csv.DictReader(rows)]


def table_prr(table, dbm):
    """The table's PRR at `dbm`, interpolated as the abstract channel does."""
    powers = [p for p, _ in table]
    heard = next(i for i, (_, prr) in enumerate(table) if prr > 0)
    if dbm < powers[max(0, heard - 1)]:
        return 0.0
    if dbm <= powers[0]:
        return table[0][1]
    if dbm >= powers[-1]:
        return table[-1][1]
    i = bisect.bisect_right(powers, dbm)
    (p0, r0), (p1, r1) = table[i - 1], table[i]
    return r0 + (dbm - p0) / (p1 - p0) * (r1 - r0)


class AbstractRadio(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.env = dict(os.environ, SANET_CACHE=os.path.join(cls.tmp.name, "cache"))
        cls.scenario = cls.write("grey.yaml", RADIO)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    @classmethod
    def write(cls, name, text):
        path = os.path.join(cls.tmp.name, name)
        with open(path, "w") as f:
            f.write(text)
        return path

    def sanet(self, *args, check=True):
        done = subprocess.run([SANET, *args], capture_output=True, text=True, env=self.env)
        if check:
            self.assertEqual(done.returncode, 0, done.stderr)
        return done

    def curve(self, name, *args, scenario=None):
        out = os.path.join(self.tmp.name, name)
        self.sanet("link-curve", scenario or self.scenario, "-o", out, "--force", "-q", *args)
        return out

    def test_delivery_against_distance_follows_the_calibrating_curve(self):
        full = self.curve("full", *LINKS)
        table_file = os.path.join(full, "calibration.csv")
        self.assertTrue(os.path.exists(table_file), "a curve without shadowing calibrates")
        table = read_table(table_file)
        scenario = self.write("given.yaml", RADIO.replace("network:\n", "network:\n  radio_model: abstract\n"
                                                          "  calibration: %s\n" % table_file))
        abstract = read_curve(self.curve("abstract", "--links", "200", "--frames", "50", scenario=scenario))
        measured = read_curve(full)
        last_heard = max(r["distance_m"] for r in measured if r["prr"] > 0)
        checked = 0
        for row in abstract:
            frames = row["frames_sent"]
            self.assertEqual(frames, 200 * 50)
            expected = table_prr(table, row["mean_dbm"])
            sigma = math.sqrt(expected * (1 - expected) / frames)
            self.assertLessEqual(abs(row["prr"] - expected), 4 * sigma + 1e-9,
                                 "at %g m (%.2f dBm)" % (row["distance_m"], row["mean_dbm"]))
            if row["distance_m"] > last_heard:
                self.assertEqual(row["frames_received"], 0, "beyond the curve's last distance heard")
                checked += 1
            if 0.05 < expected < 0.95:
                checked += 1
        self.assertGreaterEqual(checked, 6, "the curve crosses its grey zone and goes beyond it")

    def test_with_shadowing_both_models_agree_within_five_points(self):
        text = RADIO.replace("    fading:", "    shadowing: {sigma_db: 6}\n    fading:")
        scenario = self.write("shadowed.yaml", text)
        full = read_curve(self.curve("shadowed-full", "--links", "150", scenario=scenario))
        self.assertFalse(os.path.exists(os.path.join(self.tmp.name, "shadowed-full", "calibration.csv")),
                         "a curve with shadowing does not calibrate: the abstract radio adds its own")
        abstract = read_curve(self.curve("shadowed-abstract", "--links", "150", "--set",
                                         "network.radio_model=abstract", scenario=scenario))
        self.assertEqual([r["distance_m"] for r in full], [r["distance_m"] for r in abstract])
        grey = 0
        for f, a in zip(full, abstract):
            self.assertLessEqual(abs(f["prr"] - a["prr"]), 0.05, "at %g m" % f["distance_m"])
            grey += 0.1 < f["prr"] < 0.9
        self.assertGreaterEqual(grey, 4)

    def test_validate_says_where_the_calibration_comes_from(self):
        self.env = dict(self.env, SANET_CACHE=os.path.join(self.tmp.name, "cache-of-validate"))
        abstract = ["--set", "network.radio_model=abstract"]
        before = self.sanet("validate", self.scenario, *abstract).stdout
        self.assertIn("not measured yet: the first run measures", before)
        printed = self.sanet("validate", self.scenario, *abstract, "--print").stdout
        self.assertIn("  calibration: measure\n", printed)
        self.assertIn("# network.calibration: not measured yet", printed)
        self.sanet("run", self.scenario, *abstract, "-q", "-o", os.path.join(self.tmp.name, "run"), "--force",
                   "--duration", "1")
        after = self.sanet("validate", self.scenario, *abstract).stdout
        self.assertIn("measured earlier, cached in " + self.env["SANET_CACHE"], after)
        with open(os.path.join(self.tmp.name, "run", "summary.json")) as f:
            self.assertEqual(json.load(f)["network"]["channel"]["calibration"], "measured")

    def test_a_weak_radio_measured_within_a_metre_is_cached_and_read_back(self):
        # At -5 dBm the curve starts under the path loss's reference distance (1 m), where every
        # distance has the same power: the table keeps one row for it, and the cache reads back.
        self.env = dict(self.env, SANET_CACHE=os.path.join(self.tmp.name, "cache-of-weak"))
        weak = self.write("weak.yaml", "name: weak\nduration: 1\nnetwork: {radio_model: abstract, tx_power: -5}\n"
                                       "nodes:\n  - {name: a, model: mote, pose: [0, 0, 0]}\n")
        sources = []
        for run in ("first", "second"):
            out = os.path.join(self.tmp.name, "weak-" + run)
            self.sanet("run", weak, "-q", "-o", out, "--force")
            with open(os.path.join(out, "summary.json")) as f:
                sources.append(json.load(f)["network"]["channel"]["calibration"])
        self.assertEqual(sources, ["measured", "cached"])

    def test_unicasts_at_a_higher_rate_are_calibrated_at_that_rate(self):
        self.env = dict(self.env, SANET_CACHE=os.path.join(self.tmp.name, "cache-of-rates"))
        fast = ["--set", "network.radio_model=abstract", "--set", "network.data_rate=11",
                "--set", "network.rx_threshold=-95"]  # where the rate, not the threshold, limits reception
        self.sanet("run", self.scenario, *fast, "-q", "-o", os.path.join(self.tmp.name, "fast"), "--force",
                   "--duration", "1")
        folder = os.path.join(self.env["SANET_CACHE"], "calibrations")
        (name,) = os.listdir(folder)
        with open(os.path.join(folder, name)) as f:
            rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
        def p50(column):  # the mean power where the column first reaches 0.5, interpolated
            below = None
            for r in rows:
                power, value = float(r["mean_dbm"]), float(r[column])
                if value >= 0.5:
                    return power if below is None else below[0] + (0.5 - below[1]) / (value - below[1]) * (
                        power - below[0])
                below = (power, value)
        # Measured here: 1 Mbps DSSS -89.1 dBm, 11 Mbps CCK -87.8 dBm (Nakagami fading blurs both).
        self.assertGreater(p50("unicast_prr"), p50("prr") + 0.7, "11 Mbps needs a stronger signal than 1 Mbps")
        self.assertLess(p50("unicast_prr"), p50("prr") + 6)

    def test_a_calibration_file_travels_in_the_effective_scenario(self):
        table = self.write("table.csv", "# mine\nmean_dbm, prr, access_delay_s\n-90,0,0.001\n-80,0.5,0.001\n"
                                        "-70,1,0.0005\n")
        text = RADIO.replace("network:\n", "network:\n  radio_model: abstract\n  calibration: table.csv\n")
        text += "  - {name: b, model: mote, pose: [20, 0, 0], controller: {name: pinger, params: {to: a}}}\n"
        scenario = self.write("file.yaml", text)
        self.assertIn("from table.csv", self.sanet("validate", scenario).stdout)
        printed = self.sanet("validate", scenario, "--print").stdout
        self.assertIn("    file: table.csv\n", printed)
        self.assertIn("[-80, 0.5, 0.001, 0.5]", printed)
        effective = self.write("effective.yaml", printed)
        os.remove(table)  # the effective scenario needs no file
        runs = []
        for name, path in (("file", scenario), ("effective", effective)):
            if name == "file":
                self.write("table.csv", "mean_dbm,prr,access_delay_s\n-90,0,0.001\n-80,0.5,0.001\n-70,1,0.0005\n")
            out = os.path.join(self.tmp.name, "run-" + name)
            self.sanet("run", path, "-q", "-o", out, "--force")
            with open(os.path.join(out, "summary.json")) as f:
                runs.append(json.load(f))
        self.assertEqual(runs[0]["scenario_fingerprint"], runs[1]["scenario_fingerprint"])
        self.assertEqual(runs[0]["fingerprint"], runs[1]["fingerprint"])
        self.assertEqual(runs[0]["network"]["channel"]["calibration"], "file")
        self.assertGreater(runs[0]["network"]["packets"]["messages_received"], 0)

    def test_radio_energy_follows_airtime_and_the_motes_die_when_they_do_on_the_full_model(self):
        scenario = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scenarios",
                                "sensor-network-energy.yaml")
        runs = {}
        for model in ("full", "abstract"):
            out = os.path.join(self.tmp.name, "energy-" + model)
            self.sanet("run", scenario, "-q", "-o", out, "--force", "--set", "network.radio_model=" + model)
            with open(os.path.join(out, "summary.json")) as f:
                runs[model] = json.load(f)["energy"]
        full, abstract = runs["full"], runs["abstract"]
        self.assertEqual(abstract["lifetime"]["dead"], full["lifetime"]["dead"])
        self.assertGreater(full["lifetime"]["dead"], 0)
        for key in ("first_death_s", "half_dead_s"):
            self.assertAlmostEqual(abstract["lifetime"][key], full["lifetime"][key], delta=0.01 * full["lifetime"][key])
        for name, node in abstract["nodes"].items():
            seconds, reference = node["radio_s"], full["nodes"][name]["radio_s"]
            self.assertEqual(sorted(seconds), ["idle", "rx", "tx"], "no sleep, no CCA-busy on the abstract radio")
            for state in ("tx", "rx"):
                self.assertAlmostEqual(seconds[state], reference[state], delta=0.2 * reference[state] + 0.01,
                                       msg="%s %s" % (name, state))
            used = node["used_j"]
            self.assertAlmostEqual(used["radio_tx"] + used["radio_rx"] + used["radio_idle"] + used["electronics"]
                                   + used["motion"] + used["sensors"], used["total"], places=6)

    def test_the_mac_gives_up_on_a_unicast_to_a_radio_switched_off(self):
        scenario = self.write("gave-up.yaml", """name: gave-up
duration: 10
network: {radio_model: abstract, routing: none, packet_log: true, tx_power: 10}
nodes:
  - {name: a, model: mote, pose: [0, 0, 0]}
  - {name: b, model: mote, pose: [20, 0, 0], controller: {name: pinger, params: {to: a, start: 1}}}
events:
  - {time: 5, node: a, action: switch_off}
""")
        out = os.path.join(self.tmp.name, "gave-up")
        self.sanet("run", scenario, "-q", "-o", out, "--force")
        with open(os.path.join(out, "packets", "b.csv")) as f:
            rows = list(csv.DictReader(f))
        gave_up = [float(r["time"]) for r in rows if r["reason"] == "mac_gave_up"]
        self.assertEqual(len(gave_up), 5, "the unicasts of 5 to 9 s")
        self.assertTrue(all(t >= 5 for t in gave_up))
        with open(os.path.join(out, "messages.csv")) as f:
            self.assertEqual(sum(1 for r in csv.DictReader(f) if r["time_received"]), 4, "those of 1 to 4 s arrive")

    def test_a_duty_cycle_is_refused_on_the_abstract_radio(self):
        scenario = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scenarios",
                                "duty-cycled-motes.yaml")
        done = self.sanet("validate", scenario, "--set", "network.radio_model=abstract", check=False)
        self.assertEqual(done.returncode, 2)
        self.assertIn("radio.duty_cycle': the abstract radio does not sleep", done.stderr)

    def test_bad_calibrations_are_refused_with_file_line_and_column(self):
        cases = [
            ("mean_dbm,prr\n-90,0\n", "1", "header"),
            ("mean_dbm,prr,access_delay_s\n-90,0,0.001\n-80,x,0.001\n", "3", "prr"),
            ("mean_dbm,prr,access_delay_s\n-90,0,0.001\n-80,1.5,0.001\n", "3", "prr"),
            ("mean_dbm,prr,access_delay_s\n-80,0,0.001\n-90,1,0.001\n", "3", "mean_dbm"),
            ("mean_dbm,prr,access_delay_s\n-90,0,0.001\n-80,0,0.001\n", "3", "prr"),
            ("mean_dbm,prr,access_delay_s\n-90,0,0.001\n-80,1,-1\n", "3", "access_delay_s"),
            ("mean_dbm,prr,access_delay_s\n-90,0,0.001,\n-80,1,0.001\n", "2", "row"),
            ("mean_dbm,prr,access_delay_s,unicast_prr\n-90,0,0.001,0\n-80,1,0.001,2\n", "3", "unicast_prr"),
        ]
        for i, (csv_text, line, column) in enumerate(cases):
            table = self.write("bad%d.csv" % i, csv_text)
            scenario = self.write("bad%d.yaml" % i, RADIO.replace(
                "network:\n", "network:\n  radio_model: abstract\n  calibration: bad%d.csv\n" % i))
            done = self.sanet("validate", scenario, check=False)
            self.assertEqual(done.returncode, 2, done.stderr)
            self.assertIn("%s:%s" % (table, line), done.stderr)
            self.assertIn(column, done.stderr)
        missing = self.write("missing.yaml", RADIO.replace(
            "network:\n", "network:\n  radio_model: abstract\n  calibration: nowhere.csv\n"))
        done = self.sanet("validate", missing, check=False)
        self.assertIn("missing.yaml:5", done.stderr)
        self.assertIn("nowhere.csv", done.stderr)
        full = self.write("full.yaml", RADIO.replace("network:\n", "network:\n  calibration: bad0.csv\n"))
        done = self.sanet("validate", full, check=False)
        self.assertIn("needs radio_model: abstract", done.stderr)
        measure = self.write("measure.yaml", RADIO.replace("network:\n", "network:\n  calibration: measure\n"))
        self.sanet("validate", measure)  # a printed abstract scenario switched back to the full model


if __name__ == "__main__":
    unittest.main()
