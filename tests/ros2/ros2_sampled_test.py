#!/usr/bin/env python3
"""The ROS 2 face publishes a sensor that samples on its own clock once per sample, stamped when
it was taken, as a driver stamps its data (tests/ros2/ros2_stamps.c, an independent DDS client,
reads the stamps): a 5 Hz camera under the face's 10 Hz gives every picture once, at multiples
of 0.2 s (before, each came twice, stamped at the face's reads); a 100 Hz IMU gives one sample a
period, each at a multiple of 0.01 s. A robot a USARSim client owns goes the same way, from what
its owner reads."""
import os
import socket
import subprocess
import sys
import tempfile
import threading
import time
import unittest

from socket_drain import drain

SANET, STAMPS = sys.argv.pop(1), sys.argv.pop(1)
DOMAIN = 24  # its own: tests run side by side (ros2_face has 21, ros2_agent 22, ros2_discovery 23)

SCENARIO = """name: sampled
duration: 14
nodes:
  - name: r
    model: diffdrive
    pose: [0, 0, 0]
    sensors:
      camera: {width: 32, height: 24, rate: 5}
      imu: {rate: 100}
  - {name: owned, model: diffdrive, pose: [0, 3, 0], sensors: {camera: {width: 32, height: 24, rate: 5}}}
"""


def multiples(stamps, period):
    return all(abs(t / period - round(t / period)) < 1e-6 for t in stamps)


class SampledSensorsOnTheFace(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "s.yaml")
            with open(path, "w") as f:
                f.write(SCENARIO)
            port_file = os.path.join(tmp, "port")
            served = subprocess.Popen([SANET, "serve", path, "--port", "0", "--port-file", port_file, "-o",
                                       os.path.join(tmp, "out"), "--ros2", "--ros2-domain", str(DOMAIN)],
                                      stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
            deadline = time.time() + 30
            while not os.path.exists(port_file):
                assert time.time() < deadline and served.poll() is None, served.communicate()
                time.sleep(0.02)
            with open(port_file) as f:
                owner = socket.create_connection(("127.0.0.1", int(f.read())))
            owner.sendall(b"INIT {Name owned}\r\n")  # a USARSim client: the face publishes what it reads
            threading.Thread(target=drain, args=(owner,), daemon=True).start()
            read = subprocess.run([STAMPS, str(DOMAIN), "8", "/r/camera/image_raw=image", "/r/imu=imu",
                                   "/owned/camera/image_raw=image"], capture_output=True, text=True, timeout=60)
            owner.close()
            served.communicate(timeout=60)
        assert read.returncode == 0, read.stderr
        cls.stamps = {"/r/camera/image_raw": [], "/r/imu": [], "/owned/camera/image_raw": []}
        for line in read.stdout.splitlines():
            topic, stamp = line.split()
            cls.stamps[topic].append(float(stamp))

    def test_every_picture_once_stamped_when_it_was_taken(self):
        pictures = self.stamps["/r/camera/image_raw"]
        self.assertGreater(len(pictures), 30, "5 a second for most of 8 s")
        self.assertEqual(len(pictures), len(set(pictures)), "none twice")
        self.assertTrue(multiples(pictures, 0.2), pictures[:10])
        gaps = [round(b - a, 6) for a, b in zip(pictures, pictures[1:])]
        self.assertEqual(set(gaps), {0.2}, "every picture, in order")

    def test_a_robot_another_client_owns_gives_each_picture_once_too(self):
        pictures = self.stamps["/owned/camera/image_raw"]
        self.assertGreater(len(pictures), 30, "5 a second for most of 8 s, from what its owner reads")
        self.assertEqual(len(pictures), len(set(pictures)), "none twice")
        self.assertTrue(multiples(pictures, 0.2), pictures[:10])

    def test_a_faster_sensor_gives_one_sample_a_period_at_its_own_time(self):
        samples = self.stamps["/r/imu"]
        self.assertGreater(len(samples), 60, "10 a second (the face's rate) for most of 8 s")
        self.assertEqual(len(samples), len(set(samples)))
        self.assertTrue(multiples(samples, 0.01), samples[:10])
        gaps = [b - a for a, b in zip(samples, samples[1:])]
        self.assertTrue(all(0.05 < g < 0.15 for g in gaps), sorted(gaps)[:3] + sorted(gaps)[-3:])


if __name__ == "__main__":
    unittest.main(verbosity=2)
