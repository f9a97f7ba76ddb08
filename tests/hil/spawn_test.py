#!/usr/bin/env python3
"""INIT spawns robots, as in USARSim. A client written from docs/protocol.md, standard library only:
- spawns a robot by class, name and pose; drives it and sees it move in its ground truth; reads its laser;
- spawns a second one that sends a message to a mote (an `echo`) and receives the mote's reply, across
  the simulated radio network;
- is refused, with an ERR that says why, for a name already taken, a class the scenario does not
  offer, a pose inside a wall, a pose outside the world and a robot over the scenario's maximum,
  and goes on using the same connection;
- still claims a scenario robot by name, and GETSTARTPOSES lists only the scenario's robots.
The spawned robots' trajectories, packets and messages are in the results like any other node's."""
import csv
import json
import os
import sys
import tempfile
import threading
import time
import unittest

from protocol_client import Client, field, serve

SANET = sys.argv.pop(1)
SCENARIO = """duration: 12
world:
  size: [40, 40]
  obstacles:
    - wall: {from: [10, -5], to: [10, 5]}
network: {routing: aodv}
spawn:
  max: 2
  region: {min: [-15, -15], max: [25, 15]}
nodes:
  - {name: m1, model: mote, pose: [20, 0, 0], controller: {name: echo}}
  - {name: scout, model: diffdrive, pose: [0, 0, 0]}
"""


def location(line):
    return [float(v) for v in field(line, "Location").split(",")]


class Spawning(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.server, cls.port, cls.out = serve(SANET, SCENARIO, cls.tmp.name)
        cls.results = {}
        cls.driver_ready = threading.Event()
        threads = [threading.Thread(target=cls.drive_probe1), threading.Thread(target=cls.talk_from_probe2)]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        cls.over_the_maximum_and_claiming()
        cls.server.wait(timeout=60)
        with open(os.path.join(cls.out, "summary.json")) as f:
            cls.summary = json.load(f)
        cls.rows = {}
        for name in ["trajectories", "messages", "packets", "log"]:
            with open(os.path.join(cls.out, name + ".csv")) as f:
                cls.rows[name] = list(csv.DictReader(f))

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    @classmethod
    def drive_probe1(cls):
        c = Client(cls.port)
        c.send("INIT {ClassName USARBot.P2DX} {Name Probe1} {Location 2,2,0.2} {Rotation 0,0,0}")
        first = c.sensor("GroundTruth")
        cls.driver_ready.set()
        scan = c.sensor("RangeScanner")
        c.send("DRIVE {Left 4} {Right 4}")
        deadline = time.time() + 8
        last = first
        while time.time() < deadline and location(last)[0] - location(first)[0] < 1.0:
            last = c.sensor("GroundTruth")
        c.send("DRIVE {Left 0} {Right 0}")
        cls.results["probe1"] = {"first": location(first), "last": location(last), "scan": scan}
        c.close()

    @classmethod
    def talk_from_probe2(cls):
        cls.driver_ready.wait(10)
        c = Client(cls.port)
        refusals = {}
        for case, line in [("taken", "INIT {ClassName USARBot.P2DX} {Name Probe1} {Location 0,8,0}"),
                           ("mote", "INIT {ClassName USARBot.P2DX} {Name m1} {Location 0,8,0}"),
                           ("class", "INIT {ClassName USARBot.AirRobot} {Name Flyer} {Location 0,8,0}"),
                           ("wall", "INIT {ClassName USARBot.P2AT} {Name Stuck} {Location 10,0,0.2}"),
                           ("outside", "INIT {ClassName USARBot.P2AT} {Name Far} {Location 100,0,0.2}"),
                           ("crowded", "INIT {ClassName USARBot.P2AT} {Name Close} {Location 2.2,2,0.2}"),
                           ("two numbers", "INIT {ClassName USARBot.P2AT} {Name Flat} {Location 5,5}")]:
            c.send(line)
            refusals[case] = c.next("ERR")
        c.send("INIT {ClassName usarbot.p2at} {Name Probe2} {Location 18 -2 0.2} {Rotation 0 0 0}")  # y right
        truth = c.sensor("GroundTruth")
        c.send("SEND {To m1} {Data 0a0b0c}")
        reply = c.next("MSG")
        c.close()
        cls.results["probe2"] = {"refusals": refusals, "truth": location(truth), "reply": reply}

    @classmethod
    def over_the_maximum_and_claiming(cls):
        c = Client(cls.port)
        c.send("INIT {ClassName USARBot.P2DX} {Name Probe3} {Location -5,-5,0.2}")
        over = c.next("ERR")
        c.send("INIT {ClassName sanet.Omni3} {Name Probe1} {Location 0,8,0}")  # its client has gone
        other_class = c.next("ERR")
        c.send("GETSTARTPOSES")
        poses = c.next("NFO")
        c.send("INIT {Name scout}")
        scout = c.sensor("GroundTruth")
        c.close()
        cls.results["third"] = {"over": over, "poses": poses, "scout": location(scout), "other class": other_class}

    def test_a_spawned_robot_stands_where_init_put_it_and_drives(self):
        p = self.results["probe1"]
        self.assertAlmostEqual(p["first"][0], 2, delta=0.05)
        self.assertAlmostEqual(p["first"][1], 2, delta=0.05)  # USARSim's y, as the client gave it
        self.assertGreaterEqual(p["last"][0] - p["first"][0], 1.0, "the spawned robot should drive forward")
        ranges = [float(r) for r in field(p["scan"], "Range").split(",")]
        self.assertEqual(len(ranges), 181)
        self.assertTrue(all(0 < r <= 8.0 for r in ranges))
        self.assertLess(min(ranges), 8.0, "the wall at x = 10 lies within the laser's reach ahead")

    def test_the_second_robot_talks_to_a_mote_over_the_simulated_network(self):
        p = self.results["probe2"]
        self.assertAlmostEqual(p["truth"][0], 18, delta=0.05)
        self.assertAlmostEqual(p["truth"][1], -2, delta=0.05)
        self.assertEqual(field(p["reply"], "From"), "m1")
        self.assertEqual(field(p["reply"], "Data"), "0a0b0c")
        self.assertGreater(float(field(p["reply"], "TimeReceived")), float(field(p["reply"], "TimeSent")))

    def test_refusals_say_why_and_the_connection_goes_on(self):
        r = self.results["probe2"]["refusals"]
        self.assertIn("already driven by another client", r["taken"])
        self.assertIn("taken by a mote", r["mote"])
        self.assertIn("may not be spawned here", r["class"])
        self.assertIn("USARBot.P2DX", r["class"])  # the classes that are allowed
        self.assertIn("inside world.obstacles[0], a wall", r["wall"])
        self.assertIn("outside spawn.region", r["outside"])
        self.assertIn("expected three numbers x,y,z", r["two numbers"])
        for refusal in r.values():
            self.assertTrue(refusal.startswith("ERR {Message INIT refused: "), refusal)
        self.assertIn("taken by Probe1", r["crowded"])
        self.assertIsNotNone(self.results["probe2"]["reply"], "the same connection spawned Probe2 afterwards")

    def test_the_scenario_maximum_holds_and_scenario_robots_are_still_claimed(self):
        t = self.results["third"]
        self.assertIn("as many as this scenario allows", t["over"])
        self.assertIn("robot 'Probe1' is a USARBot.P2DX, not a sanet.Omni3", t["other class"])
        self.assertIn("{StartPoses 1}", t["poses"])
        self.assertIn("scout", t["poses"])
        self.assertNotIn("Probe", t["poses"])
        self.assertAlmostEqual(t["scout"][0], 0, delta=0.05)

    def test_spawned_robots_are_in_the_results(self):
        probe1 = [r for r in self.rows["trajectories"] if r["node"] == "Probe1"]
        self.assertGreater(float(probe1[-1]["x"]) - float(probe1[0]["x"]), 0.8)
        # The first row is the pose INIT gave, at the time of the spawn (sanet's frame: y left).
        self.assertEqual((float(probe1[0]["x"]), float(probe1[0]["y"])), (2.0, -2.0))
        spawned_at = [r for r in self.rows["log"] if r["node"] == "Probe1" and "spawned as" in r["text"]][0]["time"]
        self.assertAlmostEqual(float(probe1[0]["time"]), float(spawned_at), delta=0.001)
        messages = self.rows["messages"]
        sent = [r for r in messages if r["from"] == "Probe2" and r["to"] == "m1"]
        echoed = [r for r in messages if r["from"] == "m1" and r["to"] == "Probe2" and r["time_received"]]
        self.assertEqual(len(sent), 1)
        self.assertEqual(len(echoed), 1)
        self.assertEqual(sent[0]["bytes"], "3")
        self.assertGreater(float(echoed[0]["delay"]), 0)
        packets = {r["node"]: r for r in self.rows["packets"]}
        self.assertGreater(int(packets["Probe2"]["sent"]), 0)
        self.assertEqual(packets["Probe2"]["messages_received"], "1")
        self.assertIn("Probe1", packets)
        nodes = {n["name"]: n for n in self.summary["nodes"]}
        self.assertEqual(nodes["Probe1"].get("spawned_as"), "USARBot.P2DX")
        self.assertEqual(nodes["Probe2"].get("spawned_as"), "USARBot.P2AT")
        self.assertNotIn("spawned_as", nodes["scout"])
        self.assertTrue(any(r["node"] == "Probe2" and "spawned as USARBot.P2AT" in r["text"] for r in self.rows["log"]))


class StockClientOnAShippedLoopScenario(unittest.TestCase):
    """A stock USARSim client starts by spawning its robot with INIT: the shipped loop scenarios
    allow it (their spawn sections offer the default classes)."""

    def test_init_by_class_spawns_a_robot_that_drives(self):
        source = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scenarios")
        for name in ("formation-hil.yaml", "formation-radio.yaml", "help-request-loop.yaml"):
            with self.subTest(scenario=name), tempfile.TemporaryDirectory() as tmp:
                with open(os.path.join(source, name)) as f:
                    server, port, out = serve(SANET, f.read(), tmp, "--duration", "6")
                c = Client(port)
                c.send("INIT {ClassName USARBot.P2DX} {Location 10,10,0.2} {Rotation 0,0,0}")
                first = c.sensor("GroundTruth")
                self.assertAlmostEqual(location(first)[0], 10, delta=0.1)
                self.assertAlmostEqual(location(first)[1], 10, delta=0.1)
                c.send("DRIVE {Left 4} {Right 4}")
                last = first
                deadline = time.time() + 4
                while time.time() < deadline and location(last)[0] - location(first)[0] < 0.5:
                    last = c.sensor("GroundTruth")
                self.assertGreater(location(last)[0] - location(first)[0], 0.5, "the spawned robot drives")
                c.close()
                server.wait(timeout=60)
                with open(os.path.join(out, "summary.json")) as f:
                    nodes = {n["name"]: n for n in json.load(f)["nodes"]}
                self.assertEqual(nodes["P2DX-1"].get("spawned_as"), "USARBot.P2DX")


if __name__ == "__main__":
    unittest.main(verbosity=2)
