#!/usr/bin/env python3
"""An agent as it runs on a computer of its own (here over loopback, without --shared-clock):
- given only --server and --robot it fetches the server's scenario and runs; a clock 1000 s off
  is found to within the reported bound, itself under a millisecond, and every figure reaches the
  server's results (agents.csv, clock.csv, summary.json, messages.csv);
- server and agent refuse each other, naming both sides, when their protocol versions, their
  scenarios (fingerprints) or their controller libraries (SHA-256) differ."""
import csv
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
import unittest

SANET, LIBRARY = sys.argv.pop(1), os.path.abspath(sys.argv.pop(1))

# Its agents run without launch, on loopback: ports of their own, away from launches' (47000 up).
SCENARIO = """name: remote-agent
duration: 30
loop: {{udp_port: 52000}}
nodes:
  - name: a
    model: diffdrive
    pose: [0, 0, 0]
    controller: {{name: wander, library: {library}}}
  - name: b
    model: diffdrive
    pose: [0, 3, 0]
    controller: {{name: wander, library: {library}}}
"""


class Server:
    """`sanet serve` on loopback, any free port, for `duration` s."""

    def __init__(self, tmp, scenario, duration, quiet=True):
        self.out = os.path.join(tmp, "out")
        port_file = os.path.join(tmp, "port")
        self.process = subprocess.Popen([SANET, "serve", scenario, "--port", "0", "--port-file", port_file, "-o",
                                         self.out, "--duration", str(duration), "--force"] + (["-q"] if quiet else []),
                                        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        deadline = time.time() + 60
        while not os.path.exists(port_file):
            assert time.time() < deadline and self.process.poll() is None, self.process.communicate()
            time.sleep(0.01)
        with open(port_file) as f:
            self.address = "127.0.0.1:" + f.read().strip()

    def agent(self, robot, *extra, timeout=120):
        return subprocess.run([SANET, "agent", "--server", self.address, "--robot", robot, *extra],
                              capture_output=True, text=True, timeout=timeout)

    def finish(self, undriven=()):
        """The server's end: exit status 0, or 3 naming the robots no client drove (status failed)."""
        out, err = self.process.communicate(timeout=120)
        assert self.process.returncode == (3 if undriven else 0), (self.process.returncode, err)
        if undriven:
            assert "sanet: no client drove " + ", ".join(undriven) + ", so " in err, err
        self.stdout = out
        with open(os.path.join(self.out, "summary.json")) as f:
            return json.load(f)


class RemoteAgent(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.scenario = os.path.join(self.tmp.name, "remote.yaml")
        with open(self.scenario, "w") as f:
            f.write(SCENARIO.format(library=LIBRARY))

    def tearDown(self):
        self.tmp.cleanup()

    def test_an_agent_with_only_the_server_runs_on_an_estimated_clock(self):
        server = Server(self.tmp.name, self.scenario, 6)
        a = subprocess.Popen([SANET, "agent", "--server", server.address, "--robot", "a", "--test-clock-offset", "1000"],
                             stderr=subprocess.PIPE, text=True)
        b = server.agent("b", "--test-clock-offset", "-7.25")
        self.assertEqual(b.returncode, 0, b.stderr)
        self.assertIn("sanet agent b: server 127.0.0.1:", b.stdout)  # it says what it found
        self.assertIn("scenario remote-agent fetched", b.stdout)
        self.assertRegex(b.stdout, r"peers reach it at 127\.0\.0\.1:52001; clock estimated, offset -?[0-9.]+ s")
        self.assertIn("the run is over", b.stdout)
        self.assertEqual(a.wait(timeout=60), 0, a.stderr.read())
        summary = server.finish()
        origin = summary["clock"]["origin_monotonic_s"]
        self.assertGreater(summary["clock"]["exchanges_served"], 30)
        for robot, skew in (("a", 1000), ("b", -7.25)):
            stats = summary["agents"][robot]
            truth = -origin - skew  # the server's clock minus the agent's: one machine's, skewed
            self.assertLess(stats["clock_error_s"], 1e-3, stats)
            self.assertLess(stats["clock_error_max_s"], 1e-3, stats)
            self.assertLessEqual(abs(stats["clock_offset_s"] - truth), stats["clock_error_max_s"] + 2e-6, stats)
            self.assertGreater(stats["steps"], 30, stats)
        with open(os.path.join(server.out, "clock.csv")) as f:
            clocks = list(csv.DictReader(f))
        self.assertEqual({r["node"] for r in clocks}, {"a", "b"})
        self.assertGreaterEqual(len(clocks), 2 * 4, "a burst a second each")
        for r in clocks:
            skew = 1000 if r["node"] == "a" else -7.25
            self.assertLessEqual(abs(float(r["offset_s"]) - (-origin - skew)), float(r["error_bound_s"]) + 2e-6, r)
        # What one agent broadcast and the other heard over UDP, stamped on the two estimated clocks.
        with open(os.path.join(server.out, "messages.csv")) as f:
            heard = [r for r in csv.DictReader(f) if r["time_received"]]
        self.assertTrue(any(r["from"] == "a" for r in heard) and any(r["from"] == "b" for r in heard))
        bound = 2 * max(summary["agents"][r]["clock_error_max_s"] for r in ("a", "b"))
        self.assertGreaterEqual(min(float(r["delay"]) for r in heard), -bound)

    def test_another_protocol_version_is_refused_naming_both(self):
        server = Server(self.tmp.name, self.scenario, 4)
        out = server.agent("a", "--test-protocol-version", "1", timeout=30)
        unknown = server.agent("c", timeout=30)
        self.assertEqual(unknown.returncode, 2)
        self.assertIn("'c' is not a robot with a controller in the scenario of the server at 127.0.0.1:",
                      unknown.stderr)
        self.assertIn("(those are: a, b)", unknown.stderr)
        server.finish(undriven=("a", "b"))
        self.assertNotEqual(out.returncode, 0)
        self.assertIn("speaks sanet's protocol 1 (sanet ", out.stderr)
        self.assertIn("the server protocol 3 (sanet ", out.stderr)

    def test_the_server_says_who_drives_what_who_was_refused_and_which_robots_nobody_drove(self):
        server = Server(self.tmp.name, self.scenario, 4, quiet=False)
        refused = server.agent("b", "--test-protocol-version", "1", timeout=30)
        driven = server.agent("a", timeout=30)
        server.finish(undriven=("b",))
        self.assertNotEqual(refused.returncode, 0)
        self.assertEqual(driven.returncode, 0, driven.stderr)
        self.assertRegex(server.stdout, r"sanet: client 127\.0\.0\.1:[0-9]+ refused: this agent speaks sanet's protocol 1")
        self.assertRegex(server.stdout, r"sanet: client 127\.0\.0\.1:[0-9]+ drives a\n")
        summary = json.load(open(os.path.join(server.out, "summary.json")))
        self.assertEqual(summary["status"], "failed: no client drove b, so its controller never ran")
        self.assertEqual(summary["attendance"]["b"]["driven"], [])
        self.assertEqual(len(summary["attendance"]["a"]["driven"]), 1)

    def test_another_scenario_is_refused_naming_both_fingerprints(self):
        mine = os.path.join(self.tmp.name, "mine.yaml")
        with open(mine, "w") as f:
            f.write(SCENARIO.format(library=LIBRARY).replace("[0, 3, 0]", "[0, 4, 0]"))
        server = Server(self.tmp.name, self.scenario, 4)
        other = server.agent("a", "--scenario", mine, timeout=30)
        same = server.agent("a", "--scenario", self.scenario, "--test-protocol-version", "3", timeout=30)
        server.finish(undriven=("b",))
        self.assertNotEqual(other.returncode, 0)
        self.assertRegex(other.stderr, r"this agent's scenario has fingerprint [0-9a-f]{16}, the server's [0-9a-f]{16}")
        self.assertEqual(same.returncode, 0, same.stderr)

    def test_another_build_of_the_plugin_is_refused_naming_both_hashes(self):
        other = os.path.join(self.tmp.name, "other.so")
        shutil.copy(LIBRARY, other)
        with open(other, "ab") as f:
            f.write(b"another build")
        server = Server(self.tmp.name, self.scenario, 4)
        out = server.agent("a", "--library", other, timeout=30)
        server.finish(undriven=("a", "b"))
        self.assertNotEqual(out.returncode, 0)
        self.assertRegex(out.stderr, r"the server's .* has SHA-256 [0-9a-f]{16}\.\.\., this computer's .*other\.so "
                                     r"[0-9a-f]{16}\.\.\.")

    def test_a_server_that_never_answers_is_given_up_within_seconds(self):
        # A listener whose backlog is full: the kernel drops further connection requests silently,
        # as a firewall does, so connect() alone would wait minutes.
        import socket
        listener = socket.socket()
        listener.bind(("127.0.0.1", 0))
        listener.listen(0)
        fillers = []
        try:
            while len(fillers) < 8:
                fillers.append(socket.create_connection(listener.getsockname(), timeout=1))
        except OSError:
            pass  # the backlog is full: requests are dropped from here on
        started = time.time()
        out = subprocess.run([SANET, "agent", "--server", "127.0.0.1:%d" % listener.getsockname()[1], "--robot", "a"],
                             capture_output=True, text=True, timeout=60)
        took = time.time() - started
        for s in fillers + [listener]:
            s.close()
        self.assertNotEqual(out.returncode, 0)
        self.assertIn("cannot reach the server at 127.0.0.1:", out.stderr)
        self.assertIn("within 10 s", out.stderr)
        self.assertLess(took, 30)

    def test_a_server_address_that_cannot_be_is_a_usage_error(self):
        for server, says in (("no-such-host.invalid:3000", "cannot find the server's host 'no-such-host.invalid'"),
                             ("127.0.0.1", "expected HOST:PORT"), ("127.0.0.1:99999", "expected HOST:PORT")):
            out = subprocess.run([SANET, "agent", "--server", server, "--robot", "a"], capture_output=True, text=True,
                                 timeout=30)
            self.assertEqual(out.returncode, 2, (server, out.stderr))
            self.assertIn("--server", out.stderr)
            self.assertIn(says, out.stderr)

if __name__ == "__main__":
    unittest.main(verbosity=2)
