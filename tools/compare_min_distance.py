#!/usr/bin/env python3
"""Draws the smallest inter-robot distance of two runs on one SVG and prints how they differ.
    tools/compare_min_distance.py SIM/min_distance.csv HIL/min_distance.csv OUT.svg"""
import csv
import statistics
import sys

def load(path):
    return [(float(r["time"]), float(r["min_distance"])) for r in csv.DictReader(open(path))]

a, b = load(sys.argv[1]), load(sys.argv[2])
w, h, left, bottom, top = 800, 360, 60, 40, 40
x1 = max(t for t, _ in a + b)
y1 = max(d for _, d in a + b) * 1.1
px = lambda t: left + t / x1 * (w - left - 20)
py = lambda d: h - bottom - d / y1 * (h - top - bottom)
svg = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" font-family="sans-serif">',
       f'<rect width="{w}" height="{h}" fill="#fff"/>',
       '<text x="8" y="22" font-size="16">smallest distance between robots: simulated network (blue) and real UDP in the loop (red)</text>',
       f'<line x1="{left}" y1="{h - bottom}" x2="{w - 20}" y2="{h - bottom}" stroke="#000"/>',
       f'<line x1="{left}" y1="{top}" x2="{left}" y2="{h - bottom}" stroke="#000"/>']
for i in range(6):
    t, d = x1 * i / 5, y1 * i / 5
    svg.append(f'<text x="{px(t):.1f}" y="{h - bottom + 16}" font-size="11" text-anchor="middle">{t:.0f} s</text>')
    svg.append(f'<text x="{left - 6}" y="{py(d) + 4:.1f}" font-size="11" text-anchor="end">{d:.1f} m</text>')
for series, color in ((a, "#1f77b4"), (b, "#d62728")):
    points = " ".join(f"{px(t):.1f},{py(d):.1f}" for t, d in series)
    svg.append(f'<polyline fill="none" stroke="{color}" stroke-width="1" points="{points}"/>')
svg.append("</svg>")
open(sys.argv[3], "w").write("\n".join(svg) + "\n")
bt = dict((round(t, 1), d) for t, d in b)
diffs = [abs(d - bt[round(t, 1)]) for t, d in a if round(t, 1) in bt]
print(f"min {min(d for _, d in a):.2f} m vs {min(d for _, d in b):.2f} m; mean |difference| {statistics.mean(diffs):.3f} m, max {max(diffs):.2f} m over {len(diffs)} samples")
