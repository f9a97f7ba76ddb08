#!/usr/bin/env python3
"""What a world read from a ROS map costs (docs/scenario.md#worldmap), measured in one run of
this script against the same world built by hand:

1. Loading: a 4000 x 4000-cell map (200 x 200 m at 0.05 m: 20 x 20 rooms of 10 m with 0.2 m
   walls and 2 m doorways, written as a PGM here) through `sanet validate`, against the same
   walls typed as `wall:` obstacles; and `sanet map` writing the map's world back.
2. Physics: a diffdrive with its laser driving round a room for 60 s, in the map, among the
   same walls typed by hand, and in an empty world (the baseline).
3. Per frame: 400 motes, one in each room, each broadcasting every 2 s (at its own phase), heard
   through the concrete walls by its neighbours or not, for `--seconds` of simulated time: the
   wall time of the map's world against the hand-made one's and against no wall loss at all
   (material none), the frames received, and the wall time per frame received.

    bench/ros_map_bench.py [--sanet build/sanet] [--seconds 30] [--repeat 3]"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from grey_zone_bench import measure  # noqa: E402  (median wall time of `repeat` runs, the last summary)

CELL, ROOM, ROOMS, WALL, DOOR = 0.05, 10.0, 20, 0.2, 2.0


def walls():
    """Each wall as (x0, y0, x1, y1), a doorway in the middle of every inner one."""
    size = ROOM * ROOMS
    out = [(0, 0, size, 0), (0, size, size, size), (0, 0, 0, size), (size, 0, size, size)]
    for i in range(1, ROOMS):
        for j in range(ROOMS):
            a, m = j * ROOM, j * ROOM + ROOM / 2
            out += [(i * ROOM, a, i * ROOM, m - DOOR / 2), (i * ROOM, m + DOOR / 2, i * ROOM, a + ROOM)]  # x = const
            out += [(a, i * ROOM, m - DOOR / 2, i * ROOM), (m + DOOR / 2, i * ROOM, a + ROOM, i * ROOM)]  # y = const
    return out


def write_map(folder):
    n = int(round(ROOM * ROOMS / CELL))  # 4000
    grid = bytearray([254]) * (n * n)
    for x0, y0, x1, y1 in walls():
        c0, c1 = int(round((min(x0, x1) - WALL / 2 * (x0 == x1)) / CELL)), int(round((max(x0, x1) + WALL / 2 * (x0 == x1)) / CELL))
        r0, r1 = int(round((min(y0, y1) - WALL / 2 * (y0 == y1)) / CELL)), int(round((max(y0, y1) + WALL / 2 * (y0 == y1)) / CELL))
        for r in range(max(0, r0), min(n, r1)):
            row = (n - 1 - r) * n  # the image's top row is the map's last
            grid[row + max(0, c0):row + min(n, c1)] = bytes([0]) * (min(n, c1) - max(0, c0))
    with open(os.path.join(folder, "big.pgm"), "wb") as f:
        f.write(b"P5\n%d %d\n255\n" % (n, n) + bytes(grid))
    with open(os.path.join(folder, "big.yaml"), "w") as f:
        f.write("image: big.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.65\n"
                "free_thresh: 0.196\n")


def scenario(world):
    rooms = ROOMS
    return f"""name: map-bench
duration: 30
world:
{world}
network: {{radio: 802.11b, tx_power: 10, routing: none, packet_log: false,
          propagation: {{model: log_distance, exponent: 3, reference_loss: 46.6777}}}}
nodes:
""" + "".join(f"  - {{name: m{i}, model: mote, pose: [{(i % rooms) * ROOM + ROOM / 2 - 1}, "
              f"{(i // rooms) * ROOM + ROOM / 2 - 1}, 0], controller: {{name: pinger, "
              f"params: {{to: broadcast, interval: 2, start: {1 + (i * 0.7373) % 2:.4f}}}}}}}\n"
              for i in range(rooms * rooms))


def worlds(folder):
    hand = "\n".join(f"    - wall: {{from: [{x0}, {y0}], to: [{x1}, {y1}], thickness: {WALL}, height: 2.5}}"
                     for x0, y0, x1, y1 in walls())
    return {"map": "  map: {file: " + os.path.join(folder, "big.yaml") + ", material: concrete, thickness: 0.2}",
            "hand": "  obstacle_material: concrete\n  obstacles:\n" + hand,
            "none": "  obstacle_material: none\n  obstacles:\n" + hand}


ROBOT = """nodes:
  - name: r
    model: diffdrive
    pose: [3, 3, 0]
    controller: {name: waypoint, params: {waypoints: [[3, 8], [8, 8], [8, 3], [3, 3]], speed: 0.4}}
"""


def robot_worlds(folder):
    """A laser robot driving round its room for 60 s: in the map, among the same walls by hand,
    and with no walls (its baseline); no radio, no wall loss."""
    w = worlds(folder)
    return {"empty": "", "hand": "world:\n" + w["none"] + "\n",
            "map": "world:\n  map: {file: " + os.path.join(folder, "big.yaml") + "}\n"}


def timed(command, repeat):
    walls_s = []
    for _ in range(repeat):
        started = time.perf_counter()
        subprocess.run(command, check=True, capture_output=True)
        walls_s.append(time.perf_counter() - started)
    return statistics.median(walls_s)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sanet", default=os.path.join(ROOT, "build", "sanet"))
    parser.add_argument("--seconds", type=float, default=30, help="simulated seconds of the 400 motes")
    parser.add_argument("--repeat", type=int, default=3, help="runs of each case (the median is kept)")
    a = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        write_map(tmp)
        paths = {}
        for name, world in worlds(tmp).items():
            paths[name] = os.path.join(tmp, name + ".yaml")
            with open(paths[name], "w") as f:
                f.write(scenario(world))
        print(f"{len(walls())} walls; the map {int(ROOM * ROOMS / CELL)} x {int(ROOM * ROOMS / CELL)} cells")
        hand = timed([a.sanet, "validate", paths["hand"]], a.repeat)
        print(f"{'load':>22} {'wall s':>8} {'ratio':>6}")
        print(f"{'hand-made walls':>22} {hand:8.3f} {1:6.2f}")
        for name, command in (("the map (validate)", [a.sanet, "validate", paths["map"]]),
                              ("sanet map (write back)", [a.sanet, "map", paths["map"], "-o", tmp + "/out", "-q"])):
            took = timed(command, a.repeat)
            print(f"{name:>22} {took:8.3f} {took / hand:6.2f}")
        boxes = subprocess.run([a.sanet, "validate", paths["map"], "--print"], capture_output=True, text=True,
                               check=True).stdout.count("      - [")
        print(f"the map's boxes: {boxes}")
        print(f"\n{'a robot, 60 s':>22} {'wall s':>8} {'ratio':>6}")
        base = None
        for name, world in robot_worlds(tmp).items():
            path = os.path.join(tmp, "robot-" + name + ".yaml")
            with open(path, "w") as f:
                f.write("name: robot\nduration: 60\n" + world + ROBOT)
            wall, _ = measure(a.sanet, path, os.path.join(tmp, "robot-run-" + name), 60, [], a.repeat)
            base = base or wall
            print(f"{name:>22} {wall:8.3f} {wall / base:6.2f}")
        print(f"\n{'run of 400 motes':>22} {'wall s':>8} {'ratio':>6} {'received':>10} {'us/frame':>9} {'ratio':>6}")
        base = None
        for name in ("hand", "map", "none"):
            wall, summary = measure(a.sanet, paths[name], os.path.join(tmp, "run-" + name), a.seconds, [], a.repeat)
            received = summary["network"]["channel"]["frames_received"]
            per_frame = wall / max(received, 1) * 1e6
            base = base or (wall, per_frame)
            print(f"{name:>22} {wall:8.3f} {wall / base[0]:6.2f} {received:>10} {per_frame:9.2f} "
                  f"{per_frame / base[1]:6.2f}")


if __name__ == "__main__":
    main()
