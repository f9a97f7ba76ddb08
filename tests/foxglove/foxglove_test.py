#!/usr/bin/env python3
"""sanet's Foxglove WebSocket stream against the protocol's own client (tests/foxglove/client.mjs:
npm's @foxglove/ws-protocol over ws, messages decoded with @foxglove/rosmsg2-serialization from the
advertised schemas): a live run's /tf and a robot's scan arrive with simulated timestamps that
advance and equal the messages' stamps; a client that stops reading (a raw RFC 6455 client with a
small receive buffer) is dropped while another keeps receiving, and the run's results do not change;
garbage, unknown operations and clients without the subprotocol are answered as the protocol says;
the connection cap holds; a finished run's trace.mcap replays in time order with every message the
log has."""
import base64
import json
import os
import socket
import subprocess
import sys
import tempfile
import threading
import time
import unittest

SANET, MODULES, SOURCE = sys.argv[1:4]
del sys.argv[1:4]
CLIENT = os.path.join(SOURCE, "tests", "foxglove", "client.mjs")
DECODER = os.path.join(SOURCE, "tests", "mcap", "decode_mcap.mjs")
FORMATION = os.path.join(SOURCE, "scenarios", "formation.yaml")
HELP_REQUEST = os.path.join(SOURCE, "scenarios", "help-request.yaml")


def client(*args, timeout=120):
    done = subprocess.run(["node", CLIENT, MODULES, *args], capture_output=True, text=True, timeout=timeout)
    if done.returncode != 0:
        raise AssertionError(done.stderr)
    return json.loads(done.stdout)


def wait_for(path, process, seconds=30):
    end = time.time() + seconds
    while time.time() < end:
        if os.path.exists(path):
            with open(path) as f:
                text = f.read().strip()
            if text:
                return int(text)
        if process.poll() is not None:
            raise AssertionError(f"sanet ended early: {process.communicate()}")
        time.sleep(0.05)
    raise AssertionError(f"{path} never written")


def fingerprint(folder):
    with open(os.path.join(folder, "summary.json")) as f:
        return json.load(f)["fingerprint"]


class StallingClient(threading.Thread):
    """A Foxglove client that subscribes to every channel and then stops reading, written from RFC 6455
    and the protocol's spec on a raw socket: its receive buffer is set small before it connects, so
    the kernel cannot absorb megabytes for it and the server's own queue must fill however fast or
    slow the run and this machine are."""

    def __init__(self, url, run):
        super().__init__()
        self.host, self.port = url.removeprefix("ws://").split(":")
        self.sanet, self.channels, self.error = run, [], None

    def run(self):
        try:
            with socket.socket() as s:
                s.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
                s.connect((self.host, int(self.port)))
                s.sendall((f"GET / HTTP/1.1\r\nHost: {self.host}\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
                           f"Sec-WebSocket-Key: {base64.b64encode(os.urandom(16)).decode()}\r\n"
                           "Sec-WebSocket-Version: 13\r\nSec-WebSocket-Protocol: foxglove.websocket.v1\r\n\r\n").encode())
                stream = s.makefile("rb")
                while stream.readline() not in (b"\r\n", b""):
                    pass
                while not self.channels:
                    opcode, payload = self.message(stream)
                    if opcode == 1 and json.loads(payload).get("op") == "advertise":
                        self.channels = [c["id"] for c in json.loads(payload)["channels"]]
                subscribe = {"op": "subscribe", "subscriptions": [{"id": i, "channelId": c}
                                                                  for i, c in enumerate(self.channels)]}
                s.sendall(self.masked_text(json.dumps(subscribe).encode()))
                # Read nothing more until the run ends, however slowly this machine runs it: the whole
                # run's stream (about 19 MB) must pass through the server's queue and the kernel's.
                while self.sanet.poll() is None:
                    time.sleep(0.1)
        except Exception as e:  # reported by the test, not lost in a thread
            self.error = e

    @staticmethod
    def message(stream):
        """A whole message: its first frame's opcode and every fragment's payload (RFC 6455, 5.4)."""
        opcode, payload, final = None, b"", False
        while not final:
            head = stream.read(2)
            length = head[1] & 0x7F
            if length >= 126:
                length = int.from_bytes(stream.read(2 if length == 126 else 8), "big")
            opcode = head[0] & 0x0F if opcode is None else opcode
            payload, final = payload + stream.read(length), bool(head[0] & 0x80)
        return opcode, payload

    @staticmethod
    def masked_text(payload):
        mask = os.urandom(4)
        assert len(payload) < 65536
        head = bytes([0x81, 0x80 | 126]) + len(payload).to_bytes(2, "big") if len(payload) >= 126 \
            else bytes([0x81, 0x80 | len(payload)])
        return head + mask + bytes(b ^ mask[i % 4] for i, b in enumerate(payload))


class Live(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.tmp.cleanup()

    def start(self, scenario, *extra):
        port_file = os.path.join(self.tmp.name, "foxglove-port")
        run = subprocess.Popen([SANET, "run", scenario, "-q", "-o", os.path.join(self.tmp.name, "live"), "--view",
                                "--view-port", "0", "--foxglove-port", "0", "--foxglove-port-file", port_file, *extra],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        return run, f"ws://127.0.0.1:{wait_for(port_file, run)}"

    def test_a_live_run_streams_decodable_messages_on_simulated_time(self):
        run, url = self.start(FORMATION, "--duration", "12", "--real-time")
        seen = client("watch", url, "4", "/tf", "/f1/scan", "/tf_static", "/world")
        self.assertEqual(run.wait(timeout=60), 0, run.stderr.read())
        self.assertEqual(seen["serverInfo"]["capabilities"], ["time"])
        # Every topic is advertised from the start, before its first message (a first log line).
        for topic in ("/tf", "/f1/scan", "/leader/ground_truth", "/radio/links", "/messages", "/rosout",
                      "/transitions", "/f3/odom"):
            self.assertIn(topic, seen["topics"])
        received = seen["received"]
        self.assertEqual(received["/f1/scan"]["schemaName"], "sensor_msgs/msg/LaserScan")
        self.assertEqual(received["/f1/scan"]["encoding"], "cdr")
        for topic in ("/tf", "/f1/scan"):
            r = received[topic]
            self.assertGreater(r["count"], 20, topic)
            self.assertEqual(r["errors"], 0, topic)
            stamps = [s[0] for s in r["stamps"]]
            self.assertEqual(stamps, sorted(stamps), f"{topic}: timestamps advance")
            self.assertGreater(stamps[-1] - stamps[0], 2e9, f"{topic}: over seconds of simulated time")
            self.assertTrue(all(t == stamp for t, stamp in r["stamps"]), f"{topic}: the stamp is the simulated time")
        self.assertEqual(received["/tf_static"]["count"], 1, "a latched topic's message reaches a late subscriber")
        self.assertEqual(received["/world"]["count"], 1)
        times = seen["times"]
        self.assertGreater(len(times), 20)
        self.assertEqual(times, sorted(times))
        plain = os.path.join(self.tmp.name, "plain")
        subprocess.run([SANET, "run", FORMATION, "--duration", "12", "-q", "-o", plain], check=True)
        self.assertEqual(fingerprint(os.path.join(self.tmp.name, "live")), fingerprint(plain))

    def test_a_client_that_stops_reading_is_dropped_and_the_others_go_on(self):
        run, url = self.start(HELP_REQUEST, "--foxglove-queue-mb", "1")
        staller = StallingClient(url, run)
        staller.start()
        watched = client("watch", url, "5", "/tf", "/radio/frames")
        staller.join()
        self.assertIsNone(staller.error)
        self.assertGreater(len(staller.channels), 10)
        self.assertEqual(run.wait(timeout=120), 0, run.stderr.read())
        with open(os.path.join(self.tmp.name, "live", "summary.json")) as f:
            served = json.load(f)["foxglove"]
        self.assertEqual(served["clients"], 2)
        self.assertEqual(served["dropped_for_not_reading"], 1, "the stalled client, not the reading one")
        self.assertGreater(watched["received"]["/radio/frames"]["count"], 1000)
        self.assertEqual(watched["received"]["/radio/frames"]["errors"], 0)
        with open(os.path.join(self.tmp.name, "live", "summary.json")) as f:
            self.assertEqual(json.load(f)["status"], "completed")

    def test_garbage_and_strangers_get_the_protocols_answers(self):
        run, url = self.start(FORMATION, "--duration", "8", "--real-time", "--foxglove-max-clients", "2")
        answers = client("hostile", url)
        statuses = [s["message"] for s in answers["statuses"]]
        self.assertTrue(all(s["level"] in (1, 2) for s in answers["statuses"]))
        for says in ("not a JSON object", "unsupported operation \"getParameters\"", "no channel 99999",
                     "subscribe without \"subscriptions\"", "without its \"op\"", "takes no messages from clients",
                     "is subscribed already (subscription 1): one subscription per channel",
                     "numbers from 0 to 4294967295", "unsubscribe: no subscription 77"):
            self.assertTrue(any(says in s for s in statuses), f"{says!r} not in {statuses}")
        self.assertEqual(answers["refusedWithoutSubprotocol"], 400)
        self.assertTrue(answers["stillOpen"], "garbage (nested 100,000 deep too) does not end the session")
        self.assertEqual(answers["late"], [], "nothing for a subscription after it was unsubscribed")
        self.assertTrue(all(len(s) < 300 for s in statuses), "statuses do not echo what was sent")
        # The cap: two clients at once, the third refused.
        holders = [subprocess.Popen(["node", CLIENT, MODULES, "watch", url, "3", "/tf"], stdout=subprocess.PIPE)
                   for _ in range(2)]
        time.sleep(1.5)
        self.assertEqual(client("knock", url, "foxglove.websocket.v1")["outcome"], 503, "the third is refused")
        for h in holders:
            h.wait(timeout=30)
        self.assertEqual(run.wait(timeout=60), 0)


class Replay(unittest.TestCase):
    def test_a_finished_run_replays_in_order_with_every_message(self):
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "run")
            subprocess.run([SANET, "run", FORMATION, "--duration", "20", "-q", "-o", out], check=True)
            log = subprocess.run(["node", DECODER, MODULES, os.path.join(out, "trace.mcap")], capture_output=True,
                                 text=True, check=True)
            counts = json.loads(log.stdout)["counts"]
            port_file = os.path.join(tmp, "foxglove-port")
            view = subprocess.Popen([SANET, "view", out, "--port", "0", "--foxglove-port", "0",
                                     "--foxglove-port-file", port_file, "--speed", "10"],
                                    stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
            try:
                url = f"ws://127.0.0.1:{wait_for(port_file, view)}"
                seen = client("watch", url, "4", "/tf", "/f2/scan", "/tf_static", "/messages")
            finally:
                view.terminate()
                view.wait(timeout=30)
        for topic in ("/tf", "/f2/scan", "/tf_static", "/messages"):
            r = seen["received"][topic]
            self.assertEqual(r["count"], counts[topic], f"{topic}: every message of the log")
            self.assertEqual(r["errors"], 0)
            stamps = [s[0] for s in r["stamps"]]
            self.assertEqual(stamps, sorted(stamps), f"{topic}: in time order")
        times = seen["times"]
        self.assertEqual(times, sorted(times))
        self.assertGreaterEqual(times[-1], 19.9e9, "the timeline reaches the run's end")


if __name__ == "__main__":
    unittest.main(verbosity=2)
