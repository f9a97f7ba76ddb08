#!/usr/bin/env python3
"""Drives a robot from Python, step by step, to the mote at the far end of a line of motes,
while it reads the robot's routing table: the route to the mote shortens from five hops to one
as the robot comes near. A message from the robot every second keeps AODV's route fresh.

  PYTHONPATH=build/python /usr/bin/python3 examples/python/drive_to_mote.py [OUT_FOLDER]
"""
import math
import os
import sys

import sanet

HERE = os.path.dirname(os.path.abspath(__file__))


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "results/drive-to-mote"
    with sanet.Simulation(os.path.join(HERE, "drive_to_mote.yaml"), output=out, force=True) as sim:
        target = sim.nodes().index("m5")
        goal = sim.pose("m5")
        hops_seen = []
        while sim.step(0.1):
            pose = sim.pose("robot")
            dx, dy = goal.x - pose.x, goal.y - pose.y
            distance = math.hypot(dx, dy)
            if distance < 1.0:
                sim.drive("robot")  # stop
                print(f"{sim.now:6.1f} s  arrived, {distance:.2f} m from m5")
                break
            heading_error = math.atan2(dy, dx) - pose.theta
            heading_error = math.atan2(math.sin(heading_error), math.cos(heading_error))
            sim.drive("robot", vx=min(1.0, distance) * max(0.0, math.cos(heading_error)), omega=2.0 * heading_error)
            if round(sim.now * 10) % 10 == 0:  # every second
                sim.send("robot", "m5", b"where are you?")
                route = [r for r in sim.routing_table("robot") if r.destination == target and r.valid]
                hops = route[0].hops if route else None
                if not hops_seen or hops != hops_seen[-1]:
                    print(f"{sim.now:6.1f} s  x={pose.x:6.1f} m  route to m5: "
                          f"{'none yet' if hops is None else f'{hops} hops via {sim.nodes()[route[0].next_hop]}'}")
                    hops_seen.append(hops)
        result = sim.finish()
    delivered = sanet.Results(out).messages
    print(f"{len(delivered[delivered['to'] == 'm5'])} messages reached m5; results in {result['output']}/")


if __name__ == "__main__":
    main()
