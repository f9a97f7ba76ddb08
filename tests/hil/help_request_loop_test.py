#!/usr/bin/env python3
"""Case study 1 in the loop: `sanet launch scenarios/help-request-loop.yaml` runs the unchanged
help-request controllers, the robot's as its own process whose node is its ns-3 node over the
simulated radio. The target's call reaches the robot through the motes' routes; the robot
chooses each hop from its routing table (fetched from the server), steers by the served
bearing of the hop mote and arrives, close to the time `sanet run` of the same scenario gives, by
its route. Two launches run at once, side by side, each as one alone.
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
    def check_launch(self, run, looped):
        loop, transitions = results(looped)
        self.assertEqual(loop["status"], "completed")
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
        self.assertLess(abs(loop["ended_at_s"] - run["ended_at_s"]), 0.1 * run["ended_at_s"],
                        (loop["ended_at_s"], run["ended_at_s"]))
        return hops

    def test_two_launches_at_once_follow_the_routing_tables_over_the_simulated_radio_and_arrive(self):
        """Two launches side by side (slots of their own: bridges, namespaces, taps), each as one
        alone: the route of the simulated run, and its arrival."""
        with tempfile.TemporaryDirectory() as tmp:
            simulated = os.path.join(tmp, "run")
            subprocess.run([SANET, "run", SCENARIO, "-o", simulated, "-q"], check=True, timeout=120)
            run, run_transitions = results(simulated)
            self.assertEqual(run["ended_by"], "'arrived' logged by robot")
            run_hops = [t["why"].split()[2] for t in run_transitions
                        if t["node"] == "robot" and t["why"].startswith("next hop ")]
            folders = [os.path.join(tmp, "launch%d" % i) for i in range(2)]
            launches = [subprocess.Popen([SANET, "launch", SCENARIO, "-o", out], stdout=subprocess.PIPE,
                                         stderr=subprocess.STDOUT, text=True) for out in folders]
            for p in launches:
                output = p.communicate(timeout=400)[0]
                self.assertEqual(p.returncode, 0, output)
            for looped in folders:
                self.assertEqual(self.check_launch(run, looped), run_hops, "the simulated run's route")


if __name__ == "__main__":
    if os.geteuid() != 0 or not os.path.exists("/dev/net/tun"):
        print("skipped: the simulated radio in the loop needs root and /dev/net/tun")
        sys.exit(77)
    unittest.main(verbosity=2)
