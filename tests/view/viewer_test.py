#!/usr/bin/env python3
"""`sanet view` in a real browser (headless Chromium through Selenium): the replay of the
help-request run loads without console errors; seeking to t = 600 s puts the robot where
trajectories.csv says (within 2 m); 25 motes are drawn; a mote's packet counts in the side panel
equal packets.csv; screenshots of both case studies are taken (into docs/figures with
SANET_UPDATE_FIGURES=1). Nodes on batteries are coloured by their charge and dead ones dark grey,
in the replay of sensor-network-energy and live; nodes without energy keep their colours.
Skipped, saying why, where Chromium or Selenium is missing.
Run with Debian's python: /usr/bin/python3 viewer_test.py SANET SOURCE"""
import csv
import json
import os
import shutil
import sqlite3
import subprocess
import sys
import tempfile
import time
import unittest

SANET = sys.argv.pop(1)
SOURCE = sys.argv.pop(1)

try:
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
except ImportError:
    webdriver = None


def missing():
    if webdriver is None:
        return "python3-selenium is not installed"
    if not shutil.which("chromedriver") or not shutil.which("chromium"):
        return "chromium and chromium-driver are not installed"
    return None


def wait_for_port(port_file, seconds=60):
    """Waits for a server's port file (written whole); a loaded CI machine may take seconds."""
    deadline = time.time() + seconds
    while not os.path.exists(port_file):
        if time.time() > deadline:
            raise AssertionError(f"{port_file} did not appear within {seconds} s")
        time.sleep(0.005)


# Colours the page draws nodes in (viewer.js), as window.sanet.state() gives them.
MOTE, ROBOT, DEAD = "2060c0", "d04010", "404040"

# Three motes, no radio: `short` runs down in 2 s, `long` loses 1 % a second, `plain` has no battery.
BATTERIES = """name: batteries
seed: 1
duration: 10
world: {size: [20, 20]}
nodes:
  - {name: short, model: mote, pose: [0, 0, 0], energy: {battery_j: 2, electronics_w: 1}}
  - {name: long, model: mote, pose: [10, 0, 0], energy: {battery_j: 100, electronics_w: 1}}
  - {name: plain, model: mote, pose: [0, 10, 0]}
outputs: {energy_interval: 0.5, trace: true}
"""


def write_batteries(folder):
    path = os.path.join(folder, "batteries.yaml")
    with open(path, "w") as f:
        f.write(BATTERIES)
    return path


def rows(folder, name):
    with open(os.path.join(folder, name)) as f:
        return list(csv.DictReader(f))


class Viewer:
    """`sanet view` on a results folder, and a headless browser on its page."""

    def __init__(self, results, tmp):
        os.makedirs(tmp, exist_ok=True)
        port_file = os.path.join(tmp, "port")
        self.server = subprocess.Popen([SANET, "view", results, "--port", "0", "--port-file", port_file],
                                       stdout=subprocess.DEVNULL)
        wait_for_port(port_file)
        with open(port_file) as f:
            self.open_browser(f"http://127.0.0.1:{int(f.read())}/")

    def open_browser(self, url):
        self.url = url
        options = webdriver.ChromeOptions()
        for argument in ["--headless=new", "--no-sandbox", "--window-size=1400,1000", "--enable-unsafe-swiftshader",
                         "--use-angle=swiftshader"]:
            options.add_argument(argument)
        options.binary_location = shutil.which("chromium")
        options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
        self.browser = webdriver.Chrome(service=Service(shutil.which("chromedriver")), options=options)
        self.browser.get(self.url)
        for _ in range(300):
            if self.browser.execute_script("return Boolean(window.sanet && window.sanet.ready)"):
                break
            time.sleep(0.1)

    def call(self, script):
        return self.browser.execute_async_script(
            "const done = arguments[arguments.length - 1];"
            f"Promise.resolve({script}).then((v) => done(v === undefined ? null : v), (e) => done('error: ' + e));")

    def nodes_at(self, t):
        """Seeks to t and returns the drawn nodes by name, and whether the legend shows."""
        self.call(f"window.sanet.seek({t})")
        state = self.browser.execute_script("return window.sanet.state()")
        return {n["name"]: n for n in state["nodes"]}, state["legend"]

    def errors(self):
        return [e for e in self.browser.get_log("browser") if e["level"] == "SEVERE"]

    def close(self):
        self.browser.quit()
        self.server.terminate()
        self.server.wait(timeout=10)


@unittest.skipIf(missing(), f"the viewer's test needs a browser: {missing()}")
class ViewerTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.results = os.path.join(cls.tmp.name, "help-request")
        subprocess.run([SANET, "run", os.path.join(SOURCE, "scenarios", "help-request.yaml"), "-q", "-o", cls.results],
                       check=True)
        cls.viewer = Viewer(cls.results, os.path.join(cls.tmp.name, "h"))

    @classmethod
    def tearDownClass(cls):
        cls.viewer.close()
        cls.tmp.cleanup()

    def test_the_page_loads_without_console_errors(self):
        self.assertTrue(self.viewer.browser.execute_script("return window.sanet.ready"))
        self.assertEqual(self.viewer.errors(), [])

    def test_the_robot_is_drawn_where_the_run_put_it(self):
        self.viewer.call("window.sanet.seek(600)")
        state = self.viewer.browser.execute_script("return window.sanet.state()")
        self.assertEqual(state["t"], 600)
        robot = [n for n in state["nodes"] if n["name"] == "robot"][0]
        track = [r for r in rows(self.results, "trajectories.csv") if r["node"] == "robot"]
        before = max((r for r in track if float(r["time"]) <= 600), key=lambda r: float(r["time"]))
        after = min((r for r in track if float(r["time"]) >= 600), key=lambda r: float(r["time"]))
        for axis in ("x", "y"):
            expected = (float(before[axis]) + float(after[axis])) / 2
            self.assertAlmostEqual(robot[axis], expected, delta=2.0)
        self.assertEqual(state["motes"], 25)
        # The help request floods the network at t = 10 s: its broadcasts are drawn as they go.
        self.viewer.call("window.sanet.seek(10.1)")
        self.assertGreater(self.viewer.browser.execute_script("return window.sanet.state().broadcastsShown"), 0)

    def test_nodes_without_energy_keep_their_colours(self):
        nodes, legend = self.viewer.nodes_at(300)
        self.assertFalse(legend)
        for n in nodes.values():
            self.assertEqual(n["color"], MOTE if n["model"] == "mote" else ROBOT, n["name"])
            self.assertIsNone(n["charge"])
            self.assertFalse(n["dead"])
        with sqlite3.connect(os.path.join(self.results, "trace.sqlite")) as db:
            tables = [r[0] for r in db.execute("SELECT name FROM sqlite_master WHERE type = 'table'")]
        self.assertNotIn("energy", tables, "a run without energy has no energy table")

    def test_a_motes_panel_shows_its_packet_counts(self):
        self.viewer.call("window.sanet.select('m7')")
        cells = self.viewer.browser.execute_script(
            "return Object.fromEntries([...document.querySelectorAll('#panel-packets td')]"
            ".map((td) => [td.dataset.key, td.textContent]))")
        expected = [r for r in rows(self.results, "packets.csv") if r["node"] == "m7"][0]
        for key in ("sent", "received", "forwarded", "dropped"):
            self.assertEqual(cells[key], expected[key])
        # Read in one script: the panel is redrawn with every frame.
        self.assertEqual(self.viewer.browser.execute_script("return document.getElementById('panel-name').textContent"),
                         "m7")
        # Its routes at the time shown are drawn to their next hops.
        self.viewer.call("window.sanet.seek(600)")
        routes = self.viewer.browser.execute_script("return window.sanet.state().routesDrawn")
        self.assertGreater(routes, 0)

    def test_screenshots_of_both_case_studies(self):
        formation = os.path.join(self.tmp.name, "formation")
        subprocess.run([SANET, "run", os.path.join(SOURCE, "scenarios", "formation.yaml"), "-q", "-o", formation,
                        "--duration", "120"], check=True)
        second = Viewer(formation, os.path.join(self.tmp.name, "f"))
        try:
            folder = os.path.join(SOURCE, "docs", "figures") if os.environ.get("SANET_UPDATE_FIGURES") else self.tmp.name
            for name, viewer, t in [("help-request", self.viewer, 600), ("formation", second, 100)]:
                viewer.call(f"window.sanet.seek({t})")
                path = os.path.join(folder, f"viewer-{name}.png")
                self.assertTrue(viewer.browser.save_screenshot(path))
                self.assertGreater(os.path.getsize(path), 20000, "a screenshot of a drawn page")
            self.assertEqual(second.errors(), [])
        finally:
            second.close()


@unittest.skipIf(missing(), f"the viewer's test needs a browser: {missing()}")
class EnergyViewerTest(unittest.TestCase):
    """The replay of sensor-network-energy to 420 s: ten `old` motes die at 217 s, the others at
    362 s, m7 is recharged at 400 s; the reporter lives on."""

    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.results = os.path.join(cls.tmp.name, "energy")
        subprocess.run([SANET, "run", os.path.join(SOURCE, "scenarios", "sensor-network-energy.yaml"), "-q",
                        "-o", cls.results, "--duration", "420", "--set", "outputs.trace=true"], check=True)
        cls.viewer = Viewer(cls.results, os.path.join(cls.tmp.name, "v"))

    @classmethod
    def tearDownClass(cls):
        cls.viewer.close()
        cls.tmp.cleanup()

    def test_the_trace_holds_the_batteries_samples(self):
        with sqlite3.connect(os.path.join(self.results, "trace.sqlite")) as db:
            count, nodes = db.execute("SELECT count(*), count(DISTINCT node) FROM energy").fetchone()
            full = db.execute("SELECT fraction, remaining_j FROM energy WHERE t = 0 AND node = 0").fetchone()
        self.assertEqual(nodes, 26)
        self.assertEqual(count, len(rows(self.results, "energy.csv")))
        self.assertEqual(full, (1.0, 300.0))

    def test_old_motes_are_alive_before_217_s_and_dead_after(self):
        before, legend = self.viewer.nodes_at(100)
        self.assertTrue(legend)
        after, _ = self.viewer.nodes_at(300)
        old = [name for name in before if name.startswith("old")]
        self.assertEqual(len(old), 10)
        for name in old:
            self.assertFalse(before[name]["dead"], name)
            self.assertNotIn(before[name]["color"], (DEAD, MOTE), name)
            self.assertTrue(after[name]["dead"], name)
            self.assertEqual(after[name]["color"], DEAD, name)
        for name in ("m0", "m7", "reporter"):
            self.assertNotEqual(after[name]["color"], DEAD, name)

    def test_m7_is_dead_at_380_s_and_alive_again_at_410_s(self):
        nodes, _ = self.viewer.nodes_at(380)
        self.assertTrue(nodes["m7"]["dead"])
        self.assertEqual(nodes["m7"]["color"], DEAD)
        self.assertEqual(nodes["m0"]["color"], DEAD)
        self.assertNotEqual(nodes["reporter"]["color"], DEAD)
        nodes, _ = self.viewer.nodes_at(410)
        self.assertFalse(nodes["m7"]["dead"])
        self.assertGreater(nodes["m7"]["charge"], 0.9)
        self.assertNotIn(nodes["m7"]["color"], (DEAD, MOTE))

    def test_a_full_node_is_coloured_unlike_a_nearly_empty_one(self):
        full, _ = self.viewer.nodes_at(0)
        self.assertEqual(full["m0"]["charge"], 1)
        low, _ = self.viewer.nodes_at(210)
        self.assertLess(low["old0"]["charge"], 0.1)
        self.assertFalse(low["old0"]["dead"])
        self.assertNotIn(low["old0"]["color"], (full["m0"]["color"], DEAD, MOTE))
        self.assertEqual(self.viewer.errors(), [])

    def test_a_mote_without_energy_keeps_its_colour_beside_motes_with_energy(self):
        folder = os.path.join(self.tmp.name, "batteries")
        subprocess.run([SANET, "run", write_batteries(self.tmp.name), "-q", "-o", folder], check=True)
        viewer = Viewer(folder, os.path.join(self.tmp.name, "b"))
        try:
            nodes, legend = viewer.nodes_at(5)
            self.assertTrue(legend)
            self.assertEqual((nodes["short"]["dead"], nodes["short"]["color"]), (True, DEAD))
            self.assertAlmostEqual(nodes["long"]["charge"], 0.95, delta=0.001)
            self.assertNotIn(nodes["long"]["color"], (DEAD, MOTE))
            self.assertEqual((nodes["plain"]["color"], nodes["plain"]["charge"]), (MOTE, None))
            self.assertEqual(viewer.errors(), [])
        finally:
            viewer.close()


def sse_frames(port_file, timeout=60):
    """Connects to a live view as soon as it listens and counts its frames until the run ends."""
    import urllib.request
    wait_for_port(port_file)
    with open(port_file) as f:
        port = int(f.read())
    frames, ended = 0, False
    with urllib.request.urlopen(f"http://127.0.0.1:{port}/api/live", timeout=timeout) as stream:
        for line in stream:
            if line.startswith(b"data: "):
                frames += 1
            if line.startswith(b"event: end"):
                ended = True
                break
    return frames, ended


class LiveTest(unittest.TestCase):
    def test_a_live_run_streams_frames_and_keeps_its_fingerprint(self):
        with tempfile.TemporaryDirectory() as tmp:
            scenario = os.path.join(SOURCE, "scenarios", "formation.yaml")
            port_file = os.path.join(tmp, "port")
            run = subprocess.Popen([SANET, "run", scenario, "--duration", "90", "-q", "-o", os.path.join(tmp, "live"),
                                    "--view", "--view-port", "0", "--view-port-file", port_file])
            frames, ended = sse_frames(port_file)
            self.assertEqual(run.wait(timeout=120), 0)
            subprocess.run([SANET, "run", scenario, "--duration", "90", "-q", "-o", os.path.join(tmp, "plain")],
                           check=True)
            fingerprints = []
            for name in ("live", "plain"):
                with open(os.path.join(tmp, name, "summary.json")) as f:
                    fingerprints.append(json.load(f)["fingerprint"])
            self.assertGreaterEqual(frames, 5)
            self.assertTrue(ended, "the stream says when the run is over")
            self.assertEqual(fingerprints[0], fingerprints[1])

    @unittest.skipIf(missing(), f"needs a browser: {missing()}")
    def test_a_browser_follows_a_served_world_live(self):
        with tempfile.TemporaryDirectory() as tmp:
            port_file = os.path.join(tmp, "view-port")
            server = subprocess.Popen([SANET, "serve", os.path.join(SOURCE, "scenarios", "sensor-network.yaml"),
                                       "--port", "0", "--duration", "8", "-q", "-o", os.path.join(tmp, "out"),
                                       "--view", "--view-port", "0", "--view-port-file", port_file],
                                      stdout=subprocess.DEVNULL)
            wait_for_port(port_file)
            viewer = Viewer.__new__(Viewer)
            viewer.server = server
            with open(port_file) as f:
                Viewer.open_browser(viewer, f"http://127.0.0.1:{int(f.read())}/")
            try:
                time.sleep(3)
                state = viewer.browser.execute_script("return window.sanet.state()")
                self.assertGreater(state["frames"], 10)
                self.assertEqual(len(state["nodes"]), 28)
                self.assertGreater(state["t"], 1)
                self.assertEqual(viewer.errors(), [])
            finally:
                viewer.close()

    @unittest.skipIf(missing(), f"needs a browser: {missing()}")
    def test_a_live_view_colours_nodes_by_their_charge(self):
        with tempfile.TemporaryDirectory() as tmp:
            port_file = os.path.join(tmp, "view-port")
            run = subprocess.Popen([SANET, "run", write_batteries(tmp), "--real-time", "-q", "-o", os.path.join(tmp, "out"),
                                    "--view", "--view-port", "0", "--view-port-file", port_file, "--foxglove-port", "0"],
                                   stdout=subprocess.DEVNULL)
            wait_for_port(port_file)
            viewer = Viewer.__new__(Viewer)
            viewer.server = run
            with open(port_file) as f:
                Viewer.open_browser(viewer, f"http://127.0.0.1:{int(f.read())}/")
            try:
                # `short` dies 2 s into the run, on the wall clock.
                deadline = time.time() + 20
                while True:
                    state = viewer.browser.execute_script("return window.sanet.state()")
                    nodes = {n["name"]: n for n in state["nodes"]}
                    if nodes["short"]["dead"] or time.time() > deadline:
                        break
                    time.sleep(0.2)
                self.assertTrue(state["legend"])
                self.assertEqual(nodes["short"]["color"], DEAD)
                self.assertFalse(nodes["long"]["dead"])
                self.assertGreater(nodes["long"]["charge"], 0.8)
                self.assertNotIn(nodes["long"]["color"], (DEAD, MOTE))
                self.assertEqual((nodes["plain"]["color"], nodes["plain"]["charge"]), (MOTE, None))
                self.assertEqual(viewer.errors(), [])
            finally:
                viewer.close()


if __name__ == "__main__":
    unittest.main(verbosity=2)
