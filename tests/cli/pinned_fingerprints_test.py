#!/usr/bin/env python3
"""The fingerprint of every shipped scenario, pinned at a stated duration: a change to physics,
sensors, the network, controllers, scheduling or output formats that alters any result of any of
them fails here, and must be committed with the new value and a message that says why. Refactors
must leave every value as it is. (Label `pinned`: the sanitizer suite does not run it.)"""
import json
import os
import subprocess
import sys
import tempfile
import unittest

SANET = sys.argv.pop(1)
SOURCE = sys.argv.pop(1)

# scenario: (--duration in simulated seconds, fingerprint)
PINNED = {
    "around-the-wall": (90, "3dff464fa2648c1f"),  # its motes moved off the robot's way (issue 28)
    "formation": (60, "a421fc2dbf324523"),
    "formation-radio": (60, "a421fc2dbf324523"),  # the same world; its radio matters in the loop
    "formation-hil": (60, "f47b34c507c2329d"),
    "help-request": (300, "637c11bdfbd6668c"),
    "help-request-team": (300, "5dd2651b767b1e68"),
    "help-request-loop": (120, "fb23174b03599c8a"),  # ends at the robot's arrival, 97 s
    "help-request-indoor": (900, "098321139da9e05c"),  # concrete walls (issue 37); arrives at 198.3 s
    "help-request-office-map": (900, "098321139da9e05c"),  # the same building as a ROS map (issue 55): the same run
    "help-request-grey-zone": (300, "63f2ab048acbd774"),  # shadowing, fading, hardware spread (issue 48)
    "ros2-robots": (60, "baec0cf232e6c9a6"),  # nobody drives them in sanet run: they stand
    "ros2-team-radio": (60, "1eb346755b3dc49b"),  # the robots stand (driven in launch only), the motes ping
    "scattered-field": (300, "a3035def5023f458"),  # 30 motes scattered from the seed, a touring mule (issue 49)
    "charging-robot": (600, "7b65c128f5c9a026"),  # a robot charges motes from their battery reports (issue 51)
    "data-mule": (300, "3378f8d98c992bcc"),  # motes keep readings until a touring robot collects them (issue 50)
    "data-mule-802154": (600, "628e5c4eb6d59025"),  # 802.15.4 motes, a two-radio robot, a base on 802.11 (issue 52)
    "duty-cycled-motes": (300, "c3ae6bddc2b56796"),  # radios awake 1 s of 10, phases drawn from the seed (issue 51)
    "sensor-network": (60, "ca79ea1813db313a"),
    "sensor-network-energy": (600, "59b947a8e462943e"),  # on batteries: 24 of 26 motes die (issue 47)
    "swarm-1k": (5, "b78520b232205dd8"),
    "urdf-robot": (120, "00b37c5e79d6f33f"),  # a diffdrive and an omni3 from URDF files (issue 54)
    "camera-stream": (90, "33554d2a3ed13161"),  # a rover streams its camera's pictures over 802.11g (issue 57)
    "ros2-camera-radio": (75, "4d1b3182c0f714af"),  # the robots stand (driven in launch only), the camera samples
    "swarm-1k-abstract": (5, "19afe3bebbc920a0"),  # the abstract radio, calibrated by the full model (issue 53)
    "swarm-10k": (2, "1a7825e66ad97414"),  # on the abstract radio since issue 53; a few seconds are enough
}


class Pinned(unittest.TestCase):
    def test_every_shipped_scenario_is_pinned(self):
        shipped = sorted(f[:-5] for f in os.listdir(os.path.join(SOURCE, "scenarios")) if f.endswith(".yaml"))
        self.assertEqual(shipped, sorted(PINNED))

    def test_fingerprints(self):
        with tempfile.TemporaryDirectory() as tmp:
            for name, (duration, fingerprint) in PINNED.items():
                with self.subTest(scenario=name, duration=duration):
                    folder = os.path.join(tmp, name)
                    out = subprocess.run([SANET, "run", os.path.join(SOURCE, "scenarios", name + ".yaml"),
                                          "--duration", str(duration), "-q", "-o", folder],
                                         capture_output=True, text=True, timeout=600)
                    self.assertEqual(out.returncode, 0, out.stderr)
                    with open(os.path.join(folder, "summary.json")) as f:
                        self.assertEqual(json.load(f)["fingerprint"], fingerprint)


if __name__ == "__main__":
    unittest.main(verbosity=2)
