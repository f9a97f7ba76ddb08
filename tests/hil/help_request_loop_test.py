#!/usr/bin/env python3
"""Case study 1 in the loop: `sanet launch scenarios/help-request-loop.yaml` runs the unchanged
help-request controllers, the robot's as its own process whose node is its ns-3 node over the
simulated radio. The target's call reaches the robot through the motes' routes; the robot
chooses each hop from its routing table (fetched from the server), steers by the served
bearing of the hop mote and arrives, close to the time `sanet run` of the same scenario gives.
Needs root and /dev/net/tun (the simulated radio's taps): skipped elsewhere (exit 77). About
two minutes of real time."""
import csv
import json
import os
import subprocess
import sys
import tempfile
import unittest

SANET = sys.argv.pop(1)
SOURCE = sys.argv.pop(1)
SCENARIO = os.path.join(SOURCE, "scenarios", "help-request-loop.yaml")


def results(out):
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    with open(os.path.join(out, "transitions.csv")) as f:
        transitions = [r for r in csv.DictReader(f)]
    return summary, transitions


class HelpRequestInTheLoop(unittest.TestCase):
    def test_the_robot_follows_the_routing_tables_over_the_simulated_radio_and_arrives(self):
        with tempfile.TemporaryDirectory() as tmp:
            simulated, looped = os.path.join(tmp, "run"), os.path.join(tmp, "launch")
            subprocess.run([SANET, "run", SCENARIO, "-o", simulated, "-q"], check=True, timeout=120)
            out = subprocess.run([SANET, "launch", SCENARIO, "-o", looped], capture_output=True, text=True,
                                 timeout=400)
            self.assertEqual(out.returncode, 0, out.stdout + out.stderr)
            (run, _), (loop, transitions) = results(simulated), results(looped)
            self.assertEqual(loop["ended_by"], "'arrived' logged by robot")
            robot = [t for t in transitions if t["node"] == "robot"]
            self.assertIn("help request from target", [t["why"] for t in robot], "the call was routed to it")
            hops = [t["why"].split()[2] for t in robot if t["why"].startswith("next hop ")]
            motes = {"m0", "m1", "m2", "m3", "m4", "m5", "n0", "n1", "target"}
            self.assertGreaterEqual(len(hops), 4, robot)
            self.assertTrue(set(hops) <= motes, hops)
            reached = [t["why"] for t in robot if t["why"].startswith("reached ")]
            self.assertEqual(reached[-1], "reached target")
            self.assertEqual(len(reached), len(hops), "every hop reached by its bearing")
            self.assertEqual(loop["agents"]["robot"]["steps_missed"], 0)
            self.assertGreater(loop["network"]["route_discoveries"]["established"], 0)
            # Beside the simulated run: the same way, within a few control periods of its time.
            self.assertEqual(run["ended_by"], "'arrived' logged by robot")
            self.assertLess(abs(loop["ended_at_s"] - run["ended_at_s"]), 0.1 * run["ended_at_s"],
                            (loop["ended_at_s"], run["ended_at_s"]))


if __name__ == "__main__":
    if os.geteuid() != 0 or not os.path.exists("/dev/net/tun"):
        print("skipped: the simulated radio in the loop needs root and /dev/net/tun")
        sys.exit(77)
    unittest.main(verbosity=2)
