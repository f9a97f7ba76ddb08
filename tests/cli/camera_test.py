#!/usr/bin/env python3
"""The camera (`sensors.camera`) as a controller reads it, rendered by Mesa's llvmpipe through
OSMesa:
- a box of a known colour straight ahead fills the picture's middle with that colour, as wide as
  the pinhole model says (width x focal length / distance, within a pixel);
- the depth at the middle is the laser's range to the same face (within a pixel's depth);
- the same scenario and seed give the same picture, byte for byte, and a turning robot sees the
  box move sideways (left turn: to the right of the picture);
- other bodies are drawn in their colours, the camera's own body is not;
- sensor_msgs/CompressedImage (PNG) and CameraInfo in trace.mcap at the record rate, through the
  independent reader: the PNG decodes (Pillow) to the controller's picture byte for byte, the
  pinhole's K, the optical frame mounted in /tf_static;
- `far` not beyond `near` is refused at its line."""
import csv
import hashlib
import io
import math
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

from mcap_log import decoded

SANET, SOURCE = os.path.abspath(sys.argv.pop(1)), os.path.abspath(sys.argv.pop(1))
MODULES = os.path.join(SOURCE, "build", "npm", "node_modules")
RED = (200, 30, 30)

LOOK = """
import hashlib
import numpy as np

class Look:
    def __init__(self, params):
        self.turn = params.get("turn", 0.0)

    def control_step(self, node):
        node.drive(0, 0, self.turn)
        img, scan = node.sensor("camera"), node.sensor("laser")
        px = img.pixels
        row = px[img.height // 2]
        red = np.where((row[:, 0] == 200) & (row[:, 1] == 30) & (row[:, 2] == 30))[0]
        middle = px[img.height // 2, img.width // 2]
        depth = float(img.depth[img.height // 2, img.width // 2]) if img.depth.size else -1.0
        node.log("cam %.2f %d %d %d %d %d,%d,%d %.6f %.6f %s" % (
            node.now(), img.width, img.height, red.min() if len(red) else -1, red.max() if len(red) else -1,
            middle[0], middle[1], middle[2], depth, scan.ranges[len(scan.ranges) // 2],
            hashlib.sha256(img.data).hexdigest()))
"""


def run(folder, camera="{}", turn=0.0, extra_nodes="", trace="false", duration=1, check=True, args=()):
    with open(os.path.join(folder, "look.py"), "w") as f:
        f.write(LOOK)
    path = os.path.join(folder, "s.yaml")
    with open(path, "w") as f:
        f.write(f"name: cam\nduration: {duration}\nworld:\n  size: [20, 20]\n  obstacles:\n"
                f"    - box: {{center: [5, 0], size: [0.5, 1.0, 1.0], color: \"#c81e1e\"}}\n"
                f"outputs: {{trace: {trace}}}\nnodes:\n  - name: r\n    model: diffdrive\n    pose: [0, 0, 0]\n"
                f"    sensors:\n      laser: {{mount_x: 0.18, height: 0.4}}\n      camera: {camera}\n"
                f"    controller: {{python: \"look:Look\", rate: 10, params: {{turn: {turn}}}}}\n{extra_nodes}")
    out = os.path.join(folder, "out")
    done = subprocess.run([SANET, "run", path, "-q", "-o", out, "--force", *args], capture_output=True, text=True,
                          timeout=600)
    if not check:
        return done
    assert done.returncode == 0, done.stderr
    rows = []
    with open(os.path.join(out, "log.csv")) as f:
        for r in csv.DictReader(f):
            if r["text"].startswith("cam "):
                t, w, h, lo, hi, middle, depth, laser, digest = r["text"].split()[1:]
                rows.append({"t": float(t), "width": int(w), "height": int(h), "lo": int(lo), "hi": int(hi),
                             "middle": tuple(int(c) for c in middle.split(",")), "depth": float(depth),
                             "laser": float(laser), "sha": digest})
    return rows


CAMERA = "{mount_x: 0.18, mount_z: 0.4, depth: true}"


class Camera(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp()

    def tearDown(self):
        shutil.rmtree(self.tmp)

    def test_a_box_ahead_fills_the_middle_as_wide_as_the_pinhole_says_at_the_lasers_range(self):
        first = run(self.tmp, CAMERA)[0]
        self.assertEqual(first["middle"], RED)
        distance = 4.75 - 0.18  # the box's near face, from the optical centre
        focal = first["width"] / 2 / math.tan(math.radians(60) / 2)
        expected = 1.0 * focal / distance
        measured = first["hi"] - first["lo"] + 1
        print(f"box 1.0 m wide at {distance} m: {measured} pixels against {expected:.2f}", file=sys.stderr)
        self.assertLessEqual(abs(measured - expected), 1.0)
        self.assertAlmostEqual((first["lo"] + first["hi"]) / 2, (first["width"] - 1) / 2, delta=0.5)
        pixel_depth = distance * math.tan(math.radians(60) / 2) / (first["width"] / 2)  # a pixel's width there
        print(f"depth {first['depth']:.6f} m, laser {first['laser']:.6f} m", file=sys.stderr)
        self.assertAlmostEqual(first["depth"], first["laser"], delta=pixel_depth)
        self.assertAlmostEqual(first["depth"], distance, delta=1e-3)

    def test_the_same_seed_gives_the_same_picture_and_a_turn_moves_the_box_sideways(self):
        a = run(self.tmp, CAMERA, turn=0.3)
        b = run(self.tmp, CAMERA, turn=0.3)
        self.assertEqual([r["sha"] for r in a], [r["sha"] for r in b])
        self.assertGreater(len({r["sha"] for r in a}), 3, "the pictures change as the robot turns")
        centres = [(r["lo"] + r["hi"]) / 2 for r in a if r["lo"] >= 0]
        self.assertGreater(len(centres), 5)
        self.assertTrue(all(later > earlier for earlier, later in zip(centres, centres[1:])),
                        f"turning left, the box goes right: {centres}")

    def test_an_isolated_controller_gets_the_same_pictures(self):
        """Its node calls go over a socket pair as packets of 64 KiB: a picture with its depth
        (537,600 bytes) is past one packet's limit, about 208 KiB."""
        here = run(self.tmp, CAMERA, turn=0.3)
        isolated = run(self.tmp, CAMERA, turn=0.3, args=("--isolate-controllers",))
        self.assertEqual([r["sha"] for r in here], [r["sha"] for r in isolated])
        self.assertEqual([r["depth"] for r in here], [r["depth"] for r in isolated])

    def test_the_second_thread_renders_the_same_pictures(self):
        one = run(self.tmp, CAMERA, turn=0.3)
        two = run(self.tmp, CAMERA, turn=0.3, args=("--set", "world.threads=2"))
        self.assertEqual([r["sha"] for r in one], [r["sha"] for r in two])

    def test_a_mote_camera_in_a_world_without_vehicles_is_recorded_in_time_order(self):
        if not os.path.isdir(MODULES):
            self.skipTest("the MCAP reader's npm packages are not installed")
        path = os.path.join(self.tmp, "motes.yaml")
        with open(path, "w") as f:
            f.write("name: motes\nduration: 5\nworld:\n  obstacles:\n"
                    "    - box: {center: [3, 0], size: [1, 1, 1], color: \"#c81e1e\"}\n"
                    "nodes:\n  - {name: m, model: mote, pose: [0, 0, 0], sensors: {camera: {rate: 4, mount_z: 0.5}}}\n"
                    "  - {name: n, model: mote, pose: [0, 2, 0]}\n")
        out = os.path.join(self.tmp, "motes")
        subprocess.run([SANET, "run", path, "-q", "-o", out], check=True, timeout=120)
        log = decoded(SOURCE, MODULES, os.path.join(out, "trace.mcap"))
        self.assertEqual(log["counts"]["/m/camera/image_raw/compressed"], 21, "every picture of 5 s at 4 Hz")
        self.assertEqual(log["backwards"], 0)

    def test_other_bodies_in_their_colours_and_not_its_own(self):
        others = ("  - {name: m, model: mote, pose: [2, 0, 0], body: {size: 0.5, color: \"#10e020\"}}\n")
        rows = run(self.tmp, "{mount_x: 0.18, mount_z: 0.2, pitch: 0.0}", extra_nodes=others)
        self.assertEqual(rows[0]["middle"], (0x10, 0xe0, 0x20), "the mote ahead, in its colour")
        rows = run(self.tmp, "{mount_x: -0.1, mount_z: 0.15}")
        self.assertEqual(rows[0]["middle"], RED, "a camera inside its own body sees through it")

    def test_compressed_pictures_and_camera_info_in_the_mcap_log(self):
        if not os.path.isdir(MODULES):
            self.skipTest("the MCAP reader's npm packages are not installed")
        from PIL import Image  # an independent PNG decoder
        rows = run(self.tmp, CAMERA[:-1] + ", rate: 10, record_rate: 5}", trace="true")
        saved = os.path.join(self.tmp, "saved")
        os.makedirs(saved)
        log = decoded(SOURCE, MODULES, os.path.join(self.tmp, "out", "trace.mcap"), saved)
        self.assertEqual(log["backwards"], 0)
        self.assertEqual(log["channels"]["/r/camera/image_raw/compressed"]["schema"], "sensor_msgs/msg/CompressedImage")
        self.assertEqual(log["channels"]["/r/camera/camera_info"]["schema"], "sensor_msgs/msg/CameraInfo")
        self.assertEqual(log["counts"]["/r/camera/image_raw/compressed"], 6, "1 s at record_rate 5 Hz")
        self.assertEqual(log["counts"]["/r/camera/camera_info"], 6)
        self.assertNotIn("/r/camera/image_raw", log["counts"], "the record keeps the compressed pictures")
        self.assertNotIn("/r/camera/image_raw", log["channels"], "and has no channel for the raw ones")
        compressed = log["first"]["/r/camera/image_raw/compressed"]
        self.assertEqual((compressed["format"], compressed["header"]["frame_id"]), ("png", "r/camera_optical"))
        with open(os.path.join(saved, "_r_camera_image_raw_compressed.bin"), "rb") as f:
            picture = Image.open(io.BytesIO(f.read()))
            picture.load()
        self.assertEqual((picture.mode, picture.size), ("RGB", (320, 240)))
        self.assertEqual(hashlib.sha256(picture.tobytes()).hexdigest(), rows[0]["sha"],
                         "PNG is lossless: the controller's picture, byte for byte")
        depth = log["first"]["/r/camera/depth/image_raw"]
        self.assertEqual((depth["encoding"], depth["step"], depth["dataLength"]), ("32FC1", 1280, 1280 * 240))
        info = log["first"]["/r/camera/camera_info"]
        focal = 160 / math.tan(math.radians(30))
        for got, want in zip(info["k"], [focal, 0, 159.5, 0, focal, 119.5, 0, 0, 1]):
            self.assertAlmostEqual(got, want, places=9)
        mounts = {(t["child_frame_id"]): t["transform"] for t in log["last"]["/tf_static"]["transforms"]}
        optical = mounts["r/camera_optical"]["rotation"]
        self.assertEqual((optical["x"], optical["y"], optical["z"], optical["w"]), (-0.5, 0.5, -0.5, 0.5))
        self.assertEqual(mounts["r/camera"]["translation"], {"x": 0.18, "y": 0, "z": 0.4})

    def test_a_record_rate_that_does_not_divide_the_rate_is_refused(self):
        done = run(self.tmp, "{rate: 10, record_rate: 3}", check=False)
        self.assertNotEqual(done.returncode, 0)
        self.assertIn("'nodes[0].sensors.camera.record_rate': must divide `rate` (10 Hz)", done.stderr)

    def test_far_not_beyond_near_is_refused_at_its_line(self):
        done = run(self.tmp, "{near: 5, far: 2}", check=False)
        self.assertNotEqual(done.returncode, 0)
        self.assertIn("s.yaml:14: 'nodes[0].sensors.camera.far'", done.stderr)
        self.assertIn("`far` must be beyond `near`", done.stderr)


if __name__ == "__main__":
    unittest.main()
