#!/usr/bin/env python3
"""A USARSim-style client in plain Python: claims a robot, drives it, reads laser scans.
    usarsim_client.py HOST PORT ROBOT  -> prints the distance driven and the scans read"""
import math, socket, sys, time

host, port, robot = sys.argv[1], int(sys.argv[2]), sys.argv[3]
sock = socket.create_connection((host, port), timeout=10)
stream = sock.makefile("rwb")

def send(line):
    stream.write(line.encode() + b"\r\n"); stream.flush()

def message(line):  # "SEN {Time 1.2} {Type GroundTruth} ..." -> ("SEN", [("Time", "1.2"), ...])
    kind, _, rest = line.partition(" ")
    fields = [part.strip().partition(" ")[::2] for part in rest.replace("}", "{").split("{") if part.strip()]
    return kind, fields

hello = stream.readline().decode().strip()
assert hello.startswith("NFO"), hello
send(f"INIT {{ClassName USARBot.P2DX}} {{Name {robot}}} {{Location 0,0,0}}")
start, scans, position = None, 0, None
deadline = time.time() + 20
while time.time() < deadline and (scans < 5 or start is None or math.dist(start, position) < 1.0):
    line = stream.readline().decode().strip()
    kind, fields = message(line)
    values = dict(fields)
    if kind == "SEN" and values.get("Type") == "GroundTruth":
        position = [float(v) for v in values["Location"].split(",")][:2]
        if start is None:
            start = position
            send("DRIVE {Left 4.0} {Right 4.0}")
    elif kind == "SEN" and values.get("Type") == "RangeScanner":
        ranges = [float(r) for r in values["Range"].split(",")]
        assert len(ranges) > 100 and all(0 <= r <= 80 for r in ranges), ranges[:5]
        scans += 1
    elif kind == "ERR":
        sys.exit("server error: " + line)
send("DRIVE {Left 0} {Right 0}")
print(f"drove {math.dist(start, position):.2f} m, read {scans} laser scans")
sock.close()
