"""Visits a list of way points in order, going round obstacles it meets, and stops at the last.

sanet's built-in `waypoint` controller (controllers/waypoint.cc with its pilot,
controllers/navigation.cc) written again in Python, step for step, as an example of a Python
controller: `controller: {python: "waypoint:Waypoint", params: {...}}` with this file beside the
scenario (or on --python-path). Same parameters, same defaults, the same trajectory
(tests/python/python_controllers_test.py compares them).
"""
import math

import sanet

SECTOR = math.pi / 3  # half-width of the "ahead" sector around the goal direction


def wrap_angle(a):
    """Into (-pi, pi], as sanet's WrapAngle."""
    a = math.fmod(a + math.pi, 2 * math.pi)
    if a <= 0:
        a += 2 * math.pi
    return a - math.pi


class Pilot:
    """Head for the goal; when something blocks the way, follow its boundary until the goal is
    nearer than where the obstacle was met and the way towards it is clear (the Bug2 idea)."""

    def __init__(self, params):
        self.speed = params.get("speed", 0.5)
        self.safe_distance = params.get("safe_distance", 0.5)
        self.follow_distance = params.get("follow_distance", 0.35)
        self.turn_gain = params.get("turn_gain", 2.0)
        for key, low, high in (("speed", 0.01, 10), ("safe_distance", 0.05, 50), ("follow_distance", 0.05, 50),
                               ("turn_gain", 0.01, 100)):
            value = getattr(self, key)
            if not low <= value <= high:
                raise sanet.ParamError(key, f"parameter '{key}' is {value:g}, must be >= {low:g} and <= {high:g}")
        self.following = False
        self.side = 1.0
        self.hit_distance = 0.0
        self.last_heading = 0.0
        self.hold_heading = None
        self.last_time = None

    def choose_heading(self, pose, goal, scan, dt):
        dx, dy = goal[0] - pose.x, goal[1] - pose.y
        goal_heading = math.atan2(dy, dx)
        distance = math.hypot(dx, dy)
        if scan is None or len(scan.ranges) == 0:
            return goal_heading
        goal_local = wrap_angle(goal_heading - pose.theta)
        nearest, nearest_angle, ahead = scan.max_range, 0.0, scan.max_range
        left_room = right_room = 0.0
        for r, a in zip(scan.ranges.tolist(), scan.angles.tolist()):
            if r < nearest:
                nearest, nearest_angle = r, a
            off = wrap_angle(a - goal_local)
            if abs(off) < SECTOR:
                ahead = min(ahead, r)
            if off > 0:
                left_room += r
            else:
                right_room += r
        if not self.following:
            if ahead >= self.safe_distance or distance < ahead:
                return goal_heading
            self.following = True
            self.hit_distance = distance
            self.side = 1.0 if left_room >= right_room else -1.0
            self.last_heading = goal_heading
        elif ahead >= self.safe_distance and distance < self.hit_distance - 0.05:
            self.following = False
            return goal_heading
        if nearest >= scan.max_range:
            radius = self.follow_distance + self.safe_distance
            self.last_heading = wrap_angle(self.last_heading - self.side * self.speed * dt / radius)
            return self.last_heading
        lean = min(max(2.0 * (nearest - self.follow_distance), -math.pi / 4), math.pi / 4)
        self.last_heading = wrap_angle(pose.theta + nearest_angle + self.side * (math.pi / 2 - lean))
        return self.last_heading

    def steer(self, now, pose, goal, scan, holonomic):
        """The velocity (robot frame) towards `goal`: (vx, vy, omega)."""
        dt = min(max(now - self.last_time, 0.0), 1.0) if self.last_time is not None else 0.1
        self.last_time = now
        heading = self.choose_heading(pose, goal, scan, dt)
        distance = math.hypot(goal[0] - pose.x, goal[1] - pose.y)
        speed = min(self.speed, 0.8 * distance + 0.05)
        if holonomic:
            if self.hold_heading is None:
                self.hold_heading = pose.theta
            angle = heading - pose.theta
            c, s = math.cos(angle), math.sin(angle)
            return c * speed - s * 0, s * speed + c * 0, self.turn_gain * wrap_angle(self.hold_heading - pose.theta)
        error = wrap_angle(heading - pose.theta)
        return speed * max(0.0, math.cos(error)), 0.0, self.turn_gain * error


class Waypoint:
    """Visits `waypoints` ([[x, y], ...] m) in order at `speed`, going round obstacles seen by its
    laser or IR ring; stops within `tolerance` of the last (or starts over with `loop`)."""

    def __init__(self, params):
        self.pilot = Pilot(params)
        self.tolerance = params.get("tolerance", 0.3)
        if self.tolerance < 0.01:
            raise sanet.ParamError("tolerance", f"parameter 'tolerance' is {self.tolerance:g}, must be >= 0.01")
        localization = params.get("localization", "ground_truth")
        if localization not in ("ground_truth", "odometry"):
            raise sanet.ParamError("localization", "parameter 'localization' must be ground_truth or odometry")
        self.use_odometry = localization == "odometry"
        self.loop = params.get("loop", False)
        points = params.get("waypoints", [])
        if not all(isinstance(p, list) and len(p) == 2 for p in points):
            raise sanet.ParamError("waypoints", "parameter 'waypoints' must be a list of [2 numbers] lists")
        self.points = [(float(x), float(y)) for x, y in points]
        if not self.points:
            raise sanet.ParamError("waypoints", "parameter 'waypoints' is required: [[x, y], ...]")
        self.next = 0

    def control_step(self, node):
        if self.next >= len(self.points):
            return
        pose = node.odometry() if self.use_odometry else node.ground_truth()
        if pose is None:
            return
        goal = self.points[self.next]
        if math.hypot(goal[0] - pose.x, goal[1] - pose.y) < self.tolerance:
            node.log(f"reached waypoint {self.next}")
            self.pilot.following = False
            self.next += 1
            if self.next == len(self.points):
                if not self.loop:
                    node.drive()
                    node.log("arrived")
                    return
                self.next = 0
        scan = node.laser()
        if scan is None:
            scan = node.ir()
        was_following = self.pilot.following
        node.drive(*self.pilot.steer(node.now(), pose, self.points[self.next], scan, node.holonomic()))
        if self.pilot.following != was_following:
            node.log("obstacle: following its boundary" if self.pilot.following else "way clear: heading for the goal")
