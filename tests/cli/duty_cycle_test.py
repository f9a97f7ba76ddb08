#!/usr/bin/env python3
"""radio.duty_cycle: a duty-cycled mote hears the broadcasts sent inside its awake windows and
none sent while it sleeps; on a battery it lives as long as the cycle's mean power says; the
cycle is printed in the effective scenario; mistakes name the key."""
import csv
import json
import os
import subprocess
import sys
import tempfile
import unittest

SANET, SOURCE = sys.argv[1:3]
del sys.argv[1:3]

SCENARIO = """name: duty
duration: {duration}
world: {{size: [100, 100]}}
network: {{radio: 802.11b, tx_power: 20, routing: none}}
nodes:
  - name: sender
    model: mote
    pose: [0, 0, 0]
    controller: {{name: pinger, params: {{to: broadcast, interval: 0.25, start: 0.1, size: 32}}}}
  - name: sleeper
    model: mote
    pose: [30, 0, 0]
    radio: {{duty_cycle: {cycle}}}
    energy: {{battery_j: 100, voltage: 3, electronics_w: 0.01, radio: ns3_wifi}}
"""
PERIOD, AWAKE, PHASE = 10.0, 2.0, 1.0
CYCLE = f"{{period_s: {PERIOD}, awake_s: {AWAKE}, phase_s: {PHASE}}}"
IDLE_A, SLEEP_A, VOLTS, ELECTRONICS_W = 0.273, 0.033, 3.0, 0.01  # ns-3's WifiRadioEnergyModel currents


def awake(t):
    return (t - PHASE) % PERIOD < AWAKE


def lifetime_from_the_formula(battery_j):
    """Integrates the cycle's power, awake (idle current) and asleep, until the battery is spent."""
    awake_w, asleep_w = VOLTS * IDLE_A + ELECTRONICS_W, VOLTS * SLEEP_A + ELECTRONICS_W
    t, left = 0.0, battery_j
    while True:
        into = (t - PHASE) % PERIOD
        end = t + (AWAKE - into if into < AWAKE else PERIOD - into)
        power = awake_w if into < AWAKE else asleep_w
        if left <= power * (end - t):
            return t + left / power
        left -= power * (end - t)
        t = end


class DutyCycle(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.out = cls.run_scenario(cls, "run", duration=600, cycle=CYCLE)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def run_scenario(self, name, **values):
        path = os.path.join(self.tmp.name, name + ".yaml")
        with open(path, "w") as f:
            f.write(SCENARIO.format(**values))
        out = os.path.join(self.tmp.name, name)
        done = subprocess.run([SANET, "run", path, "-q", "-o", out], capture_output=True, text=True, timeout=300)
        assert done.returncode == 0, done.stderr
        return out

    def test_a_sleeping_radio_misses_what_is_sent_while_it_sleeps(self):
        with open(os.path.join(self.out, "summary.json")) as f:
            died = json.load(f)["energy"]["nodes"]["sleeper"]["died_s"]
        with open(os.path.join(self.out, "messages.csv")) as f:
            heard = [float(r["time_sent"]) for r in csv.DictReader(f) if r["to"] == "sleeper"]
        sent = [0.1 + 0.25 * k for k in range(int((died - 0.1) / 0.25))]
        expected = [t for t in sent if awake(t) and awake(t + 0.01)]  # not the ones cut by the window's end
        self.assertGreater(len(expected), 100)
        self.assertTrue(all(awake(t) for t in heard), "nothing sent while it slept arrives")
        self.assertGreaterEqual(len(heard), len(expected), "what is sent inside a window arrives")
        self.assertLess(len(heard), len(sent) / 3, "most are sent while it sleeps")

    def test_it_lives_as_long_as_its_duty_cycle_says(self):
        with open(os.path.join(self.out, "summary.json")) as f:
            sleeper = json.load(f)["energy"]["nodes"]["sleeper"]
        expected = lifetime_from_the_formula(100)
        self.assertAlmostEqual(sleeper["died_s"], expected, delta=0.01 * expected)
        always_awake = 100 / (VOLTS * IDLE_A + ELECTRONICS_W)
        self.assertGreater(sleeper["died_s"], 3 * always_awake, "the cycle more than triples its life")
        self.assertGreater(sleeper["radio_s"]["sleep"], 3 * sleeper["radio_s"]["idle"])

    def test_the_cycle_is_in_the_effective_scenario(self):
        with open(os.path.join(self.out, "scenario.yaml")) as f:
            text = f.read()
        self.assertIn("duty_cycle: {period_s: 10, awake_s: 2, phase_s: 1}", text)

    def test_the_shipped_motes_with_phases_from_the_seed_deliver_every_report_within_a_period(self):
        scenario = os.path.join(SOURCE, "scenarios", "duty-cycled-motes.yaml")
        out = os.path.join(self.tmp.name, "shipped")
        done = subprocess.run([SANET, "run", scenario, "--duration", "300", "-q", "-o", out], capture_output=True,
                              text=True, timeout=300)
        self.assertEqual(done.returncode, 0, done.stderr)
        with open(os.path.join(out, "messages.csv")) as f:
            delays = [float(r["delay"]) for r in csv.DictReader(f) if r["delay"]]
        with open(os.path.join(out, "packets.csv")) as f:
            sent = sum(int(r["messages_sent"]) for r in csv.DictReader(f))
        # Reports queued while asleep go out in the next window: only a mote's last may still wait.
        self.assertLessEqual(sent - len(delays), 12)
        self.assertGreater(len(delays), 300)
        self.assertTrue(all(d < 10 for d in delays), "within a period")
        self.assertGreater(sum(delays) / len(delays), 1, "most wait for a window")
        with open(os.path.join(out, "scenario.yaml")) as f:
            self.assertIn("phase_s: random", f.read())

    def test_mistakes_name_the_key(self):
        for cycle, message in [("{period_s: 10, awake_s: 12}", "awake_s"),
                               ("{period_s: 10, awake_s: 2, phase_s: 10}", "must be under period_s (10), or random"),
                               ("{period_s: 10, awake_s: 2, phase_s: later}", "phase_s"),
                               ("{awake_s: 2}", "period_s"),
                               ("{period_s: 10, awake_s: 2, wake: 1}", "wake"),
                               ("10", "must be a mapping")]:
            path = os.path.join(self.tmp.name, "bad.yaml")
            with open(path, "w") as f:
                f.write(SCENARIO.format(duration=10, cycle=cycle))
            done = subprocess.run([SANET, "validate", path], capture_output=True, text=True, timeout=60)
            self.assertEqual(done.returncode, 2, cycle)
            self.assertIn("bad.yaml:13:", done.stderr, cycle)
            self.assertIn("duty_cycle", done.stderr, cycle)
            self.assertIn(message, done.stderr, cycle)


if __name__ == "__main__":
    unittest.main()
