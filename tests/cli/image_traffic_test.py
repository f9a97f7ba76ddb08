#!/usr/bin/env python3
"""Images as radio traffic: a message of 65,480 bytes (one UDP datagram less sanet's header)
crosses the simulated 802.11 as the 45 IP fragments it becomes, and arrives whole or not at all:
- a robot driving away from a mote broadcasts one every second (one hop, no retries) under
  Nakagami fading; every message that arrives has every byte it was sent with;
- near, every one arrives, far none, and in the grey zone between, fewer big ones than small ones
  sent at the same moments (a message is lost when any of its fragments is);
- a message of 65,481 bytes is refused, and the node's log says why, once."""
import csv
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

SANET, SOURCE = os.path.abspath(sys.argv.pop(1)), os.path.abspath(sys.argv.pop(1))

CONTROLLERS = """
import hashlib

def body(n, size):
    head = n.to_bytes(4, "little")
    return head + bytes((n * 7 + i) % 251 for i in range(size - 4))

class Sender:
    def __init__(self, params):
        self.size, self.small, self.n = params["size"], params.get("small", 0), 0

    def control_step(self, node):
        node.drive(params_speed, 0, 0)
        node.broadcast(body(self.n, self.size))  # one hop, no retries: every fragment has one chance
        if self.small:
            node.broadcast(body(self.n, self.small))
        node.log("sent %d %.3f" % (self.n, node.ground_truth().x))
        self.n += 1

class Receiver:
    def __init__(self, params):
        pass

    def control_step(self, node):
        pass

    def on_message(self, node, m):
        n = int.from_bytes(m.payload[:4], "little")
        whole = m.payload == body(n, len(m.payload))
        node.log("got %d %d %d %.4f" % (n, len(m.payload), whole, m.time_received - m.time_sent))
""".replace("params_speed", "1.0")


def run(folder, size, small=0, duration=100):
    with open(os.path.join(folder, "traffic.py"), "w") as f:
        f.write(CONTROLLERS)
    path = os.path.join(folder, "s.yaml")
    with open(path, "w") as f:
        f.write(f"name: images\nduration: {duration}\nworld: {{size: [300, 300]}}\n"
                "network:\n  radio: 802.11g\n  routing: none\n  propagation: {fading: {model: nakagami, m: 3}}\n"
                "nodes:\n"
                f"  - {{name: r, model: diffdrive, pose: [0, 0, 0], body: {{max_speed: 1.0}}, controller: "
                f"{{python: \"traffic:Sender\", rate: 1, params: {{size: {size}, small: {small}}}}}}}\n"
                "  - {name: m, model: mote, pose: [-2, 0, 0], controller: {python: \"traffic:Receiver\"}}\n")
    out = os.path.join(folder, "out")
    done = subprocess.run([SANET, "run", path, "-q", "-o", out, "--force"], capture_output=True, text=True,
                          timeout=600)
    assert done.returncode == 0, done.stderr
    sent, got, lines = {}, {"big": {}, "small": {}}, []  # by size: the image, and the small message
    with open(os.path.join(out, "log.csv")) as f:
        for r in csv.DictReader(f):
            words = r["text"].split()
            lines.append(r["text"])
            if words[0] == "sent":
                sent[int(words[1])] = float(words[2])
            elif words[0] == "got":
                got["big" if int(words[2]) == size else "small"][int(words[1])] = (
                    int(words[2]), int(words[3]), float(words[4]))
    return sent, got, lines


class ImageTraffic(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp()

    def tearDown(self):
        shutil.rmtree(self.tmp)

    def test_a_datagram_sized_image_arrives_whole_or_not_at_all(self):
        sent, got, _ = run(self.tmp, 65480, small=200)
        big, small = got["big"], got["small"]
        self.assertTrue(big, "some images arrive")
        for n, (size, whole, delay) in big.items():
            self.assertEqual((size, whole), (65480, 1), f"image {n} arrived cut or changed")
        near = [n for n, x in sent.items() if x < 15]
        far = [n for n, x in sent.items() if x > 60]
        self.assertTrue(all(n in big for n in near), "near, every image arrives")
        self.assertFalse(any(n in big or n in small for n in far), "far, nothing")
        grey = [n for n, x in sent.items() if 15 <= x <= 60]
        grey_big, grey_small = sum(n in big for n in grey), sum(n in small for n in grey)
        print(f"in the grey zone, of {len(grey)} sent: {grey_big} images and {grey_small} small messages arrived",
              file=sys.stderr)
        self.assertLess(grey_big, grey_small, "45 fragments must all arrive; one frame is likelier to")
        delays = sorted(d for _, _, d in big.values())
        self.assertGreater(delays[len(delays) // 2], 0.087, "65,535 bytes of IP at 6 Mbps take 87 ms on air alone")

    def test_one_byte_more_is_refused_with_a_reason(self):
        _, got, lines = run(self.tmp, 65481, duration=3)
        self.assertFalse(got["big"])
        refusals = [line for line in lines if line.startswith("message of 65481 bytes refused")]
        self.assertEqual(refusals, ["message of 65481 bytes refused: a message holds at most 65480 bytes (one UDP "
                                    "datagram less sanet's header); split it (said once: later ones are refused too)"],
                         "said once, though three were refused")


if __name__ == "__main__":
    unittest.main()
