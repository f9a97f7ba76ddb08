#!/usr/bin/env python3
"""The worked example of docs/ros2.md, as a user runs it: `sanet launch
scenarios/ros2-team-radio.yaml --exec all -- pose_team ...` with examples/ros2/cyclonedds-team.xml.
Three robots driven over the ROS 2 face (DDS domain 0, on the namespaces' bridge) publish their
poses to each other (DDS domain 1, on radio0) across the simulated radio, AODV running:
- the followers hear the leader while it is in range, never farther than the radio's range, stop
  hearing it while it is away and hear it again when it is back; they follow it, stop, follow;
- the face's domain crosses the bridge, the team's never does (the bridge's capture);
- the team's frames are in each robot's pcap (the leader's poses in the followers' while in
  range), and in taps.csv; the robots were driven by cmd_vel over the face (summary.json).
Needs root and /dev/net/tun: elsewhere it says why and is skipped."""
import csv
import json
import math
import os
import sys
import tempfile
import unittest

from dds_ports import domain_of, pcap_datagrams
from radio_launch import SniffedLaunch, permitted, ros2_team_environment

SANET, SOURCE, POSE_TEAM = sys.argv.pop(1), sys.argv.pop(1), sys.argv.pop(1)
SCENARIO = os.path.join(SOURCE, "scenarios", "ros2-team-radio.yaml")
TX_POWER = -5  # dBm, the scenario's
RANGE = 10 ** ((TX_POWER - 46.6777 + 82) / 30)  # m: log-distance (exponent 3, 46.6777 dB at 1 m) meets -82 dBm
FACE, TEAM = 0, 1  # DDS domains, as examples/ros2/cyclonedds-team.xml has them


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def track(out, robot):
    """[(time, x, y)] of a robot's true poses."""
    return [(float(r["time"]), float(r["x"]), float(r["y"])) for r in rows(os.path.join(out, "trajectories.csv"))
            if r["node"] == robot]


def at(positions, t):
    return min(positions, key=lambda p: abs(p[0] - t))


@unittest.skipIf(permitted(), f"the simulated radio needs root and /dev/net/tun ({permitted()})")
class TeamOverTheRadio(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.out, cls.heard = os.path.join(cls.tmp.name, "out"), os.path.join(cls.tmp.name, "heard")
        launch = SniffedLaunch([SANET, "launch", SCENARIO, "-o", cls.out, "--exec", "all", "--", POSE_TEAM, "--team",
                                "leader,f1,f2", "--route", "24,0:8,0", "--log", cls.heard], ros2_team_environment(SOURCE))
        cls.lines, cls.said, cls.sniffer, cls.server_address = launch.lines, launch.said, launch.sniffer, launch.server_address
        assert launch.returncode == 0, cls.said

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def heard_from_leader(self, follower):
        return [(float(r["stamp"]), float(r["heard_at"])) for r in rows(os.path.join(self.heard, follower + ".csv"))
                if r["peer"] == "leader"]

    def test_the_followers_hear_the_leader_in_range_only_and_again_when_it_is_back(self):
        leader = track(self.out, "leader")
        for follower in ("f1", "f2"):
            me = track(self.out, follower)
            heard = self.heard_from_leader(follower)
            self.assertGreater(len(heard), 100, follower)
            distances = [math.dist(at(leader, stamp)[1:], at(me, stamp)[1:]) for stamp, _ in heard]
            self.assertLess(max(distances), RANGE + 1.0, f"{follower} heard the leader beyond the radio's range")
            gaps = [(a, b) for (a, _), (b, _) in zip(heard, heard[1:]) if b - a > 5]
            self.assertEqual(len(gaps), 1, f"{follower}: one silence while the leader is away, not {gaps}")
            far = [t for t, x, y in leader if gaps[0][0] < t < gaps[0][1]]
            self.assertGreater(max(math.dist(at(leader, t)[1:], at(me, t)[1:]) for t in far), RANGE,
                               "the silence is the leader out of range")
            self.assertGreater(len([h for h in heard if h[0] > gaps[0][1]]), 25, f"{follower} hears the leader again")
            late = [heard_at - stamp for stamp, heard_at in heard]
            self.assertLess(sorted(late)[len(late) // 2], 0.2, "poses arrive within a few steps")

    def test_the_followers_follow_wait_and_follow_again(self):
        for follower in ("f1", "f2"):
            said = [line for line in self.lines if line.startswith(follower + " ")]
            kinds = [("following" if "following leader" in line else "lost") for line in said
                     if "following leader" in line or "lost leader" in line]
            self.assertEqual(kinds[:3], ["following", "lost", "following"], said)
            me = track(self.out, follower)
            self.assertGreater(max(x for _, x, _ in me), 0.0, f"{follower} moved towards the leader")
        end = track(self.out, "leader")[-1]
        self.assertLess(math.dist(end[1:], (8, 0)), 0.5, "the leader drove its route to its end")
        self.assertLess(math.dist(track(self.out, "f1")[-1][1:], end[1:]), 3.0, "f1 caught up with it")

    def team_participants(self):
        """The GUID prefixes of the participants whose RTPS messages crossed the radio."""
        return {d[4] for robot in ("leader", "f1", "f2")
                for d in pcap_datagrams(os.path.join(self.out, "pcap", robot + ".pcap")) if d[4]}

    def test_the_face_uses_the_bridge_and_the_team_never_does(self):
        face = self.sniffer.addresses[self.server_address]
        self.assertEqual(len(face), 1, "the server has one participant, the face's")
        self.assertGreater(self.sniffer.senders[next(iter(face))], 1000, "ground truth of three robots at 10 Hz")
        team = self.team_participants()
        self.assertEqual(len(team), 3, "one team participant per robot on the radio")
        self.assertFalse(team & set(self.sniffer.senders), "no team participant sent anything over the bridge")
        self.assertFalse(face & team, "the face's participant never on the radio")

    def test_the_team_frames_are_in_each_robots_pcap_and_in_the_results(self):
        for robot in ("leader", "f1", "f2"):
            datagrams = pcap_datagrams(os.path.join(self.out, "pcap", robot + ".pcap"))
            team = [d for d in datagrams if d[4]]
            self.assertGreater(len(team), 300, robot)
            self.assertTrue([d for d in team if domain_of(d[3]) == TEAM], "the team's discovery in domain 1")
            self.assertFalse([d for d in team if domain_of(d[3]) == FACE], "no discovery of the face's domain")
            if robot == "leader":
                continue
            from_leader = [d[0] for d in team if d[1] == "10.0.0.1"]
            silences = [(a, b) for a, b in zip(from_leader, from_leader[1:]) if b - a > 5]
            self.assertEqual(len(silences), 1, f"{robot}'s radio received nothing of the leader while it was away")
            heard = self.heard_from_leader(robot)
            gap = [(a, b) for (a, _), (b, _) in zip(heard, heard[1:]) if b - a > 5][0]
            self.assertLess(abs(silences[0][0] - gap[0]), 3.0, "the samples stopped with the frames")
        taps = {r["node"]: r for r in rows(os.path.join(self.out, "taps.csv"))}
        for robot in ("leader", "f1", "f2"):
            self.assertGreater(int(taps[robot]["packets_sent"]), 150, robot)
            self.assertGreater(int(taps[robot]["packets_received"]), 150, robot)
        packets = {r["node"]: r for r in rows(os.path.join(self.out, "packets.csv"))}
        for robot in ("leader", "f1", "f2"):
            self.assertGreater(int(packets[robot]["sent"]), 150, f"{robot}'s DDS packets count in packets.csv")
        with open(os.path.join(self.out, "summary.json")) as f:
            face = json.load(f)["ros2"]["robots"]
        for robot in ("leader", "f1", "f2"):
            self.assertGreater(face[robot]["cmd_vel_taken"], 500, f"{robot} was driven over the face")
            self.assertEqual(face[robot]["cmd_vel_refused_owned"], 0)

    def test_sanets_own_messages_beside_the_team_are_delivered(self):
        pings = [r for r in rows(os.path.join(self.out, "messages.csv")) if r["from"] == "beacon"]
        self.assertGreater(len(pings), 70, "one a second from 2 s")
        self.assertTrue(all(r["to"] == "sink" and r["time_received"] for r in pings))
        self.assertLess(max(float(r["delay"]) for r in pings), 0.1)


if __name__ == "__main__":
    unittest.main(verbosity=2)
