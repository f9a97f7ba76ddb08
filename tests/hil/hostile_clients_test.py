#!/usr/bin/env python3
"""The simulation server against clients that flood it, crowd it or stop reading (docs/protocol.md,
Safety): the others keep their replies and sensor lines on time, the server keeps its deadlines,
its memory and its signals, every connection is greeted or refused, a cap full of registered
clients (INIT) refuses a newcomer and keeps them past their handshake time, and a client that
stops reading loses its robot within the documented 2 s (plus the time its lines take to show)."""
import csv
import json
import os
import resource
import signal
import socket
import subprocess
import sys
import tempfile
import threading
import time
import unittest

SANET = sys.argv.pop(1)
sys.path.insert(0, os.path.dirname(__file__))
from protocol_client import Client, field, serve  # noqa: E402

SCENARIO = """duration: 30
nodes:
  - {name: r1, model: diffdrive, pose: [0, 0, 0]}
  - {name: r2, model: diffdrive, pose: [0, 3, 0]}
  - {name: r3, model: diffdrive, pose: [0, -3, 0]}
"""
HUNDRED_ROBOTS = """duration: 30
nodes:
  - {grid: {name: r, rows: 10, cols: 10, spacing: 3}, model: diffdrive}
"""
HANDSHAKE_TIME = 3  # s: a connection that has not spoken by then is closed (docs/protocol.md, Safety)


class Flooder(threading.Thread):
    """Sends short lines as fast as the server takes them (and reads its ERR replies, so that it
    is not dropped for not reading) until stopped."""

    def __init__(self, port, line):
        super().__init__(daemon=True)
        self.sock = socket.create_connection(("127.0.0.1", port))
        self.blob = line * 20000
        self.sent = 0
        self.running = True
        threading.Thread(target=self.drain, daemon=True).start()

    def drain(self):
        try:
            while self.sock.recv(1 << 16):
                pass
        except OSError:
            pass

    def run(self):
        try:
            while self.running:
                self.sent += self.sock.send(self.blob)
        except OSError:
            pass


class Reader:
    """A client that has sent INIT and reads every line the server sends, in a thread of its own
    (so that it is not dropped for not reading): whether it drives its robot, when its last sensor
    line came, whether the server closed it."""

    def __init__(self, sock, f):
        self.sock, self.file = sock, f
        self.lines, self.last_sensor = [], 0.0
        self.driving, self.closed = threading.Event(), threading.Event()
        threading.Thread(target=self.read, daemon=True).start()

    def read(self):
        try:
            for raw in iter(self.file.readline, b""):
                line = raw.decode().strip()
                self.lines.append(line)
                if line.startswith("SEN"):
                    self.last_sensor = time.time()
                    self.driving.set()
        except OSError:
            pass
        self.closed.set()

    def close(self):
        self.sock.shutdown(socket.SHUT_RDWR)  # its reader holds the socket open otherwise
        self.sock.close()


def peak_memory_mb(pid):
    for line in open(f"/proc/{pid}/status"):
        if line.startswith("VmHWM:"):
            return int(line.split()[1]) / 1024
    raise AssertionError("no VmHWM")


class HostileClients(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()

    def tearDown(self):
        if self.server.poll() is None:
            self.server.kill()
        self.server.wait()
        self.tmp.cleanup()

    def test_floods_delay_no_other_client_and_no_deadline(self):
        self.server, port, out = serve(SANET, SCENARIO, self.tmp.name)
        good = Client(port)
        good.send("INIT {Name r1}")
        good.sensor("GroundTruth")
        flooders = [Flooder(port, line) for line in (b"GETGEO\r\n", b"x\r\n", b"GETSTARTPOSES\r\n", b"{\r\n")]
        for f in flooders:
            f.start()
        replies, sensor_times = [], []
        end = time.time() + 8
        while time.time() < end:
            asked = time.time()
            good.send("GETGEO")
            for line in good.lines():
                if line.startswith("SEN") and field(line, "Type") == "GroundTruth":
                    sensor_times.append(time.time())
                if line.startswith("GEO"):
                    replies.append(time.time() - asked)
                    break
            time.sleep(0.02)
        flooded = sum(f.sent for f in flooders)
        memory = peak_memory_mb(self.server.pid)
        self.server.send_signal(signal.SIGTERM)  # stops while the flood goes on
        self.server.wait(timeout=10)
        for f in flooders:
            f.running = False
        replies.sort()
        gaps = sorted(b - a for a, b in zip(sensor_times, sensor_times[1:]))
        print(f"flooded {flooded / 1e6:.0f} MB; GETGEO replies p50 {replies[len(replies) // 2] * 1e3:.1f} ms, "
              f"p99 {replies[int(0.99 * (len(replies) - 1))] * 1e3:.1f} ms; widest sensor gap {gaps[-1]:.3f} s; "
              f"peak memory {memory:.0f} MB")
        self.assertGreater(flooded, 10e6, "the flooders sent much more than the server could answer")
        self.assertLess(replies[int(0.99 * (len(replies) - 1))], 0.1, "documented: replies within 0.1 s")
        self.assertLess(gaps[-1], 0.35, "GroundTruth comes every 0.1 s; none is held back long")
        self.assertLess(memory, 300, "the flood's bytes wait in the flooders' sockets, not in the server")
        summary = json.load(open(os.path.join(out, "summary.json")))
        self.assertEqual(summary["status"], "interrupted")
        lag = summary["real_time_lag"]
        print("lag", lag)
        self.assertLess(lag["p99_s"], lag["deadline_s"], "the step loop keeps its deadlines")

    def test_a_flood_of_clock_reports_grows_no_table(self):
        self.server, port, out = serve(SANET, SCENARIO, self.tmp.name)
        claim = Client(port)
        claim.send("INIT {Name r2}")
        claim.sensor("GroundTruth")
        flooder = Flooder(port, b"INIT {Name r3}\r\n" + b"CLOCK {Offset 1} {Error 0} {RoundTrip 0} {Drift 0}\r\n" * 50)
        flooder.start()
        started = time.time()
        time.sleep(4)
        self.server.send_signal(signal.SIGTERM)
        self.server.wait(timeout=10)
        flooder.running = False
        with open(os.path.join(out, "clock.csv")) as f:
            rows = [r for r in csv.DictReader(f) if r["node"] == "r3"]
        self.assertGreater(flooder.sent, 1e6)
        self.assertGreater(len(rows), 2, "the reports are taken")
        self.assertLessEqual(len(rows), 2 * (time.time() - started) + 1, "at most one every 0.5 s")

    def test_200_clients_at_once_are_each_greeted_or_refused(self):
        """A storm of 200 connections against a cap of 100: each is greeted or refused. The greeted
        ones INIT (a robot each), so that past their handshake time they still hold the cap: a
        newcomer is refused with the cap's message, and none of them loses its robot for it."""
        self.server, port, out = serve(SANET, HUNDRED_ROBOTS, self.tmp.name, "--max-clients", "100")
        sockets = [socket.socket() for _ in range(200)]
        for s in sockets:
            s.setblocking(False)
            s.connect_ex(("127.0.0.1", port))
        greeted, refused = [], []
        for s in sockets:
            s.setblocking(True)
            s.settimeout(10)
            f = s.makefile("rwb")
            first = f.readline().decode()
            if first.startswith("NFO"):
                f.write(f"INIT {{Name r{len(greeted)}}}\r\n".encode())
                f.flush()
                greeted.append(Reader(s, f))
            else:
                refused.append((s, first))
        self.assertEqual(len(greeted), 100)
        self.assertEqual(len(refused), 100)
        for s, line in refused:
            self.assertTrue(line.startswith("ERR"), line)
            self.assertIn("--max-clients 100", line)
            self.assertEqual(s.recv(100), b"", "a refused connection is closed")
        for r in greeted:
            self.assertTrue(r.driving.wait(10), r.lines[:3])
        time.sleep(HANDSHAKE_TIME + 0.5)  # every client past its handshake time: only registration keeps it
        newcomer = socket.create_connection(("127.0.0.1", port), timeout=10)
        line = newcomer.makefile("rb").readline().decode()
        self.assertTrue(line.startswith("ERR {Message connection refused: the server already has 100 connections "
                                        "(its cap, --max-clients 100)}"), line)
        self.assertEqual(newcomer.recv(100), b"", "the newcomer is closed")
        time.sleep(0.5)
        for r in greeted:
            self.assertFalse(r.closed.is_set(), r.lines[-3:])
            self.assertLess(time.time() - r.last_sensor, 0.5, "its robot's sensor lines still come")
        for s, _ in refused:
            s.close()
        newcomer.close()
        for r in greeted:
            r.close()
        time.sleep(0.2)
        again = Client(port)  # the slots are free again
        again.send("INIT {Name r2}")
        self.assertIsNotNone(again.sensor("GroundTruth"))

    def test_a_cap_full_of_registered_clients_refuses_a_newcomer_and_keeps_them(self):
        self.server, port, out = serve(SANET, SCENARIO, self.tmp.name, "--max-clients", "3")
        readers = []
        for name in ("r1", "r2", "r3"):
            c = Client(port)
            c.send(f"INIT {{Name {name}}}")
            readers.append(Reader(c.sock, c.file))
        for r in readers:
            self.assertTrue(r.driving.wait(10), r.lines[:3])
        time.sleep(HANDSHAKE_TIME + 0.5)  # past their handshake time: only registration keeps them
        newcomer = socket.create_connection(("127.0.0.1", port), timeout=10)
        self.assertEqual(newcomer.makefile("rb").read().decode(),
                         "ERR {Message connection refused: the server already has 3 connections "
                         "(its cap, --max-clients 3)}\r\n")
        for r in readers:
            self.assertFalse(r.closed.is_set(), r.lines[-3:])
            self.assertLess(time.time() - r.last_sensor, 0.5, "a registered client keeps its slot and its robot")
        readers[0].close()  # one leaves: its slot is free for the next
        time.sleep(0.2)
        again = Client(port)
        again.send("INIT {Name r1}")
        self.assertIsNotNone(again.sensor("GroundTruth"))

    def test_a_cap_beyond_the_descriptor_limit_is_refused_up_front(self):
        path = os.path.join(self.tmp.name, "s.yaml")
        open(path, "w").write(SCENARIO)
        limit = lambda: resource.setrlimit(resource.RLIMIT_NOFILE, (256, 256))  # noqa: E731
        self.server = subprocess.Popen([SANET, "serve", path, "--port", "0", "--max-clients", "1000"],
                                       preexec_fn=limit, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        _, err = self.server.communicate(timeout=30)
        self.assertEqual(self.server.returncode, 2, err)
        self.assertIn("--max-clients", err)
        self.assertIn("at most 256 (ulimit -Hn)", err)

    def test_a_client_that_stops_reading_loses_its_robot_and_a_slow_one_does_not(self):
        self.server, port, out = serve(SANET, SCENARIO, self.tmp.name, "--duration", "9")
        stopping, slow, agent = Client(port), Client(port), Client(port)
        stopping.send("INIT {Name r2}")
        slow.send("INIT {Name r3}")
        agent.send("INIT {Name r1}")  # reports like an agent, then falls silent (and still reads)
        agent.send("STATS {Steps 1} {Missed 0} {Rate 10} {Sent 0} {Received 0} {DatagramsSent 0} "
                   "{DatagramsReceived 0} {DatagramsRejected 0} {SendErrors 0} {LatenessP50 0} {LatenessP99 0} "
                   "{LatenessMax 0} {ClockOffset 0} {ClockError 0} {ClockErrorMax 0}")
        silent_from = float(field(agent.sensor("GroundTruth"), "Time"))
        threading.Thread(target=lambda: [None for _ in agent.lines()], daemon=True).start()
        stopped_at = float(field(stopping.sensor("GroundTruth"), "Time"))  # and reads no more
        slow.sock.settimeout(0.05)
        while self.server.poll() is None:
            time.sleep(0.5)  # reads twice a second, everything that came
            try:
                while slow.sock.recv(1 << 16):
                    pass
            except (socket.timeout, BlockingIOError, OSError):
                pass
        log = list(csv.DictReader(open(os.path.join(out, "log.csv"))))
        gone = [row for row in log if "gone" in row["text"]]
        not_reading = [row for row in gone if "not reading" in row["text"]]
        self.assertEqual([row["node"] for row in not_reading], ["r2"], gone)
        dropped_after = float(not_reading[0]["time"]) - stopped_at
        print(f"r2 dropped {dropped_after:.2f} s after its client stopped reading")
        self.assertLess(dropped_after, 3.5, "2 s once its window shows it, which a laser scan does within 1 s")
        silent = [row for row in gone if "an agent silent for 2 s" in row["text"]]
        self.assertEqual([row["node"] for row in silent], ["r1"], gone)
        self.assertLess(float(silent[0]["time"]) - silent_from, 2.6)


if __name__ == "__main__":
    unittest.main(verbosity=2)
