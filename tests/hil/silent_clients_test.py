#!/usr/bin/env python3
"""Slots are for clients that speak (docs/protocol.md, Safety): a connection to the robot server or
the WSS endpoint that has sent no line within the handshake time (3 s) is closed, whatever the
cap; when the cap is full a newcomer takes the slot of the longest-silent connection that never
registered (INIT) and is past its handshake time. So a hundred connections that open and never
speak hold the default cap of 64 for 3 s at most: a well-behaved client that retries as clients do
is driving its robot within the handshake time (and a margin) of its first attempt."""
import os
import socket
import sys
import tempfile
import threading
import time
import unittest

SANET = sys.argv.pop(1)
sys.path.insert(0, os.path.dirname(__file__))
from protocol_client import Client, field, serve  # noqa: E402

HANDSHAKE_TIME = 3  # s, documented
MARGIN = 1.5  # s: a retry every 0.2 s, the polls, the INIT's answer, a loaded machine
SCENARIO = """duration: 40
nodes:
  - {name: r1, model: diffdrive, pose: [0, 0, 0]}
  - {name: r2, model: diffdrive, pose: [0, 3, 0]}
"""


class Drained:
    """A robot client that INITs and then reads everything in a thread of its own (so that it is
    never dropped for not reading its sensor lines)."""

    def __init__(self, port, robot):
        self.client = Client(port)
        self.client.send(f"INIT {{Name {robot}}}")
        self.client.sensor("GroundTruth")
        self.lines, self.closed = [], threading.Event()
        threading.Thread(target=self.read, daemon=True).start()

    def read(self):
        try:
            self.lines.extend(self.client.lines())
        except OSError:
            pass
        self.closed.set()

    def answers(self, line, prefix):
        """Whether `line` is answered with a line starting with `prefix` within 5 s."""
        seen = len(self.lines)
        self.client.send(line)
        end = time.time() + 5
        while time.time() < end:
            if any(s.startswith(prefix) for s in self.lines[seen:]):
                return True
            time.sleep(0.05)
        return False


def open_silent(port, count):
    """`count` connections that never send a byte (connected without waiting for the server)."""
    sockets = []
    for _ in range(count):
        s = socket.socket()
        s.setblocking(False)
        s.connect_ex(("127.0.0.1", port))
        sockets.append(s)
    return sockets


def read_to_end(sock, limit=10):
    """What the server sends until it closes the connection, and when it closed it."""
    sock.settimeout(limit)
    data = b""
    try:
        while chunk := sock.recv(4096):
            data += chunk
    except ConnectionResetError:
        pass
    return data.decode(), time.time()


def ground_truth(f):
    """The next GroundTruth sensor line; an ERR line fails."""
    for raw in iter(f.readline, b""):
        line = raw.decode().strip()
        assert not line.startswith("ERR"), line
        if line.startswith("SEN") and field(line, "Type") == "GroundTruth":
            return line
    raise EOFError("closed while waiting for GroundTruth")


def drive_robot_server(port):
    """A well-behaved client: connects, INITs r1 and waits for its robot's sensor line; refused, it
    retries every 0.2 s. Returns the seconds from its first attempt to its robot's first sensor
    line, and the refusals it got; then drives the robot until it moves."""
    first, refusals = time.time(), []
    while time.time() - first < 20:
        sock = socket.create_connection(("127.0.0.1", port), timeout=5)
        f = sock.makefile("rwb")
        greeting = f.readline().decode()
        if greeting.startswith("NFO"):
            f.write(b"INIT {Name r1}\r\n")
            f.flush()
            start = field(ground_truth(f), "Location")
            took = time.time() - first
            f.write(b"DRIVE {Left 2} {Right 2}\r\n")
            f.flush()
            while field(ground_truth(f), "Location") == start:
                pass  # until it moves
            sock.close()
            return took, refusals
        refusals.append(greeting)
        sock.close()
        time.sleep(0.2)
    raise AssertionError(f"not served within 20 s: {refusals[-3:]}")


def register_with_wss(port):
    """The same for the WSS endpoint: INIT {Robot r1} until INITREPLY {Status OK}, then GETSS."""
    first, refusals = time.time(), []
    while time.time() - first < 20:
        sock = socket.create_connection(("127.0.0.1", port), timeout=5)
        f = sock.makefile("rwb")
        f.write(b"INIT {Robot r1} {Port 5000}\r\n")
        f.flush()
        reply = f.readline().decode().strip()
        if reply == "INITREPLY {Status OK}":
            f.write(b"GETSS {Robot r2}\r\n")
            f.flush()
            assert f.readline().startswith(b"SS {Robot r2} {Strength "), "answered once registered"
            sock.close()
            return time.time() - first, refusals
        refusals.append(reply)
        sock.close()
        time.sleep(0.2)
    raise AssertionError(f"not served within 20 s: {refusals[-3:]}")


class SilentClients(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.sockets = []

    def tearDown(self):
        for s in self.sockets:
            s.close()
        self.server.kill()
        self.server.wait()
        self.tmp.cleanup()

    def serve(self, *extra):
        self.server, port, _ = serve(SANET, SCENARIO, self.tmp.name, *extra)
        return port

    def serve_wss(self):
        port_file = os.path.join(self.tmp.name, "wss-port")
        self.serve("--wss-port", "0", "--wss-port-file", port_file)
        with open(port_file) as f:
            return int(f.read())

    def test_a_hundred_silent_connections_delay_a_robot_client_by_the_handshake_time_at_most(self):
        port = self.serve()  # the default cap: 64
        self.sockets = open_silent(port, 100)
        took, refusals = drive_robot_server(port)
        print(f"robot server: driving {took:.2f} s after the first attempt, {len(refusals)} refusals")
        self.assertGreater(len(refusals), 0, "the silent ones filled the cap")
        self.assertIn("(its cap, --max-clients 64)", refusals[0])
        self.assertLess(took, HANDSHAKE_TIME + MARGIN)

    def test_a_hundred_silent_connections_delay_a_wss_client_by_the_handshake_time_at_most(self):
        port = self.serve_wss()  # the default cap: 64
        self.sockets = open_silent(port, 100)
        took, refusals = register_with_wss(port)
        print(f"WSS: registered {took:.2f} s after the first attempt, {len(refusals)} refusals")
        self.assertGreater(len(refusals), 0, "the silent ones filled the cap")
        self.assertIn("Too.Many.Connections", refusals[0])
        self.assertIn("(its cap, --wss-max-clients 64)", refusals[0])
        self.assertLess(took, HANDSHAKE_TIME + MARGIN)

    def test_a_silent_connection_is_closed_after_the_handshake_time_and_one_that_spoke_is_not(self):
        port = self.serve()  # far from its cap
        silent = socket.create_connection(("127.0.0.1", port))
        opened = time.time()
        slow = Client(port)
        slow.send("GETSTARTPOSES")  # speaks once, then takes its time, as an agent fetching a scenario may
        self.assertTrue(slow.next("NFO").startswith("NFO {StartPoses"))
        text, closed = read_to_end(silent)
        self.assertEqual(text.splitlines()[-1], "ERR {Message connection closed: silent for 3 s after connecting}")
        self.assertTrue(text.startswith("NFO {Gametype"), "greeted first")
        self.assertGreaterEqual(closed - opened, HANDSHAKE_TIME - 0.1, "not before its handshake time")
        self.assertLess(closed - opened, HANDSHAKE_TIME + MARGIN)
        time.sleep(1)
        slow.send("INIT {Name r1}")
        self.assertIsNotNone(slow.sensor("GroundTruth"), "a client that spoke keeps its connection")

    def test_a_silent_wss_connection_is_closed_after_the_handshake_time(self):
        port = self.serve_wss()
        silent = socket.create_connection(("127.0.0.1", port))
        opened = time.time()
        text, closed = read_to_end(silent)
        self.assertEqual(text,
                         "ERROR {Reason Handshake.Timeout: connection closed: silent for 3 s after connecting}\r\n")
        self.assertGreaterEqual(closed - opened, HANDSHAKE_TIME - 0.1)
        self.assertLess(closed - opened, HANDSHAKE_TIME + MARGIN)

    def test_a_client_that_speaks_but_never_inits_makes_room_for_a_newcomer_once_past_its_handshake(self):
        port = self.serve("--max-clients", "3")
        driver = Drained(port, "r1")
        talkers = [Client(port), Client(port)]
        for t in talkers:
            t.send("GETSTARTPOSES")  # speaks; never INITs
            t.next("NFO")
        early = socket.create_connection(("127.0.0.1", port), timeout=5)
        text, _ = read_to_end(early)
        self.assertEqual(text, "ERR {Message connection refused: the server already has 3 connections "
                               "(its cap, --max-clients 3)}\r\n", "the talkers are inside their handshake time")
        time.sleep(0.5)
        talkers[1].send("GETSTARTPOSES")  # the second spoke last: the first has been silent longer
        talkers[1].next("NFO")
        time.sleep(HANDSHAKE_TIME)
        newcomer = Client(port)  # greeted: it took a slot
        evicted, _ = read_to_end(talkers[0].sock)
        self.assertEqual(evicted, "ERR {Message closed to make room: no INIT within 3 s of connecting and the server "
                                  "is full (its cap, --max-clients 3)}\r\n")
        newcomer.send("INIT {Name r2}")
        self.assertIsNotNone(newcomer.sensor("GroundTruth"))
        talkers[1].send("GETSTARTPOSES")
        self.assertTrue(talkers[1].next("NFO").startswith("NFO {StartPoses"), "the other talker stays")
        self.assertFalse(driver.closed.is_set(), driver.lines[-3:])
        self.assertTrue(driver.answers("GETGEO", "GEO"), "the registered client stays")

    def test_a_wss_client_that_never_registers_makes_room_for_a_newcomer_once_past_its_handshake(self):
        port_file = os.path.join(self.tmp.name, "wss-port")
        self.serve("--wss-port", "0", "--wss-port-file", port_file, "--wss-max-clients", "2")
        with open(port_file) as f:
            port = int(f.read())
        registered = socket.create_connection(("127.0.0.1", port), timeout=5)
        registered_file = registered.makefile("rwb")
        registered_file.write(b"INIT {Robot r2} {Port 5001}\r\n")
        registered_file.flush()
        self.assertEqual(registered_file.readline(), b"INITREPLY {Status OK}\r\n")
        talker = socket.create_connection(("127.0.0.1", port), timeout=5)
        talker.sendall(b"GETSS {Robot r2}\r\n")  # answered ERROR: not registered; it never is
        self.assertEqual(talker.makefile("rb").readline(), b"ERROR {Reason Must.Use.INIT.Method.First}\r\n")
        time.sleep(HANDSHAKE_TIME + 0.5)
        took, refusals = register_with_wss(port)
        self.assertEqual(refusals, [], "the talker's slot is taken at once")
        text, _ = read_to_end(talker)
        self.assertEqual(text, "ERROR {Reason Too.Many.Connections: closed to make room: no INIT within 3 s of "
                               "connecting and the server is full (its cap, --wss-max-clients 2)}\r\n")
        registered_file.write(b"GETSS {Robot r1}\r\n")
        registered_file.flush()
        self.assertTrue(registered_file.readline().startswith(b"SS {Robot r1}"), "the registered client stays")


if __name__ == "__main__":
    unittest.main(verbosity=2, warnings="ignore")  # sockets left to the server to close
