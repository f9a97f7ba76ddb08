#!/usr/bin/env python3
"""studies/camera-stream/run: the shipped rover streams its pictures to the operator; the table
and the figure come out; every picture the operator gets is whole; near, every picture arrives,
far, none; the delay grows towards the edge, where the MAC retries more fragments; and the
pictures are as large as the docs say (38 to 43 kB)."""
import os
import re
import subprocess
import sys
import tempfile
import unittest

SANET, SOURCE = sys.argv[1:3]
del sys.argv[1:3]
RUN = os.path.join(SOURCE, "studies", "camera-stream", "run")


class CameraStreamStudy(unittest.TestCase):
    def test_pictures_delivered_and_their_delay_against_the_distance(self):
        with tempfile.TemporaryDirectory() as tmp:
            figure = os.path.join(tmp, "delivery.svg")
            done = subprocess.run([RUN, "--figure", figure], capture_output=True, text=True, timeout=300,
                                  env={**os.environ, "SANET": SANET, "OUT": os.path.join(tmp, "run")})
            self.assertEqual(done.returncode, 0, done.stdout + done.stderr)
            self.assertTrue(os.path.getsize(figure) > 1000)
        head = re.search(r"(\d+) pictures sent \((\d+) to (\d+) bytes\), (\d+) delivered, (\d+) cut", done.stdout)
        self.assertTrue(head, done.stdout)
        sent, smallest, largest, delivered, cut = map(int, head.groups())
        self.assertEqual(cut, 0, "a picture arrives whole or not at all")
        self.assertGreaterEqual(smallest, 38000)
        self.assertLessEqual(largest, 43500)
        rows = [line.split() for line in done.stdout.splitlines() if re.match(r"\s+\d+\.\d+\s+\d+\s+\d+", line)]
        table = [(float(r[0]), int(r[1]), int(r[2]), None if r[4] == "-" else float(r[4])) for r in rows]
        print(done.stdout, file=sys.stderr)
        for middle, n, got, delay in table:
            if 5 < middle < 40:
                self.assertEqual(got, n, f"every picture at {middle} m")
            if middle > 55:
                self.assertEqual(got, 0, f"none at {middle} m")
        near = [d for m, _, _, d in table if m < 30 and d is not None]
        edge = [d for m, _, _, d in table if 40 < m < 50 and d is not None]
        self.assertTrue(near and edge)
        self.assertGreater(min(edge), 1.5 * max(near), "the delay grows where fragments need retries")


if __name__ == "__main__":
    unittest.main()
