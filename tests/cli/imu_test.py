#!/usr/bin/env python3
"""The IMU (`sensors.imu`) as a controller reads it, sampled at 100 Hz:
- at rest it reads +g on z and nothing else;
- a diffdrive accelerating from rest: the x acceleration integrates to the speed its true poses
  show, and turning in place its z turn rate is the true poses' turn rate;
- over a long record at rest, the Allan deviation of the turn rate and of the acceleration matches
  the noise's parameters (white noise N/sqrt(tau) and bias random walk K sqrt(tau/3), as Kalibr
  and PX4 define them) at short and long averaging times;
- a mount off the centre feels the turn's centripetal acceleration."""
import csv
import math
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

from mcap_log import decoded

SANET, SOURCE = sys.argv.pop(1), sys.argv.pop(1)
MODULES = os.path.join(SOURCE, "build", "npm", "node_modules")

READER = """
class Reader:
    def __init__(self, params):
        self.wheels = params.get("wheels", [0.0, 0.0])
        self.begin = params.get("begin", 1.0)

    def control_step(self, node):
        t = node.now()
        node.set_wheel_speeds(self.wheels if t >= self.begin else [0.0, 0.0])
        imu, pose = node.sensor("imu"), node.ground_truth()
        a, w = imu.linear_acceleration, imu.angular_velocity
        node.log("imu %.4f %.9f %.9f %.9f %.9f %.9f %.9f %.9f %.9f %.9f" % (
            t, a[0], a[1], a[2], w[0], w[1], w[2], pose.x, pose.y, pose.theta))
"""


def run(folder, wheels, duration, imu="{}", trace="false"):
    with open(os.path.join(folder, "reader.py"), "w") as f:
        f.write(READER)
    path = os.path.join(folder, "s.yaml")
    with open(path, "w") as f:
        f.write(f"name: imu\nduration: {duration}\nworld: {{size: [40, 40]}}\noutputs: {{trace: {trace}}}\nnodes:\n"
                f"  - name: r\n    model: diffdrive\n    pose: [5, 5, 0]\n    sensors: {{imu: {imu}}}\n"
                f"    controller: {{python: \"reader:Reader\", rate: 100, params: {{wheels: {wheels}}}}}\n")
    out = os.path.join(folder, "out")
    done = subprocess.run([SANET, "run", path, "-q", "-o", out, "--force"], capture_output=True, text=True,
                          timeout=600)
    assert done.returncode == 0, done.stderr
    rows = []
    with open(os.path.join(out, "log.csv")) as f:
        for r in csv.DictReader(f):
            if r["text"].startswith("imu "):
                rows.append([float(v) for v in r["text"].split()[1:]])
    return rows  # t, ax, ay, az, wx, wy, wz, x, y, theta


def allan(values, rate, tau):
    """Overlapping Allan deviation of samples at `rate` for averaging time `tau` (IEEE Std 952)."""
    n = max(1, int(round(tau * rate)))
    sums = [0.0]
    for v in values:
        sums.append(sums[-1] + v)
    means = [(sums[i + n] - sums[i]) / n for i in range(len(values) - n + 1)]
    diffs = [(means[i + n] - means[i]) ** 2 for i in range(len(means) - n)]
    return math.sqrt(sum(diffs) / (2 * len(diffs)))


class Imu(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp()

    def tearDown(self):
        shutil.rmtree(self.tmp)

    def test_at_rest_it_reads_g_upwards(self):
        rows = run(self.tmp, [0, 0], 2, trace="true")
        for t, ax, ay, az, wx, wy, wz, *_ in rows[50:]:  # once it has settled on its wheels
            self.assertAlmostEqual(az, 9.81, places=6)
            for v in (ax, ay, wx, wy, wz):
                self.assertAlmostEqual(v, 0, delta=0.05)
        if not os.path.isdir(MODULES):
            return
        # sensor_msgs/msg/Imu in trace.mcap, through the independent reader: no orientation given.
        log = decoded(SOURCE, MODULES, os.path.join(self.tmp, "out", "trace.mcap"))
        self.assertEqual(log["channels"]["/r/imu"]["schema"], "sensor_msgs/msg/Imu")
        self.assertEqual(log["counts"]["/r/imu"], 201, "every sample of 2 s at 100 Hz, at its own time")
        last = log["last"]["/r/imu"]
        self.assertEqual(last["header"]["frame_id"], "r/imu")
        self.assertAlmostEqual(last["linear_acceleration"]["z"], 9.81, places=6)
        self.assertEqual(last["orientation_covariance"][0], -1)

    def test_acceleration_integrates_to_the_true_speed_and_the_turn_rate_is_the_true_one(self):
        rows = run(self.tmp, [4.0, 4.0], 2.5)
        speed, prev = 0.0, None
        for row in rows:
            if prev and row[0] >= 0.9:
                speed += prev[1] * (row[0] - prev[0])
            prev = row
        end, before = rows[-1], rows[-11]  # 0.1 s apart
        true_speed = math.hypot(end[7] - before[7], end[8] - before[8]) / (end[0] - before[0])
        self.assertGreater(true_speed, 0.3)
        self.assertAlmostEqual(speed, true_speed, delta=0.05 * true_speed)
        rows = run(self.tmp, [-2.0, 2.0], 3)
        turning = [r for r in rows if 2.0 <= r[0] <= 2.9]
        true_rate = math.remainder(turning[-1][9] - turning[0][9], 2 * math.pi) / (turning[-1][0] - turning[0][0])
        self.assertGreater(abs(true_rate), 0.5)
        measured = sum(r[6] for r in turning) / len(turning)
        self.assertAlmostEqual(measured, true_rate, delta=0.03 * abs(true_rate))

    def test_the_noise_has_the_density_and_random_walk_it_was_given(self):
        n_gyro, k_gyro, n_acc, k_acc = 0.01, 0.002, 0.05, 0.01
        rows = run(self.tmp, [0, 0], 300, "{gyroscope_noise_density: %g, gyroscope_random_walk: %g, "
                   "accelerometer_noise_density: %g, accelerometer_random_walk: %g}" % (n_gyro, k_gyro, n_acc, k_acc))
        gyro, acc = [r[6] for r in rows], [r[1] for r in rows]
        for values, n, k in ((gyro, n_gyro, k_gyro), (acc, n_acc, k_acc)):
            for tau in (0.01, 0.1, 30):
                expected = math.sqrt(n * n / tau + k * k * tau / 3)
                measured = allan(values, 100, tau)
                print(f"tau {tau:6.2f} s: Allan deviation {measured:.5f}, expected {expected:.5f}", file=sys.stderr)
                self.assertAlmostEqual(measured, expected, delta=(0.1 if tau < 1 else 0.35) * expected)

    def test_a_mount_off_the_centre_feels_the_turn(self):
        rows = run(self.tmp, [-2.0, 2.0], 3, "{mount_x: 0.2}")
        turning = [r for r in rows if 2.0 <= r[0] <= 2.9]
        rate = sum(r[6] for r in turning) / len(turning)
        centripetal = sum(r[1] for r in turning) / len(turning)
        self.assertAlmostEqual(centripetal, -rate * rate * 0.2, delta=0.1 * rate * rate * 0.2)


if __name__ == "__main__":
    unittest.main()
