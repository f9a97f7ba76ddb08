"""Controllers of scenarios/camera-stream.yaml: a robot streams its camera's pictures to an
operator over the radio while it drives away (docs/camera.md).

Streamer (the robot): drives ahead at `speed`; at each control step (its rate is the camera's)
it takes the latest picture, compresses its pixels with zlib (deflate, as PNG does) and sends it
to the operator as one message: a frame number, the picture's size, the distance the robot has
driven, then the compressed bytes. A picture that compresses past one message (65,480 bytes) is
skipped and logged.

Operator (a mote): decompresses each frame it receives, checks it holds a whole picture, and logs
the frame, its size and its delay."""
import struct
import zlib

HEADER = struct.Struct("<IHHf")  # frame, width, height, metres driven when it was taken
MOST = 65480


class Streamer:
    def __init__(self, params):
        self.speed = params.get("speed", 1.0)
        self.to = params.get("to", "operator")
        self.frame = 0

    def start(self, node):
        self.target = node.lookup(self.to)
        self.origin = node.ground_truth().x

    def control_step(self, node):
        node.drive(self.speed, 0, 0)
        picture = node.sensor("camera")
        driven = node.ground_truth().x - self.origin
        packed = zlib.compress(picture.data, 6)
        message = HEADER.pack(self.frame, picture.width, picture.height, driven) + packed
        if len(message) > MOST:
            node.log("frame %d skipped: %d bytes compressed, past one message" % (self.frame, len(message)))
        else:
            node.send(self.target, message)
            node.log("sent %d %d %.2f" % (self.frame, len(message), driven))
        self.frame += 1


class Operator:
    def __init__(self, params):
        pass

    def control_step(self, node):
        pass

    def on_message(self, node, message):
        frame, width, height, driven = HEADER.unpack_from(message.payload)
        pixels = zlib.decompress(message.payload[HEADER.size:])
        whole = len(pixels) == width * height * 3
        node.log("frame %d %d %.2f %.4f %s" % (frame, len(message.payload), driven,
                                              message.time_received - message.time_sent,
                                              "whole" if whole else "cut"))
