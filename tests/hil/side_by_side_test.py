#!/usr/bin/env python3
"""Launches side by side on one machine: each takes a slot of its own (a lock under
/run/lock/sanet that the kernel frees when its launch dies), and with it its bridge's subnet,
namespaces, interfaces and, on loopback, its agents' UDP ports.
- two launches on loopback at once: both complete, on different UDP ports;
- two launches in network namespaces at once: both complete, on different subnets and names;
- a launch SIGKILLed mid-run leaves its namespaces behind; the next launch runs, and removes them.
The namespaced cases need root (skipped elsewhere, saying why)."""
import fcntl
import json
import os
import re
import signal
import subprocess
import sys
import tempfile
import time
import unittest

SANET, LIBRARY = sys.argv.pop(1), os.path.abspath(sys.argv.pop(1))
LOCKS = "/run/lock/sanet" if os.access("/run/lock", os.W_OK) else "/tmp/sanet-locks"

SCENARIO = """name: side-by-side
duration: {duration}
loop: {{namespaces: {namespaces}}}
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


def scenario(tmp, duration, namespaces):
    path = os.path.join(tmp, "s-%s-%s.yaml" % (duration, namespaces))
    with open(path, "w") as f:
        f.write(SCENARIO.format(duration=duration, namespaces=str(namespaces).lower(), library=LIBRARY))
    return path


def launch(path, out):
    return subprocess.Popen([SANET, "launch", path, "-o", out], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True)


def summary(out):
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def netns_names():
    return set(os.listdir("/var/run/netns")) if os.path.isdir("/var/run/netns") else set()


def slot_names(slot):
    """The namespaces and interfaces (here) named after launch slot `slot`."""
    pattern = re.compile(r"^sanet%d(br|[hn-]\d+)$" % slot)
    return {n for n in netns_names() | set(os.listdir("/sys/class/net")) if pattern.match(n)}


def slot_is_free(slot):
    try:
        fd = os.open(os.path.join(LOCKS, "slot-%d.lock" % slot), os.O_RDONLY)
    except FileNotFoundError:
        return True
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        return True
    except BlockingIOError:
        return False
    finally:
        os.close(fd)


class SideBySide(unittest.TestCase):
    def run_pair(self, namespaces):
        with tempfile.TemporaryDirectory() as tmp:
            path = scenario(tmp, 6, namespaces)
            outs = [os.path.join(tmp, "out%d" % i) for i in range(2)]
            launches = [launch(path, out) for out in outs]
            results = [p.communicate(timeout=120) for p in launches]
            for p, (stdout, stderr) in zip(launches, results):
                self.assertEqual(p.returncode, 0, stdout + stderr)
            for out in outs:
                s = summary(out)
                self.assertEqual(s["status"], "completed")
                self.assertEqual(set(s["attendance"]), {"a", "b"})
                self.assertGreater(s["agents"]["a"]["steps"], 40)
                self.assertGreater(s["agents"]["b"]["messages_received"], 40, "a's broadcasts reached b")
            return [stdout for stdout, _ in results]

    def test_two_launches_on_loopback_use_different_ports(self):
        outputs = self.run_pair(False)
        ports = [re.search(r"UDP port (\d+) \+ i", out).group(1) for out in outputs]
        self.assertNotEqual(ports[0], ports[1], outputs)

    @unittest.skipIf(os.geteuid() != 0, "needs root: network namespaces")
    def test_two_launches_in_namespaces_use_different_subnets(self):
        outputs = self.run_pair(True)
        spaces = [set(re.findall(r"in namespace (sanet\d+)-\d+", out)) for out in outputs]
        self.assertEqual([len(s) for s in spaces], [1, 1], outputs)
        self.assertNotEqual(spaces[0], spaces[1])

    @unittest.skipIf(os.geteuid() != 0, "needs root: network namespaces")
    def test_a_launch_after_one_was_killed_runs_and_removes_its_leftovers(self):
        with tempfile.TemporaryDirectory() as tmp:
            killed = launch(scenario(tmp, 60, True), os.path.join(tmp, "killed"))
            slot = None
            for line in killed.stdout:
                m = re.search(r"in namespace sanet(\d+)-1", line)
                if m:
                    slot = int(m.group(1))
                    break
            self.assertIsNotNone(slot, "the launch started its agents in namespaces")
            killed.send_signal(signal.SIGKILL)
            killed.communicate(timeout=30)
            deadline = time.time() + 30
            while not slot_is_free(slot):  # its server and agents end (SIGTERM as their parent dies)
                self.assertLess(time.time(), deadline)
                time.sleep(0.1)
            left = slot_names(slot)
            self.assertIn("sanet%dbr" % slot, left, "the killed launch left its bridge")
            self.assertIn("sanet%d-0" % slot, left, "and its namespaces")
            after = launch(scenario(tmp, 4, True), os.path.join(tmp, "after"))
            stdout, stderr = after.communicate(timeout=120)
            self.assertEqual(after.returncode, 0, stdout + stderr)
            self.assertIn("sanet: removing what a launch that died left behind:", stdout)
            self.assertIn(" sanet%dbr" % slot, stdout)
            self.assertEqual(summary(os.path.join(tmp, "after"))["status"], "completed")
            if slot_is_free(slot):  # unless a launch of another test holds it by now
                self.assertEqual(slot_names(slot), set(), "the dead launch's leftovers are gone")


if __name__ == "__main__":
    unittest.main(verbosity=2)
