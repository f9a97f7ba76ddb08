#!/usr/bin/env python3
"""The satellite fix (`sensors.gnss`) as a controller reads it:
- at known world positions the fix equals the datum's conversion worked out here by hand
  (east-north-up to Earth-centred coordinates, and back to WGS 84 latitude, longitude and height
  by iteration), not through GeographicLib;
- there is no fix inside a region of world.gnss_denied, inside a building of walls marked
  `indoor`, or over a world.map marked `indoor`, and a fix again outside;
- the noise has the standard deviations it was given, white or with the correlation time's
  autocorrelation;
- a scenario with a fix and no world.datum is refused at the sensor's line;
- sensor_msgs/NavSatFix in trace.mcap, through the independent reader."""
import csv
import math
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import unittest

from mcap_log import decoded

SANET, SOURCE = os.path.abspath(sys.argv.pop(1)), os.path.abspath(sys.argv.pop(1))
MODULES = os.path.join(SOURCE, "build", "npm", "node_modules")
DATUM = (48.858370, 2.294481, 35.0)
A, F = 6378137.0, 1 / 298.257223563  # WGS 84
E2 = F * (2 - F)

READER = """
class Reader:
    def __init__(self, params):
        self.wheels = params.get("wheels", [0.0, 0.0])

    def control_step(self, node):
        if self.wheels != [0.0, 0.0]:
            node.set_wheel_speeds(self.wheels)
        fix, pose = node.sensor("gnss"), node.ground_truth()
        node.log("fix %.4f %d %.12f %.12f %.6f %.6f %.6f %.6f" % (
            node.now(), fix.status, fix.latitude, fix.longitude, fix.altitude, pose.x, pose.y, pose.theta))
"""


def ecef(lat, lon, h):
    lat, lon = math.radians(lat), math.radians(lon)
    n = A / math.sqrt(1 - E2 * math.sin(lat) ** 2)
    return ((n + h) * math.cos(lat) * math.cos(lon), (n + h) * math.cos(lat) * math.sin(lon),
            (n * (1 - E2) + h) * math.sin(lat))


def geodetic(x, y, z):
    lon, p = math.atan2(y, x), math.hypot(x, y)
    lat = math.atan2(z, p * (1 - E2))
    for _ in range(10):
        n = A / math.sqrt(1 - E2 * math.sin(lat) ** 2)
        h = p / math.cos(lat) - n
        lat = math.atan2(z, p * (1 - E2 * n / (n + h)))
    n = A / math.sqrt(1 - E2 * math.sin(lat) ** 2)
    return math.degrees(lat), math.degrees(lon), p / math.cos(lat) - n


def by_hand(east, north, up, datum=DATUM):
    """The datum's local east-north-up frame, turned into Earth-centred axes."""
    lat, lon = math.radians(datum[0]), math.radians(datum[1])
    x0, y0, z0 = ecef(*datum)
    sl, cl, so, co = math.sin(lat), math.cos(lat), math.sin(lon), math.cos(lon)
    return geodetic(x0 - so * east - sl * co * north + cl * co * up,
                    y0 + co * east - sl * so * north + cl * so * up,
                    z0 + cl * north + sl * up)


def metres(lat, lon, datum=DATUM):
    """East and north of the datum, to first order (for noise, whose spread is metres)."""
    phi = math.radians(datum[0])
    m = A * (1 - E2) / (1 - E2 * math.sin(phi) ** 2) ** 1.5
    n = A / math.sqrt(1 - E2 * math.sin(phi) ** 2)
    return math.radians(lon - datum[1]) * n * math.cos(phi), math.radians(lat - datum[0]) * m


def run(folder, nodes, duration, world="", trace="false", expect_ok=True):
    with open(os.path.join(folder, "reader.py"), "w") as f:
        f.write(READER)
    path = os.path.join(folder, "s.yaml")
    with open(path, "w") as f:
        f.write(f"name: gnss\nduration: {duration}\nworld:\n  size: [400, 400]\n{world}"
                f"outputs: {{trace: {trace}}}\nnodes:\n{nodes}")
    out = os.path.join(folder, "out")
    done = subprocess.run([SANET, "run", path, "-q", "-o", out, "--force"], capture_output=True, text=True,
                          timeout=600)
    if not expect_ok:
        return done
    assert done.returncode == 0, done.stderr
    rows = {}
    with open(os.path.join(out, "log.csv")) as f:
        for r in csv.DictReader(f):
            if r["text"].startswith("fix "):
                rows.setdefault(r["node"], []).append([float(v) for v in r["text"].split()[1:]])
    return rows  # per node: t, status, lat, lon, alt, x, y, theta


def robot(name, x, y, theta=0.0, gnss="{}", wheels="[0.0, 0.0]", rate=5):
    return (f"  - name: {name}\n    model: diffdrive\n    pose: [{x}, {y}, {theta}]\n    sensors: {{gnss: {gnss}}}\n"
            f"    controller: {{python: \"reader:Reader\", rate: {rate}, params: {{wheels: {wheels}}}}}\n")


DATUM_LINE = "  datum: {latitude: %r, longitude: %r, altitude: %r}\n" % DATUM


class Gnss(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp()

    def tearDown(self):
        shutil.rmtree(self.tmp)

    def test_the_fix_is_the_datums_conversion_worked_out_by_hand(self):
        places = {"a": (0, 0, 0), "b": (150, 0, 0), "c": (0, -120, 0), "d": (-180, 170, 2.0)}
        nodes = "".join(robot(n, x, y, t, "{height: 1.5, mount_x: 0.2}") for n, (x, y, t) in places.items())
        rows = run(self.tmp, nodes, 1, DATUM_LINE)
        for name, (x, y, theta) in places.items():
            t, status, lat, lon, alt, px, py, ptheta = rows[name][-1]
            self.assertEqual(status, 0)
            east, north = px + 0.2 * math.cos(ptheta), py + 0.2 * math.sin(ptheta)  # the antenna
            want = by_hand(east, north, 1.5)
            print(f"{name}: ({east:.3f}, {north:.3f}) m -> {lat:.9f}, {lon:.9f}, {alt:.4f} "
                  f"against {want[0]:.9f}, {want[1]:.9f}, {want[2]:.4f}", file=sys.stderr)
            self.assertAlmostEqual(lat, want[0], delta=1e-9)  # 0.1 mm
            self.assertAlmostEqual(lon, want[1], delta=1e-9)
            self.assertAlmostEqual(alt, want[2], delta=1e-4)
        self.assertAlmostEqual(rows["b"][-1][4] - DATUM[2] - 1.5, 150 ** 2 / (2 * 6.37e6), delta=3e-4,
                               msg="the plane's tangent rises above the ellipsoid away from the datum")

    def test_no_fix_in_a_denied_region_indoors_or_over_an_indoor_map_and_a_fix_outside(self):
        world = DATUM_LINE + ("  gnss_denied:\n    - {center: [12, 0], size: [4, 6]}\n"
                              "  obstacles:\n"  # a building of three walls and a doorway, open to the south
                              "    - {wall: {from: [-40, 40], to: [-20, 40], indoor: true}}\n"
                              "    - {wall: {from: [-40, 40], to: [-40, 25], indoor: true}}\n"
                              "    - {wall: {from: [-20, 40], to: [-20, 31], indoor: true}}\n"
                              "    - {wall: {from: [-20, 30], to: [-20, 25], indoor: true}}\n")
        nodes = (robot("driver", 0, 0, gnss="{rate: 20}", wheels="[8.0, 8.0]", rate=20) + robot("inside", -30, 35)
                 + robot("outside", -30, 20) + robot("doorway", -20, 30.5))
        rows = run(self.tmp, nodes, 40, world)
        for t, status, lat, lon, alt, x, y, theta in rows["driver"][1:]:
            if abs(x - 12) > 2.1:  # away from the edges, which a sample may straddle
                self.assertEqual(status, 0 if abs(x - 12) > 2 else -1, f"at x = {x}")
            elif abs(x - 12) < 1.9:
                self.assertEqual(status, -1, f"at x = {x}")
                self.assertTrue(math.isnan(lat))
        self.assertGreater(rows["driver"][-1][5], 16, "the driver went through the region")
        self.assertEqual({r[1] for r in rows["inside"]}, {-1})
        self.assertEqual({r[1] for r in rows["doorway"]}, {-1}, "a doorway is inside the building")
        self.assertEqual({r[1] for r in rows["outside"]}, {0})
        said = subprocess.run([SANET, "validate", os.path.join(self.tmp, "s.yaml")], capture_output=True, text=True)
        self.assertIn("none in 1 region(s) of world.gnss_denied; in the building of indoor obstacles within (",
                      said.stdout, "validate says where the walls' building denies the fix")
        office = os.path.join(SOURCE, "scenarios", "maps", "office.yaml")
        world = DATUM_LINE + f"  map: {{file: {office}, indoor: true}}\n"
        rows = run(self.tmp, robot("indoors", 4, 4) + robot("yard", -20, -20), 1, world)
        self.assertEqual({r[1] for r in rows["indoors"]}, {-1})
        self.assertEqual({r[1] for r in rows["yard"]}, {0})

    def test_the_noise_has_the_spread_and_correlation_it_was_given(self):
        gnss = "{rate: 5, horizontal_noise: 2.5, vertical_noise: 4, correlation_time: %s}"
        rows = run(self.tmp, robot("white", 0, 0, gnss=gnss % 0) + robot("wander", 5, 5, gnss=gnss % 10), 400,
                   DATUM_LINE)
        for name, x0, y0, tau in (("white", 0, 0, 0), ("wander", 5, 5, 10)):
            fixes = rows[name][1:]
            east = [metres(r[2], r[3])[0] - r[5] for r in fixes]
            north = [metres(r[2], r[3])[1] - r[6] for r in fixes]
            up = [r[4] - DATUM[2] for r in fixes]
            for values, sigma in ((east, 2.5), (north, 2.5), (up, 4)):
                spread = statistics.pstdev(values)
                lag = statistics.correlation(values[:-1], values[1:])
                want = math.exp(-0.2 / tau) if tau else 0
                print(f"{name}: spread {spread:.3f} m against {sigma}, lag-1 autocorrelation {lag:.3f} against "
                      f"{want:.3f}", file=sys.stderr)
                # 2000 samples; correlated ones are worth fewer (about 2000 / 100 independent).
                self.assertAlmostEqual(spread, sigma, delta=(0.06 if not tau else 0.3) * sigma)
                self.assertAlmostEqual(lag, want, delta=0.05)

    def test_a_fix_without_a_datum_is_refused_at_its_line(self):
        done = run(self.tmp, robot("r", 0, 0), 1, expect_ok=False)
        self.assertNotEqual(done.returncode, 0)
        self.assertIn("s.yaml:10:", done.stderr)  # the node's `sensors` line
        self.assertIn("nodes[0].sensors.gnss", done.stderr)
        self.assertIn("world.datum", done.stderr)

    def test_navsatfix_in_the_mcap_log(self):
        if not os.path.isdir(MODULES):
            self.skipTest("the MCAP reader's npm packages are not installed")
        world = DATUM_LINE + "  gnss_denied:\n    - {polygon: [[-1, -1], [1, -1], [0, 1]]}\n"
        run(self.tmp, robot("r", 10, 0, gnss="{horizontal_noise: 1.5, vertical_noise: 3, height: 0.4}")
            + robot("hidden", 0, 0), 2, world, trace="true")
        log = decoded(SOURCE, MODULES, os.path.join(self.tmp, "out", "trace.mcap"))
        self.assertEqual(log["channels"]["/r/fix"]["schema"], "sensor_msgs/msg/NavSatFix")
        self.assertEqual(log["counts"]["/r/fix"], 11, "every fix of 2 s at 5 Hz, at its own time")
        fix = log["last"]["/r/fix"]
        self.assertEqual(fix["header"]["frame_id"], "r/gnss")
        self.assertEqual(fix["status"], {"status": 0, "service": 1})
        self.assertEqual(fix["position_covariance_type"], 2)
        self.assertEqual(fix["position_covariance"], [2.25, 0, 0, 0, 2.25, 0, 0, 0, 9])
        east, north = metres(fix["latitude"], fix["longitude"])
        self.assertLess(math.hypot(east - 10, north), 10 * 1.5)
        hidden = log["last"]["/hidden/fix"]
        self.assertEqual(hidden["status"]["status"], -1)
        self.assertEqual(hidden["position_covariance_type"], 0)
        mounts = {(t["header"]["frame_id"], t["child_frame_id"]): t["transform"]["translation"]
                  for t in log["last"]["/tf_static"]["transforms"]}
        self.assertEqual(mounts[("r/base_link", "r/gnss")], {"x": 0, "y": 0, "z": 0.4}, "the antenna's mount")


if __name__ == "__main__":
    unittest.main()
