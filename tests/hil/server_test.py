#!/usr/bin/env python3
"""The simulation server as clients meet it: a USARSim-style Python client drives a robot and
reads laser scans; garbage, a second claim, a huge line, a client that never reads and one that
vanishes mid-line leave the server and the other robots running."""
import json
import os
import re
import socket
import subprocess
import sys
import tempfile
import time
import unittest

SANET = sys.argv.pop(1)
SOURCE = sys.argv.pop(1)
SCENARIO = """duration: 25
world:
  obstacles: [{wall: {from: [6, -3], to: [6, 3]}}]
nodes:
  - {name: r1, model: diffdrive, pose: [0, 0, 0]}
  - {name: r2, model: diffdrive, pose: [0, 3, 0]}
  - {name: r3, model: diffdrive, pose: [0, -3, 0]}
"""


class Server(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        path = os.path.join(cls.tmp.name, "s.yaml")
        open(path, "w").write(SCENARIO)
        cls.server = subprocess.Popen([SANET, "serve", path, "--port", "0", "-o", os.path.join(cls.tmp.name, "out")],
                                      stdout=subprocess.PIPE, text=True)
        first = cls.server.stdout.readline()
        cls.port = int(re.search(r"127\.0\.0\.1:(\d+)", first).group(1))

    @classmethod
    def tearDownClass(cls):
        cls.server.wait(timeout=60)
        cls.tmp.cleanup()

    def connect(self):
        s = socket.create_connection(("127.0.0.1", self.port), timeout=5)
        f = s.makefile("rwb")
        self.assertTrue(f.readline().startswith(b"NFO"))
        return s, f

    def send(self, f, line):
        f.write(line.encode() + b"\r\n")
        f.flush()

    def read_until(self, f, prefix, limit=400):
        for _ in range(limit):
            line = f.readline().decode()
            if line.startswith(prefix):
                return line
        self.fail("no line starting with " + prefix)

    def latest_time(self, sock, f):
        """The newest simulation time among the lines waiting to be read."""
        sock.settimeout(0.3)
        newest = 0.0
        deadline = time.time() + 1.0
        try:
            while time.time() < deadline:
                line = f.readline().decode()
                if not line:
                    break
                found = re.search(r"\{Time ([\d.]+)\}", line)
                if found:
                    newest = max(newest, float(found.group(1)))
        except (socket.timeout, TimeoutError):
            pass
        sock.settimeout(5)
        return newest

    def test_1_a_python_client_drives_a_robot_and_reads_scans(self):
        out = subprocess.run([sys.executable, os.path.join(SOURCE, "tests", "hil", "usarsim_client.py"), "127.0.0.1",
                              str(self.port), "r1"], capture_output=True, text=True, timeout=30)
        self.assertEqual(out.returncode, 0, out.stderr)
        self.assertRegex(out.stdout, r"drove 1\.\d+ m, read \d+ laser scans")

    def test_2_bad_peers_do_not_hurt_the_others(self):
        good, gf = self.connect()
        self.send(gf, "INIT {ClassName USARBot.P2DX} {Name r2}")
        self.read_until(gf, "SEN")

        bad, bf = self.connect()
        self.send(bf, "this is not { a message")
        self.assertIn("malformed line", self.read_until(bf, "ERR"))
        self.send(bf, "DRIVE {Left 1} {Right 1}")
        self.assertIn("before INIT", self.read_until(bf, "ERR"))
        self.send(bf, "INIT {Name r2}")
        self.assertIn("already driven", self.read_until(bf, "ERR"))
        self.send(bf, "INIT {Name nobody}")
        self.assertIn("no robot named", self.read_until(bf, "ERR"))
        self.send(bf, "FLY {Up 1}")
        self.assertIn("FLY before INIT", self.read_until(bf, "ERR"))
        self.send(bf, "INIT {Name r1}")
        self.send(bf, "FLY {Up 1}")
        self.assertIn("unknown command FLY", self.read_until(bf, "ERR"))
        self.send(bf, "DRIVE {Left nan} {Right 1}")  # refused; the motors keep their last command
        refused = self.read_until(bf, "ERR")
        self.assertIn("needs numbers for both 'Left' and 'Right'", refused)
        self.assertEqual((refused.count("{"), refused.count("}")), (1, 1), "no braces inside the message")
        bf.write(b"X" * 100000)  # a line without end, far past the limit
        bf.flush()
        self.assertIn("longer than", self.read_until(bf, "ERR"))
        self.assertEqual(bf.readline(), b"", "the server closes the connection")

        stalled = socket.socket()  # claims r3, never reads (with a small buffer, so that it shows soon)
        stalled.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
        stalled.connect(("127.0.0.1", self.port))
        stalled.sendall(b"INIT {Name r3}\r\n")
        vanishing = socket.create_connection(("127.0.0.1", self.port))
        vanishing.sendall(b"DRIVE {Left 1")  # and gone mid-line
        vanishing.close()

        t0 = self.latest_time(good, gf)
        for _ in range(5):  # the good client keeps reading while the bad ones do their worst
            self.latest_time(good, gf)
        self.send(gf, "DRIVE {Left 2} {Right 2}")
        t1 = self.latest_time(good, gf)
        self.assertGreater(t1, t0 + 5, "the good client still gets fresh sensor lines, on time")
        stalled.close()
        good.close()

    def test_3_the_run_ends_with_its_results_and_the_lag(self):
        self.__class__.server.wait(timeout=60)
        self.assertEqual(self.server.returncode, 0)
        summary = json.load(open(os.path.join(self.tmp.name, "out", "summary.json")))
        for key in ("p50_s", "p99_s", "max_s", "missed_deadlines"):
            self.assertIn(key, summary["real_time_lag"])
        log = open(os.path.join(self.tmp.name, "out", "log.csv")).read()
        self.assertIn("r3,client", log)
        self.assertRegex(log, r"r3,client .* gone .*robot stopped")


if __name__ == "__main__":
    unittest.main(verbosity=2)
