"""Controllers for tests/python/python_controllers_test.py: each exercises part of the node API
a Python controller sees, and writes what it saw to the run's log, transitions and metrics."""
import math
import random

import numpy as np

import sanet


class Talker:
    """Drives a slow circle, reads every sensor it has and the network, tells the others."""

    def __init__(self, params):
        self.speed = params.get("speed", 0.2)
        self.peer = params.get("peer", "")
        self.every = params.get("every", 5)
        self.steps = 0
        self.draws = params.get("draws", False)

    def start(self, node):
        self.peer_id = node.lookup(self.peer) if self.peer else None
        node.log(f"start {node.name()} id={node.id()} nodes={node.node_count()} peer={self.peer_id} "
                 f"nobody={node.lookup('nobody')} name_of_peer={node.name_of(self.peer_id or 0)} "
                 f"unknown_name={node.name_of(999)!r} holonomic={node.holonomic()}")

    def control_step(self, node):
        self.steps += 1
        if not node.drive(self.speed, 0.0, 0.2):
            node.log("drive refused")
        if self.steps % self.every:
            return
        pose, odo, ir, laser = node.ground_truth(), node.odometry(), node.ir(), node.laser()
        node.metric("x", pose.x)
        node.metric("random", node.random())
        if self.draws:
            node.metric("python_random", random.random())
            node.metric("numpy_random", float(np.random.rand()))
        scan = ir if ir is not None else laser
        node.log(f"t={node.now():.1f} pose={pose.x:.4f},{pose.y:.4f},{pose.theta:.4f} odo={odo is not None} "
                 f"scan={type(scan.ranges).__name__}/{scan.ranges.dtype}/{len(scan.ranges)}/{scan.max_range} "
                 f"laser={laser is not None}")
        net = node.network()
        routes = ",".join(f"{node.name_of(r.destination)}>{node.name_of(r.next_hop)}/{r.hops}"
                          for r in net.routing_table())
        node.log(f"net {net.protocol()} routes {routes} neighbours {sorted(net.neighbours())}")
        if self.peer_id is not None:
            bearing = node.bearing(self.peer_id)
            if bearing is not None:
                node.metric("bearing_distance", bearing.distance)
            node.send(self.peer_id, b"to you %d" % self.steps)
        node.broadcast(bytearray(b"all"))

    def finish(self, node):
        """Once, at the end: what Node.sensor gives by name, and a radio that may sleep."""
        bearings = node.sensor("bearing")
        near = [(node.name_of(b.node), round(b.reading.distance)) for b in bearings] if bearings is not None else None
        node.log(f"finish steps={self.steps} truth={type(node.sensor('ground_truth')).__name__} "
                 f"ir={type(node.sensor('ir')).__name__} nothing={node.sensor('nothing')} bearings={near} "
                 f"wake={node.set_radio_sleep(False)}")

    def on_message(self, node, message):
        node.transition("listening", "heard", f"{node.name_of(message.sender)} {message.delivery} "
                                              f"{message.payload.decode()} to={message.to} "
                                              f"hops={message.hops} late={message.time_received >= message.time_sent}")


class Refusals:
    """What the node refuses: commands that are not numbers, wheel speeds of the wrong kind."""

    def __init__(self, params):
        self.done = False

    def control_step(self, node):
        if self.done:
            return
        self.done = True
        node.log(f"nan drive {node.drive(math.nan, 0, 0)}")
        node.log(f"wheel speeds {node.set_wheel_speeds([1.0, 1.0])}")
        try:
            node.send(0, "text is not bytes")
        except TypeError as e:
            node.log(f"send text: TypeError")


class Crash:
    """Fails at `at` seconds, two calls deep."""

    def __init__(self, params):
        self.at = params.get("at", 1.0)

    def control_step(self, node):
        node.drive(0.2)
        if node.now() >= self.at:
            self.deeper(node)

    def deeper(self, node):
        return {}["missing key"]


class Picky:
    """Takes a required `k`, a whole number `n` and a flag."""

    def __init__(self, params):
        self.k = params["k"]
        self.n = params.get("n", 3)
        self.fast = params.get("fast", False)
        self.params = params

    def control_step(self, node):
        if node.now() > 0.5:
            node.log(str(self.params.get("late", 1)))  # raises: read while built only


class Lister:
    """For sanet list: the parameters as it reads them."""

    def __init__(self, params):
        self.gain = params.get("gain", 1.5)
        self.name = params.get("label", "robot")
        self.points = params.get("points", [])

    def control_step(self, node):
        pass


class NotAController:
    pass


class Gauge:
    """Reports its battery every second as metrics, and logs when it is low."""

    def __init__(self, params):
        self.low = params.get("low", 0.5)
        self.said = False

    def start(self, node):
        pass

    def control_step(self, node):
        if round(node.now() * 10) % 10:
            return
        b = node.sensor("battery")
        node.metric("battery_j", b.remaining_j)
        node.metric("battery_w", b.power_w)
        if b.fraction < self.low and not self.said:
            node.log(f"low battery: {b.fraction:.3f} of {b.capacity_j:.0f} J at {b.voltage:.1f} V")
            self.said = True
