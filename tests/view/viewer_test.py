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


# Twelve flocking robots, each reporting its neighbours (metric `neighbours`) every second; `loud`
# has a radio of its own, 5 dB stronger than the others'.
FLOCK = """name: flock
seed: 1
duration: 5
world: {physics: 2d, size: [40, 40]}
network: {radio: 802.11b, tx_power: -5, routing: none, broadcast_jitter: 0.1}
nodes:
  - grid: {name: r, rows: 3, cols: 4, origin: [4, 4], spacing: 4}
    model: diffdrive
    controller: {name: flock, rate: 10}
  - name: loud
    model: diffdrive
    pose: [20, 20, 0]
    radio: {tx_power: 0}
    controller: {name: flock, rate: 10}
"""


def write_batteries(folder):
    path = os.path.join(folder, "batteries.yaml")
    with open(path, "w") as f:
        f.write(BATTERIES)
    return path


def rows(folder, name):
    with open(os.path.join(folder, name)) as f:
        return list(csv.DictReader(f))


def link_curve_crossing(folder):
    """Where link_curve.csv's PRR first falls from at least 0.5 to under it, interpolated
    linearly; and the two distances around it."""
    curve = rows(folder, "link_curve.csv")
    for a, b in zip(curve, curve[1:]):
        pa, pb = float(a["prr"]), float(b["prr"])
        if pa >= 0.5 > pb:
            da, db = float(a["distance_m"]), float(b["distance_m"])
            return da + (pa - 0.5) / (pa - pb) * (db - da), da, db
    raise AssertionError(f"{folder}/link_curve.csv never crosses a PRR of 0.5")


def nominal_range(scenario, tmp, sets=()):
    """The radio's range as the viewer documents it: `sanet link-curve --links 20` over its
    default distances, then at 20 steps between the two around PRR 0.5, interpolated there."""
    coarse, fine = os.path.join(tmp, "coarse"), os.path.join(tmp, "fine")
    curve = [SANET, "link-curve", scenario, "--links", "20", "-q", *sets]
    subprocess.run(curve + ["-o", coarse], check=True)
    _, da, db = link_curve_crossing(coarse)
    subprocess.run(curve + ["--from", repr(da), "--to", repr(db), "--step", repr((db - da) / 20), "-o", fine],
                   check=True)
    return link_curve_crossing(fine)[0]


def position_at(results, name, t):
    """A node's position at t, half way between trajectories.csv's samples around it."""
    track = [r for r in rows(results, "trajectories.csv") if r["node"] == name]
    before = max((r for r in track if float(r["time"]) <= t), key=lambda r: float(r["time"]))
    after = min((r for r in track if float(r["time"]) >= t), key=lambda r: float(r["time"]))
    return {axis: (float(before[axis]) + float(after[axis])) / 2 for axis in ("x", "y")}


class Viewer:
    """`sanet view` on a results folder, and a headless browser on its page."""

    def __init__(self, results, tmp, query=""):
        os.makedirs(tmp, exist_ok=True)
        port_file = os.path.join(tmp, "port")
        self.server = subprocess.Popen([SANET, "view", results, "--port", "0", "--port-file", port_file],
                                       stdout=subprocess.DEVNULL)
        wait_for_port(port_file)
        with open(port_file) as f:
            self.open_browser(f"http://127.0.0.1:{int(f.read())}/", query)

    def open_browser(self, url, query=""):
        self.url = url
        options = webdriver.ChromeOptions()
        for argument in ["--headless=new", "--no-sandbox", "--window-size=1400,1000", "--enable-unsafe-swiftshader",
                         "--use-angle=swiftshader"]:
            options.add_argument(argument)
        options.binary_location = shutil.which("chromium")
        options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
        self.browser = webdriver.Chrome(service=Service(shutil.which("chromedriver")), options=options)
        self.browser.get(self.url + query)
        for _ in range(300):
            if self.browser.execute_script("return Boolean(window.sanet && window.sanet.ready)"):
                break
            time.sleep(0.1)

    def goto(self, query):
        """Opens the page again with `query` (say "?t=600") and waits until it is ready."""
        self.browser.get(self.url + query)
        for _ in range(300):
            if self.browser.execute_script("return Boolean(window.sanet && window.sanet.ready)"):
                break
            time.sleep(0.1)

    def state(self):
        return self.browser.execute_script("return window.sanet.state()")

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

    def test_opened_at_a_time_it_shows_that_time(self):
        try:
            self.viewer.goto("?t=600")
            state = self.viewer.state()
            self.assertEqual((state["t"], state["playing"], state["notice"]), (600, False, ""))
            self.assertEqual(self.viewer.browser.find_element("id", "clock").text, "t = 600.0 s")
            robot = [n for n in state["nodes"] if n["name"] == "robot"][0]
            expected = position_at(self.results, "robot", 600)
            for axis in ("x", "y"):
                self.assertAlmostEqual(robot[axis], expected[axis], delta=2.0)
            self.viewer.goto("?t=abc")
            state = self.viewer.state()
            self.assertEqual(state["t"], 0)
            self.assertIn("?t=abc is not a time in seconds", state["notice"])
            self.assertTrue(self.viewer.browser.find_element("id", "notice").is_displayed())
            self.viewer.goto("?t=1e9")
            state = self.viewer.state()
            self.assertEqual(state["t"], state["duration"])
            self.assertIn("past the run's end", state["notice"])
            self.assertEqual(self.viewer.errors(), [])
        finally:
            self.viewer.goto("")

    def test_the_headless_screenshot_recipe_draws_the_time_asked(self):
        """docs/viewer.md's one-line recipe: chromium --headless with a virtual time budget."""
        url = self.viewer.url + "?t=600"
        recipe = ["chromium", "--headless", "--no-sandbox", "--window-size=1400,1800", "--virtual-time-budget=10000"]
        dom = subprocess.run(recipe + ["--dump-dom", url], capture_output=True, text=True, check=True).stdout
        self.assertIn("t = 600.0 s", dom)
        self.assertIn("radio range (half the frames arrive", dom)
        shot = os.path.join(self.tmp.name, "recipe.png")
        subprocess.run(recipe + [f"--screenshot={shot}", url], capture_output=True, check=True)
        self.assertGreater(os.path.getsize(shot), 50000, "a drawn page (a blank one is about 23 kB)")

    def test_a_controllers_metric_is_plotted(self):
        metrics = {m["name"]: m for m in self.viewer.state()["metrics"]}
        hops = [r for r in rows(self.results, "metrics.csv") if r["name"] == "hop_time"]
        self.assertGreater(len(hops), 2)
        self.assertEqual(metrics["hop_time"], {"name": "hop_time", "nodes": ["robot"], "folded": False,
                                               "cumulative": False, "points": len(hops),
                                               "last": float(hops[-1]["value"])})
        self.assertEqual(set(metrics), {r["name"] for r in rows(self.results, "metrics.csv")})
        chart = self.viewer.browser.find_element("css selector", '#metrics figure[data-metric="hop_time"] canvas')
        self.assertTrue(chart.is_displayed())
        self.assertGreater(chart.size["height"], 100)

    def test_the_radio_range_has_the_link_curves_radius(self):
        expected = nominal_range(os.path.join(self.results, "scenario.yaml"), os.path.join(self.tmp.name, "curve"))
        self.viewer.call("window.sanet.seek(600)")
        self.viewer.call("window.sanet.ranges()")
        ranges = self.viewer.state()["ranges"]
        self.assertEqual(ranges["error"], None)
        self.assertFalse(ranges["walls"])
        [radio] = ranges["radios"]
        self.assertEqual(len(radio["nodes"]), 26)
        self.assertAlmostEqual(radio["radius"], expected, delta=0.01)
        self.assertLess(radio["precision"], 0.5)
        # By default the robot's range is drawn while no node is selected, then the selected node's.
        [drawn] = ranges["drawn"]
        self.assertEqual(drawn["name"], "robot")
        self.assertAlmostEqual(drawn["radius"], expected, delta=0.01)
        try:
            self.viewer.call("window.sanet.select('m7')")
            self.assertEqual([d["name"] for d in self.viewer.state()["ranges"]["drawn"]], ["m7"])
        finally:
            self.viewer.call("window.sanet.select('')")

    def test_the_radio_range_follows_the_walls_indoors(self):
        results = os.path.join(self.tmp.name, "indoor")
        subprocess.run([SANET, "run", os.path.join(SOURCE, "scenarios", "help-request-indoor.yaml"), "-q", "-o", results,
                        "--duration", "30"], check=True)
        expected = nominal_range(os.path.join(results, "scenario.yaml"), os.path.join(self.tmp.name, "indoor-curve"))
        indoor = Viewer(results, os.path.join(self.tmp.name, "i"), "?ranges=all")
        try:
            indoor.call("window.sanet.ranges()")
            ranges = indoor.state()["ranges"]
            self.assertTrue(ranges["walls"])
            self.assertAlmostEqual(ranges["radios"][0]["radius"], expected, delta=0.01)
            drawn = {d["name"]: d for d in ranges["drawn"]}
            self.assertEqual(len(drawn), len(indoor.state()["nodes"]))
            # A room's mote reaches the nominal range through its door, and less far through its walls.
            for name, d in drawn.items():
                self.assertLessEqual(d["radius"], expected + 0.01, name)
            self.assertAlmostEqual(drawn["north0"]["radius"], expected, delta=0.01)
            self.assertLess(drawn["north0"]["shortest"], expected / 2)
            self.assertIn("shaped by the walls", indoor.browser.find_element("id", "ranges-note").text)
            self.assertEqual(indoor.errors(), [])
        finally:
            indoor.close()

    def test_802154_motes_and_802_11_robots_each_have_their_range(self):
        results = os.path.join(self.tmp.name, "mule-802154")
        subprocess.run([SANET, "run", os.path.join(SOURCE, "scenarios", "data-mule-802154.yaml"), "--duration", "20",
                        "-q", "-o", results], check=True, capture_output=True)
        motes = nominal_range(os.path.join(results, "scenario.yaml"), os.path.join(self.tmp.name, "mote-curve"))
        self.assertAlmostEqual(motes, 10 ** ((0 + 95 - 46.6777) / 30), delta=0.5, msg="the CC2420's range")
        view = Viewer(results, os.path.join(self.tmp.name, "mule-802154-view"), "?ranges=all")
        try:
            view.call("window.sanet.ranges()")
            ranges = view.state()["ranges"]
            self.assertEqual(ranges["error"], None)
            radios = sorted(ranges["radios"], key=lambda r: len(r["nodes"]))
            self.assertEqual([len(r["nodes"]) for r in radios], [2, 30], "the robot and the base; the motes")
            self.assertAlmostEqual(radios[1]["radius"], motes, delta=0.01)
            self.assertAlmostEqual(radios[0]["radius"], 10 ** ((16 + 82 - 46.6777) / 30), delta=1,
                                   msg="802.11b at 16 dBm against -82 dBm")
            self.assertEqual(view.errors(), [])
        finally:
            view.close()

    def test_a_metric_of_events_is_drawn_as_a_running_total(self):
        results = os.path.join(self.tmp.name, "mule")
        subprocess.run([SANET, "run", os.path.join(SOURCE, "scenarios", "data-mule.yaml"), "--duration", "200", "-q",
                        "-o", results], check=True, capture_output=True)
        created = [r for r in rows(results, "metrics.csv") if r["name"] == "created"]
        mule = Viewer(results, os.path.join(self.tmp.name, "mule-view"), "?t=100")
        try:
            metrics = {m["name"]: m for m in mule.state()["metrics"]}
            self.assertTrue(metrics["created"]["cumulative"])
            self.assertTrue(metrics["created"]["folded"], "30 motes: one line")
            self.assertEqual(metrics["created"]["points"], len(created))
            self.assertEqual(metrics["created"]["last"], len(created), "the running total ends at every reading made")
            self.assertFalse(metrics["held_at_end"]["cumulative"], "amounts stay values")
            self.assertEqual(mule.errors(), [])
        finally:
            mule.close()

    def test_many_nodes_metric_is_folded_and_each_radio_has_its_range(self):
        scenario = os.path.join(self.tmp.name, "flock.yaml")
        with open(scenario, "w") as f:
            f.write(FLOCK)
        results = os.path.join(self.tmp.name, "flock")
        subprocess.run([SANET, "run", scenario, "-q", "-o", results], check=True)
        effective = os.path.join(results, "scenario.yaml")
        quiet = nominal_range(effective, os.path.join(self.tmp.name, "quiet-curve"))
        loud = nominal_range(effective, os.path.join(self.tmp.name, "loud-curve"), ["--set", "network.tx_power=0"])
        flock = Viewer(results, os.path.join(self.tmp.name, "fl"), "?t=4&ranges=all")
        try:
            flock.call("window.sanet.ranges()")
            state = flock.state()
            [neighbours] = [m for m in state["metrics"] if m["name"] == "neighbours"]
            self.assertTrue(neighbours["folded"])
            self.assertEqual(len(neighbours["nodes"]), 13)
            caption = flock.browser.find_element("css selector", '#metrics figure[data-metric="neighbours"] figcaption')
            self.assertIn("mean over the 13 nodes", caption.text)
            radios = {r["txPower"]: r for r in state["ranges"]["radios"]}
            self.assertEqual(sorted(radios), [-5, 0])
            self.assertEqual(radios[0]["nodes"], ["loud"])
            self.assertEqual(len(radios[-5]["nodes"]), 12)
            self.assertAlmostEqual(radios[-5]["radius"], quiet, delta=0.01)
            self.assertAlmostEqual(radios[0]["radius"], loud, delta=0.01)
            drawn = {d["name"]: d["radius"] for d in state["ranges"]["drawn"]}
            self.assertAlmostEqual(drawn["loud"], loud, delta=0.01)
            self.assertAlmostEqual(drawn["r0"], quiet, delta=0.01)
            self.assertEqual(flock.errors(), [])
        finally:
            flock.close()

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

    def test_a_robots_panel_shows_its_latest_recorded_picture(self):
        """camera-stream records a picture a second (record_rate 1) in trace.mcap: at t = 10.5 s
        the rover's panel shows the one taken at 10 s, decoded by the browser itself."""
        results = os.path.join(self.tmp.name, "camera-stream")
        subprocess.run([SANET, "run", os.path.join(SOURCE, "scenarios", "camera-stream.yaml"), "-q", "-o", results,
                        "--duration", "12"], check=True)
        viewer = Viewer(results, os.path.join(self.tmp.name, "cam"))
        try:
            viewer.call("window.sanet.seek(10.5)")
            viewer.call("window.sanet.select('rover')")
            picture = None
            for _ in range(100):
                picture = viewer.browser.execute_script(
                    "const i = document.getElementById('panel-camera');"
                    "return i && i.complete ? [i.naturalWidth, i.naturalHeight, i.getAttribute('src'),"
                    " document.getElementById('panel-camera-note').textContent] : null")
                if picture and picture[0]:
                    break
                time.sleep(0.1)
            self.assertEqual(picture[:2], [160, 120], picture)
            self.assertIn("t=10", picture[2])
            self.assertIn("taken at 10.00 s", picture[3])
            viewer.call("window.sanet.select('operator')")
            self.assertFalse(viewer.browser.execute_script("return Boolean(document.getElementById('panel-camera'))"),
                             "the operator has no camera")
            self.assertEqual(viewer.errors(), [])
        finally:
            viewer.close()

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
