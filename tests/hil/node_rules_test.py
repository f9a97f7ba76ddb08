#!/usr/bin/env python3
"""Every driver goes through the node: a client of `sanet serve` is held to the run's rules as an
in-process controller is. A client written from docs/protocol.md:
- drives a robot that a scenario event switches off: it moves before, not after (and is told);
- receives a mote's messages to its robot (MSG, over the simulated network) and replies (SEND);
  both directions appear in messages.csv; once it has gone, the mote's messages are recorded as
  lost;
- reads its robot's battery (docs/energy.md) as seconds left in STA (sanet's SEN Battery line
  goes to clients that said SANET: tests/python's launch test reads it through `sanet agent`)."""
import csv
import json
import os
import sys
import tempfile
import threading
import unittest

from protocol_client import Client, field, serve

SANET = sys.argv.pop(1)
SOURCE = sys.argv.pop(1)
SCENARIO = """duration: 12
network: {routing: aodv}
events:
  - {time: 3, node: off, action: switch_off}
nodes:
  - name: m1
    model: mote
    pose: [0, 0, 0]
    controller: {name: pinger, params: {to: r1, interval: 0.5, start: 1, size: 8}}
  - {name: r1, model: diffdrive, pose: [5, 0, 0],
     energy: {battery_j: 40, voltage: 3, electronics_w: 0.2, drive_idle_w: 0, rolling_resistance: 0}}
  - {name: off, model: diffdrive, pose: [0, 5, 0]}
"""


def ground_truth_x(line):
    return float(field(line, "Location").split(",")[0])


class NodeRules(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.server, cls.port, cls.out = serve(SANET, SCENARIO, cls.tmp.name)
        cls.switched, cls.messages = {}, {}
        # Both clients at once, each on its own thread of the test, as two robots' programs would.
        threads = [threading.Thread(target=cls.drive_switched_off_robot), threading.Thread(target=cls.talk_to_mote)]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        cls.server.wait(timeout=60)
        cls.summary = json.load(open(os.path.join(cls.out, "summary.json")))
        with open(os.path.join(cls.out, "messages.csv")) as f:
            cls.rows = list(csv.DictReader(f))

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    @classmethod
    def drive_switched_off_robot(cls):
        c = Client(cls.port)
        c.send("INIT {ClassName USARBot.P2DX} {Name off}")
        xs_before, xs_after, errors = [], [], []
        for line in c.lines():
            if line.startswith("ERR"):
                errors.append(line)
            if not line.startswith("SEN") or "GroundTruth" not in line:
                continue
            t = float(field(line, "Time"))
            c.send("DRIVE {Left 5} {Right 5} {Normalized false}")  # rad/s, as fast forward as it goes
            if 4 < t < 4.15:
                c.send("SEND {Delivery broadcast} {Data 0102}")
            if t < 3:
                xs_before.append(ground_truth_x(line))
            elif t > 3.5:  # after it has coasted to a stop
                xs_after.append(ground_truth_x(line))
            if t > 6:
                break
        c.close()
        cls.switched = {"before": xs_before, "after": xs_after, "errors": errors}

    @classmethod
    def talk_to_mote(cls):
        c = Client(cls.port)
        c.send("INIT {ClassName USARBot.P2DX} {Name r1} {Location 5 0 0.2} {Rotation 0 0 0}")  # space-separated
        for bad in ["SEND {To nobody} {Data 00}", "SEND {To m1} {Data 0g}", "SEND {Delivery multicast} {Data 00}",
                    "SEND {Data 00}", "SEND {To r1} {Data 00}", "TRANSITION {From a} {To }",
                    "STATS {Steps many}", "RECV {From nobody} {Delivery unicast}"]:
            c.send(bad)
        received, errors, battery = [], [], {"STA": [], "SEN": []}
        for line in c.lines():
            if line.startswith("ERR"):
                errors.append(line)
            if line.startswith("STA"):
                battery["STA"].append((float(field(line, "Time")), int(field(line, "Battery"))))
            if line.startswith("SEN") and "{Type Battery}" in line:
                battery["SEN"].append((float(field(line, "Time")), float(field(line, "Remaining")),
                                       float(field(line, "Capacity")), float(field(line, "Power"))))
            if line.startswith("MSG"):
                received.append(line)
                c.send("SEND {Delivery unicast} {To m1} {Data cafe%04x}" % len(received))
            if len(received) == 4:
                break
        c.close()  # the mote goes on sending: to a robot nobody drives now
        cls.messages = {"received": received, "errors": errors, "battery": battery}

    def test_the_client_reads_its_battery_in_sta_lines(self):
        # An idle 802.11 radio (ns-3's currents) and the electronics; its drive costs nothing at rest
        # or at a steady speed (no idle draw, no rolling resistance), only as it speeds up.
        watts = 3 * 0.273 + 0.2
        sen, sta = self.messages["battery"]["SEN"], self.messages["battery"]["STA"]
        self.assertEqual(sen, [], "sanet's own SEN Battery line goes only to clients that said SANET")
        self.assertGreater(len(sta), 3)
        for t, seconds in sta:  # whole seconds left at the draw now
            self.assertLessEqual(abs(seconds - (40 - watts * t) / watts), 1.5, f"at {t}")

    def test_a_switched_off_robot_ignores_drive_from_its_client(self):
        before, after = self.switched["before"], self.switched["after"]
        self.assertGreater(before[-1] - before[0], 0.1, "the robot should move before it is switched off")
        self.assertLess(max(after) - min(after), 0.01, "a switched-off robot must not move")
        self.assertTrue(any("switched off" in e for e in self.switched["errors"]))

    def test_a_switched_off_robot_sends_nothing(self):
        self.assertTrue(any("switched off: SEND ignored" in e for e in self.switched["errors"]))
        self.assertFalse([r for r in self.rows if r["from"] == "off"])

    def test_bad_lines_get_errors_that_say_what_is_wrong(self):
        errors = "\n".join(self.messages["errors"])
        for expected in ["no node named 'nobody'", "expected hex bytes", "expected unicast, broadcast or flood",
                         "SEND to one node needs (To node)", "that is this robot", "TRANSITION needs",
                         "STATS needs a whole number from 0 to 2^53 'Steps", "RECV needs (From node)"]:
            self.assertIn(expected, errors)
        for line in self.messages["errors"]:  # a client's parser sees one field: no braces inside it
            self.assertEqual((line.count("{"), line.count("}")), (1, 1), line)

    def test_the_mote_message_reaches_the_client_over_the_simulated_network(self):
        received = self.messages["received"]
        self.assertEqual(len(received), 4)
        for line in received:
            self.assertEqual(field(line, "From"), "m1")
            self.assertEqual(field(line, "Delivery"), "unicast")
            self.assertEqual(len(field(line, "Data")), 16)  # 8 bytes
            self.assertGreater(float(field(line, "TimeReceived")), float(field(line, "TimeSent")))

    def test_both_directions_are_in_messages_csv(self):
        to_robot = [r for r in self.rows if r["from"] == "m1" and r["to"] == "r1" and r["time_received"]]
        replies = [r for r in self.rows if r["from"] == "r1" and r["to"] == "m1"]
        self.assertGreaterEqual(len(to_robot), 4)
        self.assertEqual(len(replies), 4)
        for r in replies:
            self.assertEqual(r["bytes"], "4")
            self.assertGreater(float(r["delay"]), 0)

    def test_messages_to_a_robot_whose_client_is_gone_are_lost(self):
        lost = [r for r in self.rows if r["from"] == "m1" and r["to"] == "r1" and not r["time_received"]]
        self.assertGreater(len(lost), 5)
        self.assertEqual(self.summary["messages_lost_before_their_controller"], len(lost))
        last_delivered = max(float(r["time_sent"]) for r in self.rows if r["to"] == "r1" and r["time_received"])
        self.assertTrue(all(float(r["time_sent"]) > last_delivered for r in lost))


if __name__ == "__main__":
    unittest.main(verbosity=2)
