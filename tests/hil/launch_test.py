#!/usr/bin/env python3
"""sanet launch runs the formation with four agent processes over real UDP (loopback),
shortened to 25 s: the robots keep their distances and the followers hear the leader."""
import json
import os
import re
import socket
import struct
import subprocess
import sys
import tempfile
import threading
import time

sanet, source = sys.argv[1], sys.argv[2]


def slots_held(slots):
    """Whether every one of these launch slots is held by a launch running now (which may have
    made namespaces of the same names since)."""
    import fcntl
    folder = "/run/lock/sanet" if os.access("/run/lock", os.W_OK) else "/tmp/sanet-locks"
    for slot in slots:
        fd = os.open(os.path.join(folder, "slot-%s.lock" % slot), os.O_RDONLY)
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
            return False
        except BlockingIOError:
            pass
        finally:
            os.close(fd)
    return True


def forge(port, count):
    """Another process on the machine speaks for the leader to f1 (node 1, port base + 1): a pose
    with the highest sequence number, in the datagram's layout but without the run's key, and in
    the layout of sanet before datagrams were authenticated."""
    time.sleep(4)
    s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    payload = struct.pack("<Bdddd", 1, 9.0, 9.0, 0.0, 1.0)
    for i in range(count):
        header = struct.pack("<BBIIBQd", 0x53, 2, 0, 1, 1, 2**64 - 1 - i, 1.0)
        s.sendto(header + payload + os.urandom(32), ("127.0.0.1", port))
        s.sendto(struct.pack("<BIIBd", 0x53, 0, 1, 1, 1.0) + struct.pack("<I", 2**32 - 1) + payload, ("127.0.0.1", port))
        time.sleep(0.02)


with tempfile.TemporaryDirectory() as tmp:
    launch = subprocess.Popen([sanet, "launch", os.path.join(source, "scenarios", "formation-hil.yaml"), "--duration",
                               "25", "-o", tmp, "--udp-base", "47500"], stdout=subprocess.PIPE,
                              stderr=subprocess.STDOUT, text=True)
    said = []
    for line in launch.stdout:  # another launch on this machine shifts the ports: this one says where
        said.append(line)
        if "agents on loopback" in line:
            base = int(line.split("UDP port ")[1].split()[0])
            assert base == 47500 or (base - 47500) % 256 == 0, line
            break
    forger = threading.Thread(target=forge, args=(base + 1, 150), daemon=True)
    forger.start()
    said.append(launch.stdout.read())  # through the same buffer as the lines above
    launch.wait(timeout=120)
    out = subprocess.CompletedProcess(launch.args, launch.returncode, "".join(said), "".join(said))
    print(out.stdout, out.stderr)
    assert out.returncode == 0, out.returncode
    assert len(re.findall(r"^  agent \S+: process", out.stdout, re.M)) == 4, out.stdout
    summary = json.load(open(os.path.join(tmp, "summary.json")))
    assert summary["min_distance"]["min_m"] > 0.4, summary["min_distance"]
    assert summary["min_distance"]["fraction_within_10_percent"] > 0.8, summary["min_distance"]
    # Exact rates in the loop: the leader's steps (and poses) on the 10 Hz grid.
    agents = summary["agents"]
    leader_stats = agents["leader"]
    assert abs(leader_stats["achieved_rate_hz"] - 10) < 0.1, leader_stats
    assert leader_stats["steps"] > 230 and leader_stats["messages_sent"] == 2 * leader_stats["steps"], leader_stats
    for follower in ("f1", "f2", "f3"):
        heard = summary["metrics"][follower]["pose_delay"]["count"]
        assert heard > 240, (follower, heard)  # 10 Hz for 25 s
        missed = summary["metrics"][follower]["pose_missed"]  # poses due but never received
        assert missed["count"] == heard and missed["max"] <= 2, (follower, missed)
        assert set(agents[follower]) >= {"steps", "steps_missed", "lateness_p99_s", "messages_received"}
    # messages.csv lists what the agents said to each other over UDP, with its delays.
    import csv
    with open(os.path.join(tmp, "messages.csv")) as f:
        rows = list(csv.DictReader(f))
    to_f1 = [r for r in rows if r["from"] == "leader" and r["to"] == "f1"]
    relayed = [r for r in rows if r["from"] == "f1" and r["to"] == "f3"]
    assert abs(len(to_f1) - summary["metrics"]["f1"]["pose_delay"]["count"]) <= 1, len(to_f1)
    assert len(relayed) > 240, len(relayed)
    late = [r for r in to_f1 + relayed if not 0 < float(r["delay"]) < 0.5]
    assert not late, late[:3]  # says which message, and when, if one ever is
    assert summary["rows"]["messages"] == len(rows)
    leader = [r for r in open(os.path.join(tmp, "trajectories.csv")) if ",leader," in r]
    assert float(leader[-1].split(",")[2]) > 5, "the leader drove"
    # agents.csv: each agent's packets over UDP, as it counted them (the leader's poses went to
    # f1 and f2 as one datagram each; f1 relays to f3).
    with open(os.path.join(tmp, "agents.csv")) as f:
        table = {r["node"]: r for r in csv.DictReader(f)}
    assert sorted(table) == ["f1", "f2", "f3", "leader"], table.keys()
    assert int(table["leader"]["datagrams_sent"]) == leader_stats["messages_sent"], table["leader"]
    assert int(table["f1"]["datagrams_sent"]) == agents["f1"]["messages_sent"] > 240, table["f1"]
    assert int(table["f3"]["datagrams_received"]) > 240 and table["f3"]["send_errors"] == "0", table["f3"]
    # The forged datagrams were all rejected (and the real leader still heard: pose_missed above).
    assert int(table["f1"]["datagrams_rejected"]) == 300, table["f1"]
    assert table["f2"]["datagrams_rejected"] == table["f3"]["datagrams_rejected"] == "0"
    assert "f1: rejected a datagram" in out.stderr, out.stderr
    assert "agents.csv" in summary["files"]
    print("lag:", summary["real_time_lag"])

# Each agent in its own network namespace (or, where the machine does not allow it, a clear
# fallback to loopback), with the scenario's message impairments applied in the agents.
NAMESPACED = """duration: 12
nodes:
  - name: leader
    model: diffdrive
    pose: [0, 0, 0]
    controller: {name: formation_leader, params: {corners: [[0, 0], [20, 0]], send_to: [f1]}}
  - name: f1
    model: diffdrive
    pose: [-1.7, 0, 0]
    controller: {name: formation_follower, params: {offset: [-1.7, 0]}}
messages: {loss: 0.2, delay: 0.05}
loop:
  namespaces: true
  udp_port: 47600
outputs: {min_distance: true}
"""
with tempfile.TemporaryDirectory() as tmp:
    path = os.path.join(tmp, "ns.yaml")
    open(path, "w").write(NAMESPACED)
    out = subprocess.run([sanet, "launch", path, "-o", os.path.join(tmp, "out")], capture_output=True, text=True,
                         timeout=120)
    print(out.stdout, out.stderr)
    assert out.returncode == 0, out.returncode
    assert ("in its own network namespace" in out.stdout and "in namespace " in out.stdout) or \
        "falling back to loopback" in out.stdout, out.stdout
    summary = json.load(open(os.path.join(tmp, "out", "summary.json")))
    delay = summary["metrics"]["f1"]["pose_delay"]
    missed = summary["metrics"]["f1"]["pose_missed"]["mean"]
    assert delay["count"] > 50 and 0.045 < delay["median"] < 0.1, delay  # 50 ms added
    assert 0.1 < missed < 0.45, missed  # a fifth lost: about 0.25 missed per pose received
    made = set(re.findall(r"in namespace (sanet\d+-\d+)", out.stdout))
    left = made & set(subprocess.run(["ip", "netns", "list"], capture_output=True, text=True).stdout.split())
    slots = {name.split("-")[0][len("sanet"):] for name in left}
    assert not left or slots_held(slots), ("namespaces removed", left)

# An agent's robot and a mote that lives only in the server talk through the robot's own ns-3
# node: the agent's SEND crosses the simulated network to the mote, the mote's messages reach
# the agent as MSG lines; messages.csv holds both directions. The robot's message size comes from
# --set: the agent runs the effective scenario, not the file.
WITH_MOTE = """duration: 8
network: {routing: aodv}
nodes:
  - name: m1
    model: mote
    pose: [0, 0, 0]
    controller: {name: pinger, params: {to: r1, interval: 0.5, start: 1, size: 8}}
  - name: r1
    model: diffdrive
    pose: [10, 0, 0]
    controller: {name: pinger, params: {to: m1, interval: 0.5, start: 1, size: 6}}
loop: {udp_port: 47700}
"""
with tempfile.TemporaryDirectory() as tmp:
    path = os.path.join(tmp, "mote.yaml")
    with open(path, "w") as f:
        f.write(WITH_MOTE)
    out = subprocess.run([sanet, "launch", path, "-o", os.path.join(tmp, "out"), "--set",
                          "nodes.r1.controller.params.size=9"], capture_output=True, text=True, timeout=60)
    print(out.stdout, out.stderr)
    assert out.returncode == 0, out.returncode
    import csv
    with open(os.path.join(tmp, "out", "messages.csv")) as f:
        rows = list(csv.DictReader(f))
    to_robot = [r for r in rows if r["from"] == "m1" and r["to"] == "r1" and r["time_received"]]
    to_mote = [r for r in rows if r["from"] == "r1" and r["to"] == "m1"]
    assert len(to_robot) >= 10 and len(to_mote) >= 10, (len(to_robot), len(to_mote))
    assert all(r["bytes"] == "9" and float(r["delay"]) > 0 and r["hops"] == "1" for r in to_mote), to_mote[:3]
    print("agent <-> mote:", len(to_robot), "and", len(to_mote), "messages")
