#!/usr/bin/env python3
"""`sanet view` in a real browser (headless Chromium through Selenium): the replay of the
help-request run loads without console errors; seeking to t = 600 s puts the robot where
trajectories.csv says (within 2 m); 25 motes are drawn; a mote's packet counts in the side panel
equal packets.csv; screenshots of both case studies are taken (into docs/figures with
SANET_UPDATE_FIGURES=1). Skipped, saying why, where Chromium or Selenium is missing.
Run with Debian's python: /usr/bin/python3 viewer_test.py SANET SOURCE"""
import csv
import json
import os
import shutil
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


if __name__ == "__main__":
    unittest.main(verbosity=2)
