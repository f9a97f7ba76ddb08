#!/usr/bin/env python3
"""An agent's network view in each mode of `sanet launch`, as docs/controllers.md's table says:
- over the simulated radio (loop.network: simulated), the robot's ns-3 node's: the route its
  discovery found through the motes, its neighbour, an invalidation that drops the route; the
  same route the server's trace records for that node;
- in namespaces on a real (veth) network, "kernel" with the kernel's routes (direct, as
  `ip route get` says) and its neighbour table;
- on plain loopback, "kernel" with empty tables.
The first two need root and /dev/net/tun (skipped elsewhere); the third runs anywhere."""
import csv
import os
import re
import sqlite3
import subprocess
import sys
import tempfile
import unittest

SANET = sys.argv.pop(1)
LIBRARY = os.path.abspath(sys.argv.pop(1))
SOURCE = sys.argv.pop(1)

# Motes 40 m apart: the default radio (about 51 m) links neighbours only; the robot 40 m before m0.
SIMULATED = """duration: 9
network: {{routing: aodv}}
loop: {{network: simulated}}
nodes:
  - {{name: m0, model: mote, pose: [0, 0, 0]}}
  - {{name: m1, model: mote, pose: [40, 0, 0]}}
  - {{name: m2, model: mote, pose: [80, 0, 0]}}
  - name: r
    model: omni3
    pose: [-40, 0, 0]
    controller: {{name: network_probe, library: {library}, params: {{towards: m2, invalidate_at: 6}}}}
"""

TWO_ROBOTS = """duration: 7
loop: {{{loop}}}
nodes:
  - {{name: a, model: omni3, pose: [0, 0, 0], controller: {{name: network_probe, library: {library}, params: {{towards: b}}}}}}
  - {{name: b, model: omni3, pose: [3, 0, 0], controller: {{name: network_probe, library: {library}, params: {{towards: a}}}}}}
"""


def root_and_tun():
    return os.geteuid() == 0 and os.path.exists("/dev/net/tun")


def views(out, robot):
    """The probe's log lines of `robot`: (time, text)."""
    with open(os.path.join(out, "log.csv")) as f:
        return [(float(r["time"]), r["text"]) for r in csv.DictReader(f) if r["node"] == robot]


def net_lines(lines):
    return [(t, text) for t, text in lines if text.startswith("net ")]


class Launch:
    """`sanet launch` in the background, with the namespace of each agent when it has one."""

    def __init__(self, folder, scenario):
        self.out = os.path.join(folder, "out")
        path = os.path.join(folder, "scenario.yaml")
        with open(path, "w") as f:
            f.write(scenario)
        self.process = subprocess.Popen([SANET, "launch", path, "-o", self.out], stdout=subprocess.PIPE,
                                        stderr=subprocess.STDOUT, text=True)
        self.namespaces, self.lines = {}, []
        for line in self.process.stdout:
            self.lines.append(line)
            m = re.match(r"\s*agent (\S+): process \d+(?: in namespace (\S+))?", line)
            if m:
                self.namespaces[m.group(1)] = m.group(2)
            if len(self.namespaces) == scenario.count("controller:"):
                break

    def ns(self, robot, *command):
        return subprocess.run(["ip", "netns", "exec", self.namespaces[robot], *command], capture_output=True,
                              text=True, timeout=10).stdout

    def finish(self):
        self.lines.append(self.process.communicate(timeout=120)[0])
        assert self.process.returncode == 0, "".join(self.lines)
        return self.out


def docs_rows():
    """docs/controllers.md's table of Network() per mode: {mode cell: [cells]}."""
    with open(os.path.join(SOURCE, "docs", "controllers.md")) as f:
        text = f.read()
    table = text[text.index("### `Network()` per mode"):]
    rows = {}
    for line in table.splitlines()[1:]:
        if line.startswith("| ") and not line.startswith("| mode") and "---" not in line:
            cells = [c.strip() for c in line.strip("|").split("|")]
            rows[cells[0]] = cells[1:]
        elif rows and not line.startswith("|"):
            break
    return rows


def row(fragment):
    matches = [cells for mode, cells in docs_rows().items() if fragment in mode]
    assert len(matches) == 1, (fragment, docs_rows().keys())
    return matches[0]


class OverTheSimulatedRadio(unittest.TestCase):
    @unittest.skipUnless(root_and_tun(), "needs root and /dev/net/tun (the simulated radio's taps)")
    def test_the_view_is_the_robots_ns3_node(self):
        with tempfile.TemporaryDirectory() as tmp:
            out = Launch(tmp, SIMULATED.format(library=LIBRARY)).finish()
            lines = views(out, "r")
            found = [(t, v) for t, v in net_lines(lines) if "m2>m0/3/1" in v]
            self.assertTrue(found, "no route to m2 through m0 in 3 hops:\n" + "\n".join(v for _, v in lines[:40]))
            self.assertTrue(all(v.startswith("net aodv ") for _, v in net_lines(lines)), net_lines(lines)[:3])
            self.assertTrue(any(v.endswith("neighbours m0") for _, v in found), found[:3])
            invalidated = [i for i, (_, v) in enumerate(lines) if v.startswith("invalidated")]
            self.assertEqual(len(invalidated), 1)
            self.assertEqual(lines[invalidated[0]][1], "invalidated true", "AODV drops a route when asked")
            after = lines[invalidated[0] + 1][1]
            self.assertNotIn("m2>m0/3/1", after, "the route is no longer valid just after")
            # The server's trace records the same route for the robot's node.
            with sqlite3.connect(os.path.join(out, "trace.sqlite")) as db:
                ids = dict(db.execute("SELECT name, id FROM nodes"))
                traced = db.execute("SELECT next_hop, hops FROM routes WHERE node = ? AND destination = ? AND "
                                    "next_hop IS NOT NULL", (ids["r"], ids["m2"])).fetchall()
            self.assertIn((ids["m0"], 3), traced)
            cells = row("simulated")
            self.assertIn("ns-3 node", cells[1])  # RoutingTable()
            self.assertIn("`true`", cells[3])  # InvalidateRoute, AODV


class OverARealNetwork(unittest.TestCase):
    @unittest.skipUnless(root_and_tun(), "needs root (network namespaces)")
    def test_agents_in_namespaces_read_the_kernels_tables(self):
        with tempfile.TemporaryDirectory() as tmp:
            launch = Launch(tmp, TWO_ROBOTS.format(loop="network: host, namespaces: true", library=LIBRARY))
            address_b = re.search(r"inet (\d+\.\d+\.\d+\.\d+)", launch.ns("b", "ip", "-4", "-o", "addr", "show",
                                                                          "scope", "global")).group(1)
            kernel_route = launch.ns("a", "ip", "-4", "route", "get", address_b)
            out = launch.finish()
            self.assertIn(address_b, kernel_route)
            self.assertNotIn(" via ", kernel_route, "the bridge links the namespaces directly")
            lines = net_lines(views(out, "a"))
            self.assertTrue(lines)
            self.assertTrue(all(v.startswith("net kernel routes b>b/1/1 neighbours") for _, v in lines), lines[:3])
            self.assertTrue(lines[-1][1].endswith("neighbours b"), "the kernel's ARP entry for b, after traffic")
            cells = row("real network")
            self.assertIn("`kernel`", cells[0])
            self.assertIn("`false`", cells[3])


class OnLoopback(unittest.TestCase):
    def test_every_agent_is_127_0_0_1_and_the_kernel_tables_are_empty(self):
        with tempfile.TemporaryDirectory() as tmp:
            out = Launch(tmp, TWO_ROBOTS.format(loop="network: host", library=LIBRARY)).finish()
            for robot in ("a", "b"):
                lines = net_lines(views(out, robot))
                self.assertGreater(len(lines), 20)
                self.assertEqual({v for _, v in lines}, {"net kernel routes neighbours"})
            cells = row("loopback")
            self.assertIn("`kernel`", cells[0])
            self.assertIn("empty", cells[1])
            self.assertIn("empty", cells[2])


if __name__ == "__main__":
    unittest.main(verbosity=2)
