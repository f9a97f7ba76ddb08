#!/usr/bin/env python3
"""What the radio's walls cost (net/obstacle_loss_model.h). Runs each case three ways, the same
seed, and prints wall time, the ratio to the first (the baseline, measured in the same run),
frames sent and received, and the wall losses asked for and computed (the rest came from the
cache of pairs that did not move). The cost of one loss alone: build/bench/obstacle_loss_bench.

  400 motes    a 20 x 20 grid 40 m apart, AODV, 40 motes sending 64 B to a far mote every 2 s,
               with 0.2 m walls every 80 m across the field (a door every 40 m): no obstacles
               (baseline), the walls of material `none` (they exist but cost nothing: the radio
               must not pay for them), walls of 0.01 dB each (the same frames as the baseline
               but every loss computed: the cost per frame) and walls of concrete (fewer links,
               fewer frames: what walls do to a network)
  swarm-1k     the shipped swarm (1000 robots moving on the 2D engine, a beacon each per
               second): as shipped (no wall costs anything), then its arena walls of concrete:
               no link crosses them, but every pair has moved since its last frame, so every
               loss is computed through the grid (the worst case for the cache)

    bench/walls_bench.py [--sanet build/sanet] [--seconds 30] [--swarm-seconds 10]"""
import argparse
import json
import os
import subprocess
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def grid_scenario(material):
    """400 motes 40 m apart, walls of `material` every 80 m (None: no obstacles; a number: that
    loss in dB per crossing)."""
    lines = ["name: walls-400", "seed: 1", "duration: 30", "world:", "  size: [840, 840]"]
    loss = ""
    if isinstance(material, float):
        material, loss = "none", f", radio_loss_db: {material}"
    if material:
        lines += [f"  obstacle_material: {material}", "  obstacles:"]
        for k in range(1, 10):
            at = 80 * k - 20  # between mote rows and columns
            for start in range(-20, 780, 40):  # 30 m of wall, a 10 m doorway
                lines.append(f"    - wall: {{from: [{at}, {start}], to: [{at}, {start + 30}], height: 2.5{loss}}}")
                lines.append(f"    - wall: {{from: [{start}, {at}], to: [{start + 30}, {at}], height: 2.5{loss}}}")
    lines += ["network: {routing: aodv, packet_log: false}", "outputs: {trace: false, figures: false}", "nodes:",
              "  - grid: {name: m, rows: 20, cols: 20, origin: [0, 0], spacing: 40}", "    model: mote"]
    for i in range(40):
        source, to = (i * 10) % 400, (399 - i * 10) % 400
        lines += [f"  - name: s{i}", "    model: mote", f"    pose: [{40 * (source % 20) + 1}, {40 * (source // 20) + 1}, 0]",
                  f"    controller: {{name: pinger, params: {{to: m{to}, interval: 2, start: 1, size: 64}}}}"]
    return "\n".join(lines) + "\n"


def run(sanet, scenario, out, seconds, overrides=()):
    sets = [arg for o in overrides for arg in ("--set", o)]
    subprocess.run([sanet, "run", scenario, "-q", "-o", out, "--duration", str(seconds), *sets], check=True)
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def report(name, label, summary, baseline):
    channel = summary["network"]["channel"]
    walls = channel.get("walls", {})
    wall = summary["wall_time_s"]
    print(f"{name:>10} {label:>16} {wall:>8.2f} {wall / baseline['wall_time_s']:>6.3f} {channel['frames_sent']:>9} "
          f"{channel['frames_received']:>9} {walls.get('losses_asked', 0):>10} {walls.get('losses_computed', 0):>10}",
          flush=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sanet", default=os.path.join(ROOT, "build", "sanet"))
    parser.add_argument("--seconds", type=float, default=30, help="simulated seconds of the 400 motes")
    parser.add_argument("--swarm-seconds", type=float, default=10, help="simulated seconds of swarm-1k")
    a = parser.parse_args()
    print(f"{'case':>10} {'walls':>16} {'wall s':>8} {'ratio':>6} {'frames':>9} {'received':>9} "
          f"{'losses':>10} {'computed':>10}")
    with tempfile.TemporaryDirectory() as tmp:
        results = []
        for label, material in (("no obstacles", None), ("walls of none", "none"), ("walls of 0.01 dB", 0.01),
                                ("walls concrete", "concrete")):
            path = os.path.join(tmp, f"grid-{label.replace(' ', '-')}.yaml")
            with open(path, "w") as f:
                f.write(grid_scenario(material))
            results.append((label, run(a.sanet, path, os.path.join(tmp, "out"), a.seconds)))
        for label, summary in results:
            report("400 motes", label, summary, results[0][1])
        swarm = os.path.join(ROOT, "scenarios", "swarm-1k.yaml")
        results = [(label, run(a.sanet, swarm, os.path.join(tmp, "out"), a.swarm_seconds, sets))
                   for label, sets in (("as shipped", ()), ("arena concrete", ("world.obstacle_material=concrete",)))]
        for label, summary in results:
            report("swarm-1k", label, summary, results[0][1])


if __name__ == "__main__":
    main()
