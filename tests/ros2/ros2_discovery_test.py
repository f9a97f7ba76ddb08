#!/usr/bin/env python3
"""`ros2 node list`'s view of sanet's ROS 2 face: what the face publishes on ros_discovery_info,
read by an independent DDS participant (tests/ros2/ros2_discovery.c: C on Cyclone DDS, the type
generated from IDL written from ROS 2's rmw_dds_common definitions, once with Humble's 24-byte Gid
and once with Iron's and Jazzy's 16-byte one) and checked against DDS's own discovery of the face
(the built-in DCPSParticipant, DCPSPublication and DCPSSubscription topics, which sanet's code
does not write):
- for each distro, read with its type: one node, /sanet (namespace "/", name "sanet"); the
  participant's gid is the face's participant GUID; its writer and reader gids are exactly the
  GUIDs of the face's ROS 2 writers and readers (every rt/ topic; not the ros_discovery_info writer
  itself), distinct, each a GUID and, in Humble, 8 zero bytes after it; the writer is reliable and
  transient local, so a reader that joins later reads it;
- a robot spawned during the run (INIT) adds its topics, and the face publishes the list again;
- read with the other distro's type, nothing names the node: Humble's type cannot decode a Jazzy
  sample (Cyclone drops it: "deserialization ... failed"), and Jazzy's type reads a Humble sample
  as a participant with no node (its node count falls in the gid's zero padding);
- ros2.distro defaults to jazzy, --ros2-distro overrides it, and a value that is neither is refused
  with the file, line and field."""
import os
import socket
import subprocess
import sys
import tempfile
import threading
import time
import unittest

SANET, READER = sys.argv.pop(1), {"humble": sys.argv.pop(1), "jazzy": sys.argv.pop(1)}
DOMAIN = 23  # its own: tests run side by side (ros2_face has 21, ros2_agent 22; launches take 101 down)
GID_BYTES = {"humble": 24, "jazzy": 16}

SCENARIO = """name: ros2-discovery
duration: {duration}
spawn: {{}}
nodes:
  - {{name: r1, model: diffdrive, pose: [0, 0, 0]}}
  - {{name: r2, model: omni3, pose: [0, 4, 0]}}
  - {{name: m0, model: mote, pose: [6, 0, 0]}}
ros2:
  domain: {domain}
{distro}"""


def scenario(tmp, duration, distro=None):
    path = os.path.join(tmp, "s.yaml")
    with open(path, "w") as f:
        f.write(SCENARIO.format(duration=duration, domain=DOMAIN,
                                distro=f"  distro: {distro}\n" if distro else ""))
    return path


class Served:
    def __init__(self, tmp, duration, distro=None, *extra):
        self.out = os.path.join(tmp, "out")
        port_file = os.path.join(tmp, "port")
        self.process = subprocess.Popen([SANET, "serve", scenario(tmp, duration, distro), "--port", "0", "--port-file",
                                         port_file, "-o", self.out, *extra],
                                        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        deadline = time.time() + 30
        while not os.path.exists(port_file):
            assert time.time() < deadline and self.process.poll() is None, self.process.communicate()
            time.sleep(0.02)
        with open(port_file) as f:
            self.port = int(f.read())

    def spawn(self, name):
        """Adds a robot as a USARSim client does (INIT with a class); keeps the connection read."""
        self.usarsim = socket.create_connection(("127.0.0.1", self.port))
        self.usarsim.sendall(f"INIT {{ClassName USARBot.P2DX}} {{Name {name}}} {{Location 2,2,0.2}}\r\n".encode())
        threading.Thread(target=self._drain, daemon=True).start()

    def _drain(self):
        try:
            while self.usarsim.recv(65536):
                pass
        except OSError:
            pass

    def finish(self):
        self.stdout, self.stderr = self.process.communicate(timeout=60)
        assert self.process.returncode == 0, self.stderr
        return self.stdout, self.stderr


class Seen:
    """What ros2_discovery printed: DDS's discovery of the face, and each ros_discovery_info sample."""

    def __init__(self, stdout, stderr):
        self.stderr = stderr
        self.participants, self.publications, self.subscriptions, self.samples = {}, {}, {}, []
        for line in stdout.splitlines():
            kind, *f = line.split()
            if kind == "participant":
                self.participants[f[0]] = f[1]
            elif kind == "publication":
                self.publications[f[0]] = {"participant": f[1], "topic": f[2], "type": f[3], "qos": f[4] + f[5]}
            elif kind == "subscription":
                self.subscriptions[f[0]] = {"participant": f[1], "topic": f[2], "type": f[3]}
            elif kind == "info":
                self.samples.append({"gid": f[1], "nodes": []})
            elif kind == "node":
                self.samples[int(f[0])]["nodes"].append({"ns": f[1], "name": f[2], "readers": [], "writers": []})
            elif kind in ("reader", "writer"):
                self.samples[int(f[0])]["nodes"][-1][kind + "s"].append(f[1])
            elif kind == "samples":
                self.count = int(f[0])


def read(distro, seconds):
    return subprocess.Popen([READER[distro], str(DOMAIN), str(seconds)], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)


def seen(process):
    stdout, stderr = process.communicate(timeout=60)
    assert process.returncode == 0, stderr
    return Seen(stdout, stderr)


class Discovery(unittest.TestCase):
    def check_node(self, distro, seen, robots):
        self.assertEqual(len(seen.participants), 1, "the face's participant, and no other")
        (face, user_data), = seen.participants.items()
        self.assertEqual(user_data, "enclave=/;", "as rmw_cyclonedds says its enclave")
        self.assertEqual(seen.publications.pop(next(k for k, p in seen.publications.items()
                                                    if p["topic"] == "ros_discovery_info")),
                         {"participant": face, "topic": "ros_discovery_info", "qos": "RT",
                          "type": "rmw_dds_common::msg::dds_::ParticipantEntitiesInfo_"})
        self.assertGreaterEqual(len(seen.samples), 1)
        size = GID_BYTES[distro] * 2  # hex
        padding = "00" * (GID_BYTES[distro] - 16)
        for sample in seen.samples:
            self.assertEqual(len(sample["gid"]), size)
            self.assertEqual(sample["gid"], face + padding, "the participant's GUID, zero-padded in Humble")
            self.assertEqual([(n["ns"], n["name"]) for n in sample["nodes"]], [("/", "sanet")])
            for kind in ("readers", "writers"):
                gids = sample["nodes"][0][kind]
                self.assertEqual(len(set(gids)), len(gids), "distinct")
                for gid in gids:
                    self.assertEqual(len(gid), size)
                    self.assertTrue(gid.endswith(padding))
        last = seen.samples[-1]["nodes"][0]
        # Every writer and reader the face has, as DDS discovered them, and nothing else.
        self.assertEqual(sorted(g[:32] for g in last["writers"]), sorted(seen.publications))
        self.assertEqual(sorted(g[:32] for g in last["readers"]), sorted(seen.subscriptions))
        topics = {p["topic"] for p in seen.publications.values()}
        for robot in robots:
            self.assertLessEqual({f"rt/{robot}/odom", f"rt/{robot}/ground_truth"}, topics)
        self.assertLessEqual({"rt/clock", "rt/tf", "rt/tf_static", "rt/r1/scan", "rt/r2/ir_0"}, topics)
        self.assertEqual({s["topic"] for s in seen.subscriptions.values()}, {f"rt/{r}/cmd_vel" for r in robots})
        self.assertTrue(all(p["participant"] == face for p in [*seen.publications.values(),
                                                                *seen.subscriptions.values()]))

    def test_each_distro_reads_the_node_with_every_topic_and_a_spawned_robots_too(self):
        for distro in ("humble", "jazzy"):
            with self.subTest(distro=distro), tempfile.TemporaryDirectory() as tmp:
                # jazzy by default: no distro field
                served = Served(tmp, 9, "humble" if distro == "humble" else None)
                time.sleep(1)  # a reader that joins after the face published still reads it (transient local)
                reader = read(distro, 6)
                time.sleep(2.5)
                served.spawn("probe")
                got = seen(reader)
                served.usarsim.close()
                said, _ = served.finish()
                self.assertIn(f"node /sanet for ROS 2 {'Humble' if distro == 'humble' else 'Jazzy'}", said)
                self.check_node(distro, got, ["r1", "r2", "probe"])
                first = got.samples[0]["nodes"][0]
                last = got.samples[-1]["nodes"][0]
                probe = {g for g, p in got.publications.items() if p["topic"].startswith("rt/probe/")}
                self.assertTrue(probe, "the spawned robot's topics")
                self.assertFalse(probe & {g[:32] for g in first["writers"]}, "not yet in the first sample")
                self.assertLessEqual(probe, {g[:32] for g in last["writers"]}, "published again with them")
                self.assertEqual(len(last["readers"]), len(first["readers"]) + 1, "its cmd_vel")

    def test_the_other_distros_type_reads_no_node(self):
        with tempfile.TemporaryDirectory() as tmp:
            served = Served(tmp, 4)
            got = seen(read("humble", 2))
            served.finish()
        self.assertEqual(got.count, 0, "Humble's 24-byte Gid cannot decode a Jazzy sample")
        self.assertIn("deserialization ros_discovery_info", got.stderr)
        self.assertEqual(len(got.participants), 1, "though DDS sees the participant")
        with tempfile.TemporaryDirectory() as tmp:
            served = Served(tmp, 4, "jazzy", "--ros2-distro", "humble")  # the option over the section
            got = seen(read("jazzy", 2))
            served.finish()
        face, = got.participants
        self.assertGreaterEqual(got.count, 1)
        for sample in got.samples:
            self.assertEqual(sample["gid"], face, "the first 16 bytes of Humble's Gid")
            self.assertEqual(sample["nodes"], [], "the node count falls in the Gid's zero padding")

    def test_a_distro_that_is_neither_is_refused(self):
        with tempfile.TemporaryDirectory() as tmp:
            path = scenario(tmp, 1, "iron")
            out = subprocess.run([SANET, "serve", path, "--port", "0", "-o", os.path.join(tmp, "o")],
                                 capture_output=True, text=True, timeout=30)
            self.assertNotEqual(out.returncode, 0)
            self.assertIn(f"{path}:10", out.stderr)
            self.assertIn("'ros2.distro': unknown value 'iron' (expected one of: humble, jazzy)", out.stderr)
            out = subprocess.run([SANET, "serve", scenario(tmp, 1), "--port", "0", "-o", os.path.join(tmp, "o"),
                                  "--ros2-distro", "rolling"], capture_output=True, text=True, timeout=30)
            self.assertNotEqual(out.returncode, 0)
            self.assertIn("--ros2-distro", out.stderr)


if __name__ == "__main__":
    unittest.main(verbosity=2)
