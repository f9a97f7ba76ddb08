#!/usr/bin/env python3
"""The sanet Python module (docs/python-module.md), imported by Debian's Python from the build
tree and installed:
- stepping changes poses; a robot driven from the script moves; a message sent from the script
  is in messages.csv; a script that does not act gets `sanet run`'s fingerprint; a second live
  Simulation is refused; the script's own random state is left as it was;
- DataFrames from a results folder equal its CSV files; a study's report equals `sanet report`;
- the examples (examples/python/) run and do what they say."""
import csv
import json
import os
import random
import subprocess
import sys
import tempfile
import unittest

SANET, MODULE, SOURCE = (os.path.abspath(a) for a in sys.argv[1:4])
del sys.argv[1:4]
sys.path.insert(0, MODULE)
import sanet  # noqa: E402

AROUND = os.path.join(SOURCE, "scenarios", "around-the-wall.yaml")
EXAMPLES = os.path.join(SOURCE, "examples", "python")
DRIVEN = """name: driven
seed: 2
duration: 20
network: {radio: 802.11b, routing: aodv}
nodes:
  - name: rover
    model: diffdrive
    pose: [0, 0, 0]
  - name: mote
    model: mote
    pose: [10, 3, 0]
"""


def summary(folder):
    with open(os.path.join(folder, "summary.json")) as f:
        return json.load(f)


def run_example(script, *args):
    env = dict(os.environ, PYTHONPATH=MODULE)
    return subprocess.run(["/usr/bin/python3", os.path.join(EXAMPLES, script), *args], capture_output=True,
                          text=True, timeout=300, env=env)


class Stepping(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.tmp.cleanup()

    def scenario(self, text):
        path = os.path.join(self.tmp.name, "s.yaml")
        with open(path, "w") as f:
            f.write(text)
        return path

    def test_a_script_that_does_not_act_gets_sanet_runs_fingerprint(self):
        out = os.path.join(self.tmp.name, "stepped")
        with sanet.Simulation(AROUND, output=out) as sim:
            while sim.step(0.7):  # pieces that fall anywhere between the run's events
                pass
        ran = os.path.join(self.tmp.name, "ran")
        subprocess.run([SANET, "run", AROUND, "-o", ran, "-q"], check=True)
        self.assertEqual(summary(out)["fingerprint"], summary(ran)["fingerprint"])
        for name in ("trajectories.csv", "log.csv", "transitions.csv", "metrics.csv"):
            with open(os.path.join(out, name)) as a, open(os.path.join(ran, name)) as b:
                self.assertEqual(a.read(), b.read(), name)
        # Both traces too: the module attaches the ROS 2 presentation (trace.mcap) as the command does.
        for name in ("trace.sqlite", "trace.mcap"):
            with open(os.path.join(out, name), "rb") as a, open(os.path.join(ran, name), "rb") as b:
                self.assertEqual(a.read(), b.read(), name)

    def test_stepping_changes_poses_and_reads_between_steps(self):
        with sanet.Simulation(AROUND, output=os.path.join(self.tmp.name, "o")) as sim:
            self.assertEqual(sim.now, 0)
            start = sim.pose("robot")
            for _ in range(10):
                sim.step(0.1)
            self.assertAlmostEqual(sim.now, 1.0, places=9)
            moved = sim.pose("robot")
            self.assertGreater(moved.x - start.x, 0.2)
            vx, vy, omega = sim.velocity("robot")
            self.assertGreater(vx, 0.3)
            readings = sim.readings("robot")
            self.assertEqual(len(readings["ir"]["ranges"]), 6)
            self.assertAlmostEqual(readings["time"], 0.9, places=6, msg="its controller's last step before now")
            sim.step(0.05)  # what happens at 1 s happens in the next step
            self.assertAlmostEqual(sim.readings("robot")["time"], 1.0, places=6)
            self.assertIn("mote0", sim.nodes())
            with self.assertRaises(KeyError):
                sim.pose("nobody")
            with self.assertRaisesRegex(ValueError, "scenario controller"):
                sim.drive("robot", vx=1)

    def test_a_robot_driven_from_the_script_moves_and_its_message_is_delivered(self):
        scenario = self.scenario(DRIVEN)
        out = os.path.join(self.tmp.name, "driven")
        with sanet.Simulation(scenario, output=out) as sim:
            sim.drive("rover", vx=0.5)
            sim.step(4)
            self.assertAlmostEqual(sim.pose("rover").x, 2.0, delta=0.3)
            sim.send("rover", "mote", b"hello mote")
            sim.step(2)
            delivered = sim.messages()
            self.assertEqual([(m["from"], m["to"], m["payload"]) for m in delivered],
                             [("rover", "mote", b"hello mote")])
            self.assertIn(1, [r.destination for r in sim.routing_table("rover")], "AODV found the mote")
            self.assertFalse(sim.drive("mote", vx=1), "a mote cannot move: False, as Node.drive")
        rows = list(csv.DictReader(open(os.path.join(out, "messages.csv"))))
        self.assertEqual([(r["from"], r["to"], r["bytes"]) for r in rows], [("rover", "mote", "10")])

    def test_a_second_live_simulation_is_refused(self):
        with sanet.Simulation(AROUND, output=os.path.join(self.tmp.name, "a")):
            with self.assertRaisesRegex(RuntimeError, "one per process"):
                sanet.Simulation(AROUND, output=os.path.join(self.tmp.name, "b"))
        with sanet.Simulation(AROUND, output=os.path.join(self.tmp.name, "b"), duration=1) as sim:
            self.assertFalse(sim.run())

    def test_the_scripts_random_state_is_its_own(self):
        with open(os.path.join(SOURCE, "tests", "python", "probe.py")) as f:
            probe = f.read()
        with open(os.path.join(self.tmp.name, "probe.py"), "w") as f:
            f.write(probe)
        scenario = self.scenario("""name: drawn
duration: 2
nodes:
  - name: a
    model: omni3
    pose: [0, 0, 0]
    controller: {python: "probe:Talker", params: {draws: true}}
""")
        random.seed(99)
        expected = [random.random() for _ in range(3)]
        random.seed(99)
        with sanet.Simulation(scenario, output=os.path.join(self.tmp.name, "drawn")) as sim:
            got = [random.random()]
            sim.step(1)
            got.append(random.random())
            sim.run()
            got.append(random.random())
        self.assertEqual(got, expected, "the controllers draw from the run's stream, not the script's")
        ran = os.path.join(self.tmp.name, "drawn-run")
        subprocess.run([SANET, "run", scenario, "-o", ran, "-q"], check=True)
        def drawn(folder):
            return [r["value"] for r in csv.DictReader(open(os.path.join(folder, "metrics.csv")))
                    if r["name"] == "python_random"]
        self.assertEqual(drawn(os.path.join(self.tmp.name, "drawn")), drawn(ran), "the same draws as sanet run")


class DataFrames(unittest.TestCase):
    def test_results_equal_the_csv_files(self):
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "r")
            subprocess.run([SANET, "run", os.path.join(SOURCE, "scenarios", "sensor-network.yaml"), "-o", out, "-q",
                            "--duration", "20"], check=True)
            results = sanet.Results(out)
            for name in ("trajectories", "messages", "packets", "metrics", "transitions"):
                frame = getattr(results, name)
                with open(os.path.join(out, name + ".csv")) as f:
                    rows = list(csv.reader(f))
                self.assertEqual(list(frame.columns), rows[0], name)
                self.assertEqual(len(frame), len(rows) - 1, name)
                for column in range(min(len(frame), 1) and len(rows[0])):  # the first row, as written
                    value, written = frame.iloc[0, column], rows[1][column]
                    if isinstance(value, str) or written == "":
                        self.assertEqual(str(value) if written else written, written, name)
                    else:
                        self.assertAlmostEqual(float(value), float(written), places=9, msg=name)
            self.assertEqual(results.summary["fingerprint"], summary(out)["fingerprint"])
            with self.assertRaisesRegex(FileNotFoundError, "no routes2.csv|has no"):
                results.table("routes2")
            # trace.sqlite's tables, with node names beside the ids: every frame a node received
            # from a known peer (an ACK names none) was sent by it, and the messages are
            # messages.csv's.
            frames = results.trace("frames")
            received = frames[frames.direction == "rx"]
            self.assertGreater(len(received), 100)
            sent = frames[frames.direction == "tx"]
            self.assertTrue(set(received.peer_name.dropna()) <= set(sent.node_name))
            self.assertEqual(set(frames.node_name), set(results.trace("nodes").name) & set(frames.node_name))
            traced = results.trace("messages")
            self.assertEqual(len(traced), len(results.messages))
            self.assertEqual(sorted(traced.from_name), sorted(results.messages["from"]))
            with self.assertRaisesRegex(KeyError, "its tables are nodes"):
                results.trace("frames; DROP TABLE frames")

    def test_a_study_reports_sanet_reports_numbers(self):
        with tempfile.TemporaryDirectory() as tmp:
            study = os.path.join(tmp, "study")
            subprocess.run([SANET, "sweep", AROUND, "--vary", "nodes.robot.controller.params.speed=0.4,0.7",
                            "--seeds", "1-3", "-o", study, "-q", "--duration", "80"], check=True)
            s = sanet.Study(study)
            self.assertEqual(s.parameters, ["nodes.robot.controller.params.speed"])
            self.assertEqual(len(s.runs), 6)
            table = s.report("ended_at_s")
            printed = subprocess.run([SANET, "report", study, "-m", "ended_at_s"], capture_output=True, text=True,
                                     check=True).stdout
            def first_number(line):
                try:
                    return float(line.split()[0])
                except (IndexError, ValueError):
                    return None
            self.assertEqual(table["value"].dtype.kind, "f", "the speeds are numbers")
            for row in table.itertuples():
                line = next(l for l in printed.splitlines() if first_number(l) == row.value)
                words = line.split()
                self.assertEqual(int(words[1]), row.runs)
                self.assertAlmostEqual(float(words[2]), row.mean, places=2)
            scalars = s.scalars
            self.assertEqual(len(scalars), 6)
            self.assertIn("ended_at_s", scalars.columns)


class Examples(unittest.TestCase):
    def test_drive_to_mote(self):
        with tempfile.TemporaryDirectory() as tmp:
            done = run_example("drive_to_mote.py", os.path.join(tmp, "out"))
            self.assertEqual(done.returncode, 0, done.stderr)
            self.assertIn("arrived", done.stdout)
            hops = [int(l.split("route to m5: ")[1].split()[0]) for l in done.stdout.splitlines()
                    if "hops via" in l]
            self.assertGreaterEqual(hops[0], 3, done.stdout)
            self.assertEqual(hops[-1], 1, "next to it, one hop")

    def test_sweep_by_stepping(self):
        with tempfile.TemporaryDirectory() as tmp:
            done = run_example("sweep_by_stepping.py", tmp)
            self.assertEqual(done.returncode, 0, done.stderr)
            rows = list(csv.DictReader(open(os.path.join(tmp, "arrival.csv"))))
            arrivals = [float(r["arrival_s"]) for r in rows]
            self.assertEqual(len(arrivals), 4)
            self.assertLess(arrivals[-1], arrivals[0], "faster arrives sooner")
            self.assertTrue(os.path.getsize(os.path.join(tmp, "arrival.png")) > 1000)

    def test_load_study(self):
        with tempfile.TemporaryDirectory() as tmp:
            study = os.path.join(tmp, "study")
            subprocess.run([SANET, "sweep", AROUND, "--vary", "nodes.robot.controller.params.speed=0.4,0.7",
                            "--seeds", "1-2", "-o", study, "-q", "--duration", "80"], check=True)
            done = run_example("load_study.py", study)
            self.assertEqual(done.returncode, 0, done.stderr)
            self.assertIn("parameters: nodes.robot.controller.params.speed", done.stdout)
            self.assertIn("mean", done.stdout)


class Installed(unittest.TestCase):
    def test_the_installed_package_imports(self):
        with tempfile.TemporaryDirectory() as prefix:
            subprocess.run(["cmake", "--install", os.path.dirname(MODULE), "--prefix", prefix,
                            "--component", "python"], check=True, capture_output=True)
            site = os.path.join(prefix, "lib", f"python{sys.version_info.major}.{sys.version_info.minor}",
                                "dist-packages")
            done = subprocess.run(["/usr/bin/python3", "-c", "import sanet; print(sanet.__file__); "
                                   "help(sanet.Simulation)"], capture_output=True, text=True,
                                  env=dict(os.environ, PYTHONPATH=site), cwd=prefix)
            self.assertEqual(done.returncode, 0, done.stderr)
            self.assertTrue(done.stdout.startswith(site), done.stdout[:200])
            self.assertIn("step(", done.stdout)


if __name__ == "__main__":
    unittest.main(verbosity=2)
