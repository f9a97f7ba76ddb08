#!/usr/bin/env python3
"""Draws scenarios/maps/office.png and office.yaml: the office floor of
scenarios/help-request-indoor.yaml as a ROS map (map_server's format), written for sanet.

Eight rooms (20 x 12 m) off a 6 m corridor, 80 x 30 m in all, every wall 0.2 m thick with 2 m
doorways, as the hand-made world's walls; a desk (1.6 x 0.8 m) in a corner of each room; outside
the building unknown, as a SLAM map leaves it. 0.05 m a cell, the building's south-west corner
1 m from the map's origin corner. Pixels: 0 a wall, 254 free, 205 unknown (as Nav2's map saver
writes them), grey 8-bit PNG (a few kB, where the PGM would be 1 MB).

    /usr/bin/python3 tools/make_office_map.py scenarios/maps
"""
import os
import struct
import sys
import zlib

RESOLUTION = 0.05
ORIGIN = (-1.0, -1.0)
SIZE = (82.0, 32.0)  # m
WALL = 0.2


def cell(metres, axis):
    return int(round((metres - ORIGIN[axis]) / RESOLUTION))


def walls():
    """The hand-made world's walls, as (from, to) along x or y."""
    out = [((0, 0), (80, 0)), ((80, 0), (80, 30)), ((80, 30), (0, 30)), ((0, 30), (0, 0))]
    for y in (12, 18):
        out += [((0, y), (9, y)), ((71, y), (80, y))] + [((x + 11, y), (x + 29, y)) for x in (0, 20, 40)]
    for x in (20, 40, 60):
        out += [((x, 0), (x, 12)), ((x, 18), (x, 30))]
    return out


def rectangles():
    """Every occupied rectangle (x0, y0, x1, y1) in metres: the walls and the desks."""
    rects = []
    for (ax, ay), (bx, by) in walls():
        if ay == by:
            rects.append((min(ax, bx), ay - WALL / 2, max(ax, bx), ay + WALL / 2))
        else:
            rects.append((ax - WALL / 2, min(ay, by), ax + WALL / 2, max(ay, by)))
    for x in (0, 20, 40, 60):
        rects.append((x + 17.4, 1.0, x + 19.0, 1.8))    # south rooms: the far corner from the door
        rects.append((x + 1.0, 27.2, x + 2.6, 28.0))    # north rooms
    return rects


def image():
    width, height = int(round(SIZE[0] / RESOLUTION)), int(round(SIZE[1] / RESOLUTION))
    grid = [[205] * width for _ in range(height)]  # row 0 at the bottom, for now
    for row in range(cell(0, 1), cell(30, 1)):
        for column in range(cell(0, 0), cell(80, 0)):
            grid[row][column] = 254
    for x0, y0, x1, y1 in rectangles():
        for row in range(cell(y0, 1), cell(y1, 1)):
            grid[row][cell(x0, 0):cell(x1, 0)] = [0] * (cell(x1, 0) - cell(x0, 0))
    return width, height, grid[::-1]  # an image's first row is its top


def write_png(path, width, height, rows):
    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)
    raw = b"".join(b"\x00" + bytes(r) for r in rows)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 0, 0, 0, 0)) +
                chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def main():
    folder = sys.argv[1] if len(sys.argv) > 1 else "scenarios/maps"
    os.makedirs(folder, exist_ok=True)
    width, height, rows = image()
    write_png(os.path.join(folder, "office.png"), width, height, rows)
    with open(os.path.join(folder, "office.yaml"), "w") as f:
        f.write("# The office floor of scenarios/help-request-indoor.yaml as a ROS map, drawn by\n"
                "# tools/make_office_map.py: 80 x 30 m, walls 0.2 m, a desk in each room.\n"
                f"image: office.png\nmode: trinary\nresolution: {RESOLUTION}\n"
                f"origin: [{ORIGIN[0]}, {ORIGIN[1]}, 0.0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n")


if __name__ == "__main__":
    main()
