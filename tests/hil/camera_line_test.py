#!/usr/bin/env python3
"""The camera in the loop: a client that said SANET (as sanet's agents do) gets the robot's
picture as a SEN {Type Camera} line, PNG in base64 (docs/protocol.md), which an independent
decoder (Pillow) turns into the picture: the red box ahead fills its middle; each picture once
(a 2 Hz camera under the 10 Hz sensor period: a fifth of the periods carry one); a stock
USARSim client never sees the line. A client written from docs/protocol.md."""
import base64
import io
import sys
import tempfile
import unittest

from PIL import Image
from protocol_client import Client, field, serve

SANET = sys.argv.pop(1)
SCENARIO = """duration: 6
world:
  obstacles:
    - box: {center: [5, 0], size: [0.5, 2.0, 2.0], color: "#c81e1e"}
nodes:
  - {name: r1, model: diffdrive, pose: [0, 0, 0], sensors: {camera: {width: 160, height: 120, mount_z: 0.4, rate: 2}}}
  - {name: r2, model: diffdrive, pose: [0, 3, 0]}
"""


class CameraInTheLoop(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.server, cls.port, cls.out = serve(SANET, SCENARIO, cls.tmp.name)

    @classmethod
    def tearDownClass(cls):
        cls.server.wait(timeout=60)
        cls.tmp.cleanup()

    def test_a_sanet_client_gets_pictures_and_a_stock_client_none(self):
        agent = Client(self.port)
        agent.send("SANET {Protocol 3} {Version test}")
        agent.send("INIT {Name r1}")
        for _ in range(3):
            line = agent.sensor("Camera")
            self.assertEqual((field(line, "Name"), field(line, "Width"), field(line, "Height"), field(line, "Encoding")),
                             ("Camera", "160", "120", "png"))
            picture = Image.open(io.BytesIO(base64.b64decode(field(line, "Data"), validate=True)))
            picture.load()
            self.assertEqual((picture.mode, picture.size), ("RGB", (160, 120)))
            self.assertEqual(picture.getpixel((80, 60)), (200, 30, 30), "the red box ahead")
            self.assertNotEqual(picture.getpixel((80, 2)), (200, 30, 30), "the sky above it")
        kinds = []
        while kinds.count("GroundTruth") < 20:  # 2 s of sensor periods
            kinds.append(field(agent.next("SEN"), "Type"))
        self.assertIn(kinds.count("Camera"), (3, 4, 5), "a 2 Hz camera's pictures, each once")
        stock = Client(self.port)
        stock.send("INIT {Name r2}")
        kinds = {field(stock.next("SEN"), "Type") for _ in range(6)}
        self.assertIn("GroundTruth", kinds)
        self.assertNotIn("Camera", kinds)
        agent.close()
        stock.close()


if __name__ == "__main__":
    unittest.main(verbosity=2)
