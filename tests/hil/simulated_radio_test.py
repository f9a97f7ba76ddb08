#!/usr/bin/env python3
"""Real programs over the simulated radio (loop.network: simulated): each agent's namespace has a
tap, radio0, whose packets cross ns-3's 802.11 network between the robots' simulated positions.
- ping from one robot to another stops when the second drives out of range and resumes when it
  comes back; the largest distance at which it got through agrees with the log-distance model;
- a real UDP datagram from A to C crosses mote B, the only route, and B's forwarded count shows it;
- a TCP stream (iperf3) carries data at a rate bounded by the simulated 802.11b data rate;
- IPv4 multicast (what DDS discovery sends) crosses the radio as group frames to the robots in
  range: heard while near, not while out of range, heard again when back;
- a ROS 2-style DDS chatter (C, Cyclone) between two robots' namespaces crosses the radio with
  the shipped configuration (examples/ros2/cyclonedds-radio0.xml: ROS 2's default multicast
  discovery) and with unicast peers, stops while out of range and resumes, and none of it
  crosses the bridge to the server;
- the formation of case study 2 (scenarios/formation-radio.yaml, shortened) keeps its distances
  while the agents' poses cross the simulated radio.
Needs root and /dev/net/tun: elsewhere it says why and is skipped (exit 77)."""
import csv
import json
import os
import re
import subprocess
import sys
import tempfile
import time
import unittest

from radio_launch import permitted

from dds_ports import BridgeSniffer

SANET = sys.argv.pop(1)
SOURCE = sys.argv.pop(1)
CHATTER = sys.argv.pop(1) if len(sys.argv) > 1 and not sys.argv[1].startswith("-") else None
TX_POWER = 0  # dBm
RANGE = 10 ** ((TX_POWER - 46.6777 + 82) / 30)  # m: log-distance (exponent 3, 46.6777 dB at 1 m) meets -82 dBm

PING = f"""duration: 28
network: {{tx_power: {TX_POWER}, routing: aodv}}
loop: {{network: simulated}}
nodes:
  - {{name: base, model: omni3, pose: [0, 0, 0], controller: {{name: constant_velocity, params: {{vx: 0}}}}}}
  - name: rover
    model: omni3
    pose: [10, 0, 0]
    controller: {{name: waypoint, params: {{waypoints: [[20, 0], [10, 0]], speed: 1.0}}}}
"""

RELAY = f"""duration: 14
network: {{tx_power: {TX_POWER}, routing: aodv}}
loop: {{network: simulated}}
nodes:
  - {{name: a, model: omni3, pose: [0, 0, 0], controller: {{name: constant_velocity, params: {{vx: 0}}}}}}
  - {{name: b, model: mote, pose: [12, 0, 0]}}
  - {{name: c, model: omni3, pose: [24, 0, 0], controller: {{name: constant_velocity, params: {{vx: 0}}}}}}
"""

TCP = """duration: 14
network: {radio: 802.11b, data_rate: 11, routing: aodv}
loop: {network: simulated}
nodes:
  - {name: a, model: omni3, pose: [0, 0, 0], controller: {name: constant_velocity, params: {vx: 0}}}
  - {name: b, model: omni3, pose: [5, 0, 0], controller: {name: constant_velocity, params: {vx: 0}}}
"""

LISTEN = """import socket, sys
s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
s.bind(("10.0.0.3", 5000))
s.settimeout(12)
try:
    while True:
        data, peer = s.recvfrom(2048)
        print(peer[0], data.decode(), flush=True)
except socket.timeout:
    pass
"""

SEND = """import socket, time
s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
for i in range(30):
    s.sendto(b"hello %d" % i, ("10.0.0.3", 5000))
    time.sleep(0.1)
"""


MULTICAST_LISTEN = """import socket, struct, sys, time
s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
s.bind(("239.255.0.1", 7400))
s.setsockopt(socket.IPPROTO_IP, socket.IP_ADD_MEMBERSHIP, socket.inet_aton("239.255.0.1") + socket.inet_aton("10.0.0.1"))
s.settimeout(14)  # longer than the rover is out of range
try:
    while True:
        data, peer = s.recvfrom(2048)
        print(peer[0], data.decode(), flush=True)
except socket.timeout:
    pass
"""

MULTICAST_SEND = """import socket, time
s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
s.setsockopt(socket.IPPROTO_IP, socket.IP_MULTICAST_IF, socket.inet_aton("10.0.0.2"))
s.setsockopt(socket.IPPROTO_IP, socket.IP_MULTICAST_TTL, 1)
for i in range(240):
    s.sendto(b"%d" % i, ("239.255.0.1", 7400))
    time.sleep(0.1)
"""


# The rover stays in range for 13 s, which leaves DDS's discovery time to finish even when its first
# multicast announcement is lost (it is not repeated for seconds), then goes out of range (15 m) for
# about five seconds, shorter than DDS's 10 s lease, and comes back.
DDS_TEAM = f"""duration: 28
network: {{tx_power: {TX_POWER}, routing: aodv}}
loop: {{network: simulated}}
nodes:
  - {{name: base, model: omni3, pose: [0, 0, 0], controller: {{name: constant_velocity, params: {{vx: 0}}}}}}
  - name: rover
    model: omni3
    pose: [10, 0, 0]
    controller: {{name: waypoint, params: {{waypoints: [[6, 0], [17.5, 0], [10, 0]], speed: 1.0}}}}
"""

UNICAST_PEERS = """<CycloneDDS><Domain Id="any"><General><Interfaces><NetworkInterface name="radio0" multicast="false"/>
</Interfaces><AllowMulticast>false</AllowMulticast></General><Discovery><Peers><Peer address="10.0.0.1"/>
<Peer address="10.0.0.2"/></Peers><ParticipantIndex>auto</ParticipantIndex></Discovery></Domain></CycloneDDS>"""


class Launch:
    """`sanet launch` running in the background; knows each agent's namespace."""

    def __init__(self, folder, scenario, *extra):
        self.out = os.path.join(folder, "out")
        path = os.path.join(folder, "scenario.yaml")
        with open(path, "w") as f:
            f.write(scenario)
        self.process = subprocess.Popen([SANET, "launch", path, "-o", self.out, *extra], stdout=subprocess.PIPE,
                                        stderr=subprocess.STDOUT, text=True)
        self.namespaces, self.lines = {}, []
        for line in self.process.stdout:
            self.lines.append(line)
            m = re.match(r"\s*agent (\S+): process \d+ in namespace (\S+)", line)
            if m:
                self.namespaces[m.group(1)] = m.group(2)
            if len(self.namespaces) == scenario.count("controller:"):  # every agent has started
                break

    def run_in(self, robot, *command, **kwargs):
        return subprocess.run(["ip", "netns", "exec", self.namespaces[robot], *command], **kwargs)

    def finish(self):
        rest = self.process.communicate(timeout=90)[0]
        self.lines.append(rest)
        assert self.process.returncode == 0, "".join(self.lines)
        return self.out


def rows(folder, name):
    with open(os.path.join(folder, name)) as f:
        return list(csv.DictReader(f))


class Refusal(unittest.TestCase):
    def test_without_privileges_the_run_says_what_is_missing_and_refuses(self):
        with tempfile.TemporaryDirectory() as tmp:
            os.chmod(tmp, 0o777)
            path = os.path.join(tmp, "s.yaml")
            with open(path, "w") as f:
                f.write(TCP)
            os.chmod(path, 0o644)
            # As an unprivileged user (dropping root's rights if the test has them).
            drop = ["setpriv", "--reuid=65534", "--regid=65534", "--clear-groups"] if os.geteuid() == 0 else []
            out = subprocess.run(drop + [SANET, "launch", path, "-o", os.path.join(tmp, "out")], capture_output=True,
                                 text=True, timeout=60)
            self.assertNotEqual(out.returncode, 0)
            self.assertIn("loop.network: simulated needs network namespaces and tap devices", out.stderr)
            self.assertIn("root", out.stderr)
            self.assertIn("does not fall back", out.stderr)
            self.assertFalse(os.path.exists(os.path.join(tmp, "out")), "nothing runs")

    def test_options_that_cannot_work_are_refused_before_anything_starts(self):
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "s.yaml")
            with open(path, "w") as f:
                f.write(RELAY)
            for args, says in [(["--exec", "b", "--", "true"], "'b' is not a robot with a process of its own here (a or c)"),
                               (["--exec", "A", "--", "true"], "did you mean a"),
                               (["--exec", "a,a", "--", "true"], "'a' is named twice"),
                               (["--exec", "all,c", "--", "true"], "'all' stands alone"),
                               (["--exec", "a"], "give the program to run after --"),
                               (["--udp-base", "9000"], "9000 is network.port")]:
                out = subprocess.run([SANET, "launch", path, "-o", os.path.join(tmp, "out"), *args],
                                     capture_output=True, text=True, timeout=60)
                self.assertEqual(out.returncode, 2, out.stderr)
                self.assertIn(says, out.stderr)


@unittest.skipIf(permitted(), f"the simulated radio needs root and /dev/net/tun ({permitted()})")
class SimulatedRadio(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.tmp.cleanup()

    def test_ping_stops_out_of_range_and_resumes(self):
        run = Launch(self.tmp.name, PING, "--exec", "base", "--", "ping", "-i", "0.1", "-W", "1", "-q", "10.0.0.2")
        out = run.finish()
        track = [(float(r["time"]), float(r["x"])) for r in rows(out, "trajectories.csv") if r["node"] == "rover"]

        def x_at(t):
            return max((p for p in track if p[0] <= t), default=track[0])[1]

        pings = [float(r["time"]) for r in rows(out, "packets/rover.csv")
                 if r["event"] == "received" and r["protocol"] == "ip" and r["peer"] == "base"]
        self.assertGreater(len(pings), 50, "pings should reach the rover while it is near")
        farthest = max(x_at(t) for t in pings)
        self.assertLess(abs(farthest - RANGE) / RANGE, 0.10, f"pings got through up to {farthest:.2f} m, model {RANGE:.2f} m")
        gaps = [(a, b) for a, b in zip(pings, pings[1:]) if b - a > 2]
        self.assertEqual(len(gaps), 1, f"one silence while out of range, not {gaps}")
        self.assertGreater(x_at(gaps[0][0]), RANGE * 0.9)
        self.assertGreater(max(x for _, x in track), RANGE * 1.2, "the rover left the range")
        self.assertLess(x_at(pings[-1]), RANGE, "pings resumed after the rover came back")
        taps = {r["node"]: r for r in rows(out, "taps.csv")}
        self.assertGreater(int(taps["base"]["unicast_lost"]), 20, "requests sent while out of range are lost")
        # The real packets count as the node's own in packets.csv, and start AODV discoveries.
        packets = {r["node"]: r for r in rows(out, "packets.csv")}
        self.assertGreaterEqual(int(packets["base"]["sent"]), int(taps["base"]["packets_sent"]))
        discoveries = [r for r in rows(out, "routes.csv") if r["node"] == "base" and r["destination"] == "rover"]
        self.assertGreaterEqual(len(discoveries), 2, "one at the start, one when the rover is back")
        self.assertEqual(taps["rover"]["packets_received"], taps["rover"]["packets_sent"], "every request answered")

    def test_multicast_reaches_the_robots_in_range_only(self):
        run = Launch(self.tmp.name, PING)
        listener = subprocess.Popen(["ip", "netns", "exec", run.namespaces["base"], sys.executable, "-c",
                                     MULTICAST_LISTEN], stdout=subprocess.PIPE, text=True)
        time.sleep(0.5)
        run.run_in("rover", sys.executable, "-c", MULTICAST_SEND, check=True, timeout=60)
        heard = [int(line.split()[1]) for line in listener.communicate(timeout=30)[0].splitlines()
                 if line.startswith("10.0.0.2 ")]
        out = run.finish()
        self.assertGreater(len(heard), 50, "heard while the rover is near")
        gaps = [(a, b) for a, b in zip(heard, heard[1:]) if b - a > 20]
        self.assertEqual(len(gaps), 1, f"one silence while out of range, not {gaps}")
        self.assertGreater(heard[-1], gaps[0][1], "heard again once the rover is back")
        taps = {r["node"]: r for r in rows(out, "taps.csv")}
        self.assertGreaterEqual(int(taps["base"]["packets_received"]), len(heard))
        self.assertGreaterEqual(int(taps["rover"]["packets_sent"]), 240)

    def dds_chatter(self, uri):
        run = Launch(self.tmp.name, DDS_TEAM)
        sniffer = BridgeSniffer(run.namespaces["base"].split("-")[0] + "br")
        sniffer.start()
        env = dict(os.environ, CYCLONEDDS_URI=uri)
        env.pop("ROS_LOCALHOST_ONLY", None)
        sub = subprocess.Popen(["ip", "netns", "exec", run.namespaces["base"], CHATTER, "sub", "5", "26"],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
        run.run_in("rover", CHATTER, "pub", "5", "24", env=env, check=True, timeout=60)
        heard = [int(line) for line in sub.communicate(timeout=60)[0].split()]
        sniffer.finish()
        out = run.finish()
        self.assertGreater(len(heard), 80, "heard while the rover is near")
        self.assertTrue(all(b > a for a, b in zip(heard, heard[1:])), "in order, each once")
        gaps = [(a, b) for a, b in zip(heard, heard[1:]) if b - a > 15]
        self.assertEqual(len(gaps), 1, f"one silence while out of range, not {gaps}; heard {heard[0]}..{heard[-1]}")
        self.assertGreater(heard[-1], gaps[0][1] + 40, "heard again once the rover is back")
        self.assertGreater(sniffer.frames, 100, "the sniffer saw the bridge's traffic (the agents' connections)")
        self.assertEqual(sniffer.dds, 0, "the team's DDS traffic never crossed the bridge")
        taps = {r["node"]: r for r in rows(out, "taps.csv")}
        self.assertGreater(int(taps["rover"]["packets_sent"]), 100)

    @unittest.skipUnless(CHATTER, "give the ros2_chatter program")
    def test_dds_with_ros2s_default_discovery_crosses_the_radio_only(self):
        self.dds_chatter("file://" + os.path.join(SOURCE, "examples", "ros2", "cyclonedds-radio0.xml"))

    @unittest.skipUnless(CHATTER, "give the ros2_chatter program")
    def test_dds_with_unicast_peers_crosses_the_radio_only(self):
        self.dds_chatter(UNICAST_PEERS)

    def test_a_datagram_crosses_a_mote_that_is_the_only_route(self):
        self.assertGreater(24, RANGE * 1.2)
        run = Launch(self.tmp.name, RELAY)
        listener = subprocess.Popen(["ip", "netns", "exec", run.namespaces["c"], sys.executable, "-c", LISTEN],
                                    stdout=subprocess.PIPE, text=True)
        time.sleep(0.5)
        run.run_in("a", sys.executable, "-c", SEND, check=True, timeout=30)
        heard = listener.communicate(timeout=30)[0].split("\n")
        out = run.finish()
        heard = [h for h in heard if h.startswith("10.0.0.1 hello")]
        self.assertGreaterEqual(len(heard), 25, heard)
        packets = {r["node"]: r for r in rows(out, "packets.csv")}
        self.assertGreaterEqual(int(packets["b"]["forwarded"]), len(heard))
        self.assertEqual(int(packets["a"]["forwarded"]), 0)

    def test_tcp_is_bounded_by_the_simulated_data_rate(self):
        run = Launch(self.tmp.name, TCP, "--exec", "b", "--", "iperf3", "-s", "-1")
        time.sleep(1)
        result = run.run_in("a", "iperf3", "-c", "10.0.0.2", "-t", "6", "-J", capture_output=True, text=True,
                            timeout=60)
        out = run.finish()
        mbps = json.loads(result.stdout)["end"]["sum_received"]["bits_per_second"] / 1e6
        self.assertLess(mbps, 11, "802.11b at 11 Mbit/s cannot carry more")
        self.assertGreater(mbps, 1, "the stream should flow")
        with open(os.path.join(out, "summary.json")) as f:
            taps = json.load(f)["network"]["taps"]
        self.assertGreater(taps["b"]["bytes_received"], 6 * 1e6 / 8, "the stream crossed b's tap")

    def test_the_formation_keeps_its_distances_over_the_simulated_radio(self):
        scenario = os.path.join(SOURCE, "scenarios", "formation-radio.yaml")
        out = os.path.join(self.tmp.name, "formation")
        run = subprocess.run([SANET, "launch", scenario, "--duration", "25", "-o", out], capture_output=True,
                             text=True, timeout=120)
        self.assertEqual(run.returncode, 0, run.stdout + run.stderr)
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
        self.assertGreater(summary["min_distance"]["min_m"], 0.4, summary["min_distance"])
        for follower in ("f1", "f2", "f3"):
            self.assertGreater(summary["metrics"][follower]["pose_delay"]["count"], 230, follower)
        taps = summary["network"]["taps"]
        self.assertGreater(taps["leader"]["packets_sent"], 2 * 230, "poses to f1 and f2 at 10 Hz")
        self.assertGreater(taps["f3"]["packets_received"], 230, "f1 relays the poses to f3 over the radio")


if __name__ == "__main__":
    unittest.main(verbosity=2)
