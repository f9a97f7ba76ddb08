#!/usr/bin/env python3
"""What the live view costs a run: the formation scenario (and any given) run without --view,
with --view and no browser, and with --view and one client reading every frame (server-sent
events), each best of three; prints wall times and their ratios to the plain run.

    bench/view_bench.py build/sanet [duration s, default 200]"""
import os
import subprocess
import sys
import tempfile
import threading
import time
import urllib.request

sanet = sys.argv[1]
duration = sys.argv[2] if len(sys.argv) > 2 else "200"
scenario = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scenarios", "formation.yaml")


def reader(port_file, counted):
    for _ in range(4000):
        if os.path.exists(port_file) and open(port_file).read().strip():
            break
        time.sleep(0.001)
    with urllib.request.urlopen(f"http://127.0.0.1:{int(open(port_file).read())}/api/live", timeout=60) as stream:
        for line in stream:
            counted[0] += line.startswith(b"data: ")
            if line.startswith(b"event: end"):
                return


def wall(mode):
    best, frames = None, 0
    for _ in range(3):
        with tempfile.TemporaryDirectory() as tmp:
            args = [sanet, "run", scenario, "--duration", duration, "-q", "-o", os.path.join(tmp, "out")]
            port_file = os.path.join(tmp, "port")
            if mode != "plain":
                args += ["--view", "--view-port", "0", "--view-port-file", port_file]
            counted = [0]
            client = threading.Thread(target=reader, args=(port_file, counted)) if mode == "client" else None
            start = time.monotonic()
            process = subprocess.Popen(args)
            if client:
                client.start()
            process.wait()
            elapsed = time.monotonic() - start
            if client:
                client.join()
            best = elapsed if best is None else min(best, elapsed)
            frames = max(frames, counted[0])
    return best, frames


print(f"live view overhead: formation, {duration} s simulated, best of 3")
base, _ = wall("plain")
print(f"{'mode':>22} {'wall s':>8} {'ratio':>7} {'frames':>7}")
print(f"{'no --view':>22} {base:>8.2f} {1:>7.3f} {'':>7}")
for mode, label in (("none", "--view, no browser"), ("client", "--view, one client")):
    seconds, frames = wall(mode)
    print(f"{label:>22} {seconds:>8.2f} {seconds / base:>7.3f} {frames if mode == 'client' else '':>7}", flush=True)
