#!/usr/bin/env python3
"""Latencies of sanet's ROS 2 face with 4, 16 and 32 robots on it, against as many robots driven
over the USARSim protocol in the same run (the baseline): for each side, command -> motion (from
sending a command that starts a still robot to receiving the first sensor reading that shows it
moved, sensors at 10 Hz on both sides) and sensor -> subscriber (from the simulated time a
reading was taken to its arrival), p50 and p99; and the server's real-time lag. ROS 2 robots are
driven by bench/ros2_latency.c over DDS (Cyclone's own encoder, types from tests/ros2), USARSim
robots by one thread each here. Command latencies are compared as a ratio, ROS 2 over USARSim;
sensor latencies, a millisecond or less on one machine and read against the server's ClockOrigin
(itself taken at its first poll, so good to about a millisecond), as the difference of the two.

    bench/ros2_face.py build/sanet build/bench/ros2_latency [seconds per case, default 20]"""
import json
import os
import re
import socket
import subprocess
import sys
import tempfile
import threading
import time

sanet, latency_client = sys.argv[1], sys.argv[2]
seconds = float(sys.argv[3]) if len(sys.argv) > 3 else 20
DOMAIN = 60 + os.getpid() % 100


def percentile(values, q):
    values = sorted(values)
    return values[int(q * (len(values) - 1))] if values else float("nan")


def usarsim_robot(port, name, origin, seconds, index, count, command, sensor):
    """One USARSim client: the same go/stop cycle as the ROS 2 side, over DRIVE and SEN."""
    s = socket.create_connection(("127.0.0.1", port))
    s.sendall(f"INIT {{Name {name}}}\r\n".encode())
    start, pending, going, sent, at, last = time.monotonic(), b"", False, 0.0, None, None
    next_send = start + 2.0 + 0.5 * index / count
    s.settimeout(0.002)
    while time.monotonic() - start < seconds:
        try:
            data = s.recv(65536)
            if not data:
                break
            pending += data
        except socket.timeout:
            pass
        while b"\r\n" in pending:
            line, pending = pending.split(b"\r\n", 1)
            m = re.match(rb"SEN \{Time ([\d.]+)\} \{Type GroundTruth\}.*\{Location ([-\d.]+),([-\d.]+)", line)
            if not m:
                continue
            arrived, read = time.monotonic(), origin + float(m.group(1))
            sensor.append(1000 * (arrived - read))
            last = (float(m.group(2)), float(m.group(3)))
            if going and sent and read > sent and ((last[0] - at[0]) ** 2 + (last[1] - at[1]) ** 2) ** 0.5 > 0.002:
                command.append(1000 * (arrived - sent))
                sent = 0.0
        if time.monotonic() >= next_send and last:
            going = not going
            at, sent = last, time.monotonic()
            s.sendall(f"DRIVE {{LinearVelocity {0.3 if going else 0}}}\r\n".encode())
            next_send += 0.5
    s.close()


def case(count):
    with tempfile.TemporaryDirectory() as tmp:
        lines = [f"duration: {seconds + 10}", "nodes:"]
        for i in range(count):
            lines.append(f"  - {{name: r{i}, model: omni3, pose: [{3 * (i % 8)}, {3 * (i // 8)}, 0]}}")
            lines.append(f"  - {{name: u{i}, model: omni3, pose: [{3 * (i % 8)}, {30 + 3 * (i // 8)}, 0]}}")
        path = os.path.join(tmp, "s.yaml")
        open(path, "w").write("\n".join(lines) + "\n")
        port_file = os.path.join(tmp, "port")
        server = subprocess.Popen([sanet, "serve", path, "--port", "0", "--port-file", port_file, "-o",
                                   os.path.join(tmp, "out"), "--ros2", "--ros2-domain", str(DOMAIN), "-q"],
                                  stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        while not os.path.exists(port_file):
            time.sleep(0.01)
        port = int(open(port_file).read())
        hello = socket.create_connection(("127.0.0.1", port)).recv(4096).decode()
        origin = float(re.search(r"\{ClockOrigin ([\d.]+)\}", hello).group(1))
        ros2 = subprocess.Popen([latency_client, str(DOMAIN), repr(origin), str(seconds), str(count), "r"],
                                stdout=subprocess.PIPE, text=True)
        u_command, u_sensor = [], []
        threads = [threading.Thread(target=usarsim_robot, args=(port, f"u{i}", origin, seconds, i, count, u_command,
                                                                u_sensor)) for i in range(count)]
        for t in threads:
            t.start()
        r_out = ros2.communicate()[0]
        for t in threads:
            t.join()
        server.send_signal(2)  # Ctrl-C: the run ends with its results
        server.communicate(timeout=60)
        lag = json.load(open(os.path.join(tmp, "out", "summary.json")))["real_time_lag"]
        r_command = [float(l.split()[1]) for l in r_out.splitlines() if l.startswith("command ")]
        r_sensor = [float(l.split()[1]) for l in r_out.splitlines() if l.startswith("sensor ")]
        return r_command, r_sensor, u_command, u_sensor, lag


print(f"sanet ROS 2 face: N robots over DDS and N over the USARSim protocol in one run, sensors 10 Hz, "
      f"{seconds:.0f} s per case; ms; robots = both sides; ratio = ROS 2 / USARSim, +ms = ROS 2 - USARSim")
print(f"{'robots':>6} | {'command p50':>11} {'p99':>7} {'ratio':>6} | {'sensor p50':>10} {'p99':>7} {'+ms':>6} | "
      f"{'USARSim cmd p50':>15} {'p99':>7} | {'sensor p50':>10} {'p99':>7} | {'lag p99':>7} {'missed':>6}")
for count in (4, 16, 32):
    rc, rs, uc, us, lag = case(count)
    print(f"{2 * count:>6} | {percentile(rc, .5):>11.1f} {percentile(rc, .99):>7.1f} "
          f"{percentile(rc, .5) / percentile(uc, .5):>6.2f} | {percentile(rs, .5):>10.2f} {percentile(rs, .99):>7.2f} "
          f"{percentile(rs, .5) - percentile(us, .5):>+6.2f} | {percentile(uc, .5):>15.1f} {percentile(uc, .99):>7.1f} | "
          f"{percentile(us, .5):>10.2f} {percentile(us, .99):>7.2f} | {1000 * lag['p99_s']:>7.2f} "
          f"{lag['missed_deadlines']:>6}   ({len(rc)}/{len(uc)} commands, {len(rs)}/{len(us)} readings)", flush=True)
