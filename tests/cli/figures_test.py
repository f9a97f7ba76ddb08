#!/usr/bin/env python3
"""The figures render alike in rsvg-convert and ImageMagick: converted with both, every disc of
the packets map has its fill colour at its centre, the title strip is white, and the map has axes
with units, framed on what is drawn, a scale bar and a legend; the packets map shows robots as
well as motes. A run with figures also writes PNG copies. Needs rsvg-convert and ImageMagick (./setup installs them); skipped, saying so, without."""
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest
import xml.dom.minidom

SANET = sys.argv.pop(1)
SOURCE = sys.argv.pop(1)
CONVERT = shutil.which("convert")
RSVG = shutil.which("rsvg-convert")


def pixel(png, x, y):
    """(r, g, b) of one pixel, read with ImageMagick."""
    out = subprocess.run([CONVERT, png, "-crop", f"1x1+{int(x)}+{int(y)}", "-depth", "8", "txt:-"], check=True,
                         capture_output=True, text=True).stdout
    colour = re.search(r"#([0-9A-Fa-f]{6})", out.splitlines()[-1]).group(1)
    return tuple(int(colour[i:i + 2], 16) for i in (0, 2, 4))


def near(a, b, tolerance=10):
    return all(abs(p - q) <= tolerance for p, q in zip(a, b))


@unittest.skipIf(not (CONVERT and RSVG), "needs rsvg-convert (librsvg2-bin) and ImageMagick")
class Figures(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.out = os.path.join(cls.tmp.name, "help-request")
        subprocess.run([SANET, "run", os.path.join(SOURCE, "scenarios", "help-request.yaml"), "-q", "-o", cls.out],
                       check=True)
        cls.renders = {}
        for name in ("map", "packets"):
            svg = os.path.join(cls.out, name + ".svg")
            for tool, command in (("rsvg", [RSVG, "-o"]), ("magick", [CONVERT, svg])):
                png = os.path.join(cls.tmp.name, f"{name}-{tool}.png")
                subprocess.run(command + [png] + ([svg] if tool == "rsvg" else []), check=True, capture_output=True)
                cls.renders[name, tool] = png

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_every_disc_is_drawn_in_both_renderers(self):
        document = xml.dom.minidom.parse(os.path.join(self.out, "packets.svg"))
        discs = document.getElementsByTagName("circle")
        self.assertEqual(len(discs), 26, "one per mote and one for the robot, where it ended")
        for k, disc in enumerate(discs):
            self.assertEqual(disc.childNodes.length, 0, "nothing nested in a shape")
            x, y = float(disc.getAttribute("cx")), float(disc.getAttribute("cy"))
            if any(abs(float(d.getAttribute("cx")) - x) < 20 and abs(float(d.getAttribute("cy")) - y) < 20
                   for d in list(discs)[k + 1:]):
                continue  # drawn over by a later disc (the robot where it ended, on its target)
            fill = tuple(int(disc.getAttribute("fill")[i:i + 2], 16) for i in (1, 3, 5))
            for tool in ("rsvg", "magick"):
                got = pixel(self.renders["packets", tool], float(disc.getAttribute("cx")), float(disc.getAttribute("cy")))
                self.assertTrue(near(got, fill), f"{tool}: {got} at the centre of a disc filled {fill}")

    def test_the_title_strip_is_white_in_both(self):
        for name in ("map", "packets"):
            for tool in ("rsvg", "magick"):
                self.assertEqual(pixel(self.renders[name, tool], 3, 3), (255, 255, 255), (name, tool))

    def test_the_map_has_axes_a_scale_bar_and_a_legend(self):
        with open(os.path.join(self.out, "map.svg")) as f:
            text = f.read()
        for words in ("x (m)", "y (m)", "every 50 s", ">mote<", ">obstacle<", ">robot<", " m</text>"):
            self.assertIn(words, text)
        labels = re.findall(r'<text x="([\d.]+)" y="([\d.]+)" font-size="9.0"', text)
        self.assertGreater(len(labels), 10, "time marks are labelled")
        self.assertEqual(len(labels), len(set(labels)), "no two labels in the same place")

    def test_png_copies(self):
        for name in ("map", "packets"):
            self.assertTrue(os.path.exists(os.path.join(self.out, name + ".png")), name)

    def test_the_map_is_framed_on_what_it_draws(self):
        """A long wall widens the frame only along itself; the axes cover the nodes, tracks and
        obstacles and not much more."""
        with tempfile.TemporaryDirectory() as tmp:
            scenario = os.path.join(tmp, "wall.yaml")
            with open(scenario, "w") as f:
                f.write("duration: 5\nworld:\n  size: [30, 30]\n  obstacles:\n"
                        "    - wall: {from: [0, 0], to: [30, 0]}\n"
                        "nodes:\n  - {name: m0, model: mote, pose: [0, 2, 0]}\n"
                        "  - {name: m1, model: mote, pose: [30, 4, 0]}\n"
                        "outputs: {figures: true}\n")
            subprocess.run([SANET, "run", scenario, "-q", "-o", os.path.join(tmp, "out")], check=True)
            with open(os.path.join(tmp, "out", "map.svg")) as f:
                text = f.read()
        # x ticks sit under the plot (font-size 11, anchored middle); their values are the axis.
        xs = [float(v) for v in re.findall(r'font-size="11" text-anchor="middle">(-?[\d.]+)</text>', text)]
        ys = [float(v) for v in re.findall(r'font-size="11" text-anchor="end">(-?[\d.]+)</text>', text)]
        self.assertTrue(xs and ys, "the axes have ticks")
        self.assertGreaterEqual(min(xs), -3), self.assertLessEqual(max(xs), 33)
        self.assertGreaterEqual(max(xs), 25, "the axis reaches the wall's far end")
        self.assertGreaterEqual(min(ys), -5, "the wall along x does not stretch y by half its length")
        self.assertLessEqual(max(ys), 8)


if __name__ == "__main__":
    unittest.main(verbosity=2)
