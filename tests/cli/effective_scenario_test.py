#!/usr/bin/env python3
"""`sanet validate --print` writes the effective scenario: it validates, prints itself again
unchanged, and runs to the same fingerprint as the scenario it came from, for the shipped
scenarios and for one that uses every kind of section (grids, radios, sensors changed and
removed, events, impairments, end conditions, spawning)."""
import json
import os
import subprocess
import sys
import tempfile
import unittest

SANET = sys.argv.pop(1)
SOURCE = sys.argv.pop(1)

EVERYTHING = """name: everything
seed: 7
duration: 20
world:
  size: [40, 20]
  physics_step: 0.004
  obstacles:
    - {wall: {from: [5, -2], to: [5, 2], height: 0.5, thickness: 0.1}}
    - {box: {center: [8, 3], size: [1, 0.5, 0.3], yaw: 0.3}}
network:
  radio: 802.11g
  data_rate: 12
  tx_power: 18
  propagation: {model: two_ray_ground, antenna_height: 1.5, max_range: 60}
  routing: olsr
messages: {loss: 0.1, delay: 0.05}
events:
  - {time: 15, node: m3, action: switch_off}
  - {time: 12, node: m4, action: recharge, energy_j: 40}
end: {when_logged: [never logged, nor this], grace: 1}
outputs: {trajectory_interval: 0.2, min_distance: true}
spawn:
  max: 3
  classes:
    - {class: USARBot.P2AT, model: diffdrive, body: {max_speed: 0.7}, radio: {tx_power: 12}}
    - {class: Omni, model: omni3, sensors: {laser: {fov: 1, beams: 11}}, energy: {source: li_ion, battery_j: 30000}}
nodes:
  - grid: {name: m, rows: 2, cols: 3, origin: [0, -5], spacing: [10, 10], heading: 0.1}
    model: mote
    body: {size: 0.2}
    radio: {tx_power: 20}
    energy: {battery_j: 50, voltage: 3.7, cutoff: 0.1, radio: {preset: cc2420, tx_a: 0.02}}
    controller: {name: pinger, rate: 2, params: {to: flood, interval: 2, size: 12}}
  - name: r
    model: omni3
    pose: [-1, 0, 0.2]
    body: {body_radius: 0.25, max_speed: 0.8}
    sensors: {ir: {count: 8, noise: 0.01}, laser: {fov: 2, beams: 31}, bearing: {range: 30, noise_angle: 0.01},
              ground_truth: {noise_position: 0.02}}
    controller: {name: waypoint, rate: 20, params: {waypoints: [[12, 0], [12, 6]], speed: 0.6}}
  - name: d
    model: diffdrive
    pose: [0, 4, 0]
    sensors: {laser: false, ir: true, odometry: {noise: 0.05}}
    controller: {name: constant_velocity, params: {vx: 0.3, omega: 0.05}}
"""


def run(args):
    return subprocess.run([SANET] + args, check=True, capture_output=True, text=True).stdout


class EffectiveScenario(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.tmp.cleanup()

    def fingerprint(self, scenario, name, duration):
        out = os.path.join(self.tmp.name, name)
        run(["run", scenario, "-q", "--duration", str(duration), "-o", out])
        with open(os.path.join(out, "summary.json")) as f:
            return json.load(f)["fingerprint"]

    def check(self, scenario, duration):
        printed = run(["validate", "--print", scenario])
        effective = os.path.join(self.tmp.name, "effective.yaml")
        with open(effective, "w") as f:
            f.write(printed)
        self.assertIn("valid:", run(["validate", effective]))
        again = run(["validate", "--print", effective])
        self.assertEqual(printed.split("\n", 1)[1], again.split("\n", 1)[1], "printing is a fixed point")
        self.assertEqual(self.fingerprint(scenario, "a", duration), self.fingerprint(effective, "b", duration))
        return printed

    def test_shipped_scenarios_round_trip(self):
        for name, duration in [("around-the-wall", 90), ("formation", 60), ("help-request", 300),
                               ("sensor-network", 60)]:
            with self.subTest(name):
                self.check(os.path.join(SOURCE, "scenarios", name + ".yaml"), duration)

    def test_every_shipped_scenario_prints_to_one_that_loads(self):
        for name in sorted(n for n in os.listdir(os.path.join(SOURCE, "scenarios")) if n.endswith(".yaml")):
            with self.subTest(name):
                printed = run(["validate", "--print", os.path.join(SOURCE, "scenarios", name)])
                effective = os.path.join(self.tmp.name, "effective.yaml")
                with open(effective, "w") as f:
                    f.write(printed)
                self.assertIn("valid:", run(["validate", effective]))

    def test_a_simulated_loop_prints_to_one_that_loads(self):
        # `sanet launch` hands its agents the effective scenario: it must load as the file did.
        path = os.path.join(self.tmp.name, "simulated.yaml")
        with open(path, "w") as f:
            f.write("duration: 5\nnetwork: {routing: aodv}\nloop: {network: simulated}\n"
                    "nodes:\n  - {name: a, model: omni3, pose: [0, 0, 0], controller: {name: constant_velocity}}\n")
        self.check(path, 5)

    def test_every_kind_of_section_round_trips(self):
        path = os.path.join(self.tmp.name, "everything.yaml")
        with open(path, "w") as f:
            f.write(EVERYTHING)
        printed = self.check(path, 20)
        # Defaults are filled in and grids become their nodes.
        for text in ["rx_threshold: -82", "reference_distance", "name: m5", "solver: exact", "mass: 0.05",
                     "preset: cc2420", "tx_a: 0.02", "revive: 0.15", "source: li_ion", "action: recharge",
                     "energy_j: 40", "energy_interval: 10", "sleep_a: 2e-5"]:
            if text == "reference_distance":
                self.assertNotIn(text, printed, "keys that do not apply to the model are left out")
            else:
                self.assertIn(text, printed)
        # The spawn section's default region is the field around the nodes: the world's 40 x 20 m
        # centred between the nodes and obstacles (x from -1 to 20, y from -5 to 5).
        self.assertIn("min: [-10.5, -10]", printed)
        self.assertIn("max: [29.5, 10]", printed)


if __name__ == "__main__":
    unittest.main(verbosity=2)
