#!/usr/bin/env python3
"""Case study 3 (docs/case-study-charging.md): the shipped charging-robot scenario, run with and
without its robot for the full 7200 s by the study's own script, keeps every mote alive with the
robot and loses all twelve without it, at the times the docs' table states; the figure is
written. (Label `experiment`: two runs of two hours, about 45 s.)"""
import os
import re
import subprocess
import sys
import tempfile
import unittest

SANET = sys.argv.pop(1)
SOURCE = sys.argv.pop(1)


def documented_table():
    """The lifetime table of docs/case-study-charging.md: {run: [first, half, last, dead]}."""
    with open(os.path.join(SOURCE, "docs", "case-study-charging.md")) as f:
        text = f.read()
    table = text.split("<!-- lifetime table")[1].split("\n\n")[0]
    return {cells[0]: cells[1:] for cells in
            ([c.strip() for c in line.strip("|").split("|")] for line in table.splitlines()[3:])}


class CaseStudy3(unittest.TestCase):
    def test_the_robot_keeps_the_network_alive_as_the_docs_say(self):
        with tempfile.TemporaryDirectory() as tmp:
            figure = os.path.join(tmp, "alive.svg")
            out = subprocess.run([os.path.join(SOURCE, "studies", "charging-robot", "run"), "--figure", figure],
                                 env=dict(os.environ, SANET=SANET, OUT=tmp), capture_output=True, text=True,
                                 timeout=600)
            self.assertEqual(out.returncode, 0, out.stderr)
            measured = {cells[0]: cells[1:] for cells in
                        ([c.strip() for c in line.strip("|").split("|")] for line in out.stdout.splitlines()
                         if line.startswith("| with") or line.startswith("| without"))}
            self.assertEqual(measured, documented_table())
            self.assertEqual(measured["with the robot"][3], "0 of 12")
            first_death_without = float(re.match(r"(\d+) s", measured["without it"][0]).group(1))
            self.assertLess(first_death_without, 7200)
            with open(figure) as f:
                self.assertIn("motes alive", f.read())


if __name__ == "__main__":
    unittest.main(verbosity=2)
