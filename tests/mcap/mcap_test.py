#!/usr/bin/env python3
"""sanet's MCAP writer (src/kernel/trace/mcap_writer) against an independent reader, npm's @mcap/core
(tests/mcap/read_mcap.mjs): every CRC holds reading record by record; the summary (schemas,
channels, statistics, chunk indexes, summary offsets) and the message indexes give every
message, in time order across chunks and over a time window, with its sequence."""
import json
import os
import subprocess
import sys
import tempfile
import unittest

SAMPLE, MODULES, SOURCE = sys.argv[1:4]
del sys.argv[1:4]
READER = os.path.join(SOURCE, "tests", "mcap", "read_mcap.mjs")


def read(path):
    done = subprocess.run(["node", READER, MODULES, path], capture_output=True, text=True, timeout=120)
    if done.returncode != 0:
        raise AssertionError(done.stderr)
    return json.loads(done.stdout)


class Container(unittest.TestCase):
    def test_many_chunks_read_back_whole_and_indexed(self):
        for compression in ["", "zstd"]:
            with self.subTest(compression=compression or "none"):
                self.many_chunks(compression)

    def many_chunks(self, compression):
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "sample.mcap")
            subprocess.run([SAMPLE, path, "500", "4096", *([compression] if compression else [])], check=True,
                           capture_output=True)
            f = read(path)
            self.assertEqual(f["compression"], [compression] * f["chunks"])
            self.assertEqual((f["profile"], f["library"]), ("ros2", "sanet tests"))
            self.assertTrue(f["streamed"]["done"], "the stream reader reached the trailing magic")
            self.assertEqual(f["streamed"]["messages"], 1000)
            self.assertEqual(f["streamed"]["records"]["DataEnd"], 1)
            self.assertEqual(f["channels"]["/r1/point"], {"id": 1, "schema": "geometry_msgs/msg/Point",
                                                          "encoding": "cdr",
                                                          "metadata": {"offered_qos_profiles": ""}})
            self.assertEqual(f["channels"]["/silent"]["schema"], "std_msgs/msg/String", "a channel with no message")
            self.assertGreater(f["chunks"], 10)
            self.assertEqual(f["statistics"]["chunks"], f["chunks"])
            self.assertEqual(f["statistics"]["messages"], 1000)
            self.assertEqual(f["statistics"]["perChannel"], {"1": 500, "2": 500})
            self.assertEqual((f["statistics"]["start"], f["statistics"]["end"]), (50000000, 49950000001))
            self.assertEqual(sorted(f["summaryOffsets"]), [0x03, 0x04, 0x08, 0x0B])
            points = f["perTopic"]["/r1/point"]
            self.assertEqual([p[1] for p in points], sorted(p[1] for p in points))
            self.assertEqual(len(points), 500)
            self.assertTrue(all(p[2] == 28 for p in points), "4 + 3 doubles")
            self.assertTrue(f["ordered"], "the indexed reader gives messages in log-time order across chunks")
            self.assertEqual(f["window"], [t for t in sorted(m[0] for m in f["perTopic"]["/log"])
                                           if 1000000000 <= t <= 2000000000])

    def test_an_empty_file_is_valid(self):
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "empty.mcap")
            subprocess.run([SAMPLE, path, "0", "4096"], check=True, capture_output=True)
            f = read(path)
            self.assertTrue(f["streamed"]["done"])
            self.assertEqual(f["statistics"]["messages"], 0)
            self.assertEqual(len(f["channels"]), 3)


if __name__ == "__main__":
    unittest.main(verbosity=2)
