#!/usr/bin/env python3
"""`sanet serve --wss-port`: a client of USARSim's Wireless Simulation Server protocol, written from
docs/protocol.md with the standard library only, registers two robots, reads a signal strength
that falls with their simulated distance as ns-3's log-distance model says (and by a wall's loss
behind a wall), opens a relayed TCP
connection to the other robot's port and talks through it, learns who is behind it (REVERSEDNS),
and sees it cut, and the relay port closed, once the robot drives out of range. Errors are
answered as WSS answers them."""
import math
import os
import socket
import sys
import tempfile
import threading
import time
import unittest
import warnings

from protocol_client import Client, Wss, field, serve

SANET = sys.argv.pop(1)
TX_POWER = 0
RANGE = 10 ** ((TX_POWER - 46.6777 + 82) / 30)  # m, where log-distance loss meets the -82 dBm threshold
HANDSHAKE_TIME = 3  # s: a connection that has not spoken by then is closed (docs/protocol.md, Safety)
WALL_LOSS = 12  # dB: the wall between r1 and `behind` (`beside` stands as far from r1 in the open)
SCENARIO = f"""duration: 25
world:
  obstacles:
    - wall: {{from: [-2.5, -1.5], to: [-2.5, 1.5], height: 2, radio_loss_db: {WALL_LOSS}}}
network: {{tx_power: {TX_POWER}, routing: aodv}}
nodes:
  - {{name: r1, model: omni3, pose: [0, 0, 0]}}
  - {{name: r2, model: omni3, pose: [8, 0, 0]}}
  - {{name: behind, model: mote, pose: [-5, 0, 0]}}
  - {{name: beside, model: mote, pose: [0, -5, 0]}}
"""


def model_dbm(distance):
    return TX_POWER - 46.6777 - 30 * math.log10(distance)


def echo_server():
    """A robot's program listening on a port: echoes what it gets. Returns (port, peers seen)."""
    listener = socket.socket()
    listener.bind(("127.0.0.1", 0))
    listener.listen()
    peers = []

    def serve_forever():
        while True:
            conn, peer = listener.accept()
            peers.append(peer[1])
            threading.Thread(target=lambda c=conn: [c.sendall(d) for d in iter(lambda: c.recv(4096), b"")],
                             daemon=True).start()

    threading.Thread(target=serve_forever, daemon=True).start()
    return listener.getsockname()[1], peers


class WirelessSimulationServer(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        path = os.path.join(cls.tmp.name, "wss")
        os.makedirs(path)
        port_file = os.path.join(path, "wss-port")
        cls.server, cls.port, cls.out = serve(SANET, SCENARIO, path, "--wss-port", "0", "--wss-port-file", port_file)
        with open(port_file) as f:
            cls.wss_port = int(f.read())
        cls.r2_port, cls.r2_peers = echo_server()
        cls.errors = cls.try_errors()
        cls.run_the_story()
        cls.server.wait(timeout=60)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    @classmethod
    def try_errors(cls):
        w = Wss(cls.wss_port)
        errors = {"before init": w.ask("GETSS {Robot r2}"), "bad ports": w.ask("INIT {Robot x} {Port five}"),
                  "no name": w.ask("INIT {Robot } {Port 5000}"), "not in world": w.ask("INIT {Robot ghost} {Port 5000}")}
        w.sock.close()
        return errors

    @classmethod
    def run_the_story(cls):
        w1, w2 = Wss(cls.wss_port), Wss(cls.wss_port)
        cls.init = [w1.ask("INIT {Robot r1} {Port 4999}")]
        # r2 is in the world but not yet registered: GETSS answers from the radio, DNS cannot.
        cls.errors.update({"unregistered": w1.ask("GETSS {Robot r2}"), "dns unregistered": w1.ask("DNS {Robot r2}")})
        cls.init.append(w2.ask(f"INIT {{Robot r2}} {{Port {cls.r2_port}}}"))
        cls.errors.update({"taken": Wss(cls.wss_port).ask("INIT {Robot r1} {Port 5000}"),
                           "self": w1.ask("GETSS {Robot r1}"), "unknown": w1.ask("GETSS {Robot nobody}"),
                           "dns unknown": w1.ask("DNS {Robot nobody}"), "dns self": w1.ask("DNS {Robot r1}"),
                           "dns port": w1.ask("DNS {Robot r2} {Port 1}"), "second init": w1.ask("INIT {Robot r1} {Port 1}"),
                           "reverse unknown": w2.ask("REVERSEDNS {Port 1}")})
        cls.walled = {name: float(field(w1.ask(f"GETSS {{Robot {name}}}"), "Strength")) for name in ("behind", "beside")}
        dns = w1.ask("DNS {Robot r2}")
        cls.relay_port = int(field(dns, "Port"))
        cls.dns_again = w1.ask(f"DNS {{Robot r2}} {{Port {cls.r2_port}}}")
        relayed = socket.create_connection(("127.0.0.1", cls.relay_port), timeout=5)
        relayed.sendall(b"hello r2")
        cls.echo = relayed.recv(100)
        cls.reverse = w2.ask(f"REVERSEDNS {{Port {cls.r2_peers[0]}}}")
        # Drive r2 away along +x while asking for the signal and watching the relayed connection.
        driver = Client(cls.port)
        driver.send("INIT {Name r2}")
        driver.send("DRIVE {LinearVelocity 1.0}")
        cls.samples, cls.cut_at = [], None
        relayed.settimeout(0.05)
        while True:
            x = float(field(driver.sensor("GroundTruth"), "Location").split(",")[0])
            strength = field(w1.ask("GETSS {Robot r2}"), "Strength")
            cls.samples.append((x, float(strength)))
            if cls.cut_at is None:
                try:
                    if relayed.recv(100) == b"":
                        cls.cut_at = x
                except socket.timeout:
                    pass
                except ConnectionError:
                    cls.cut_at = x
            if x > RANGE + 2:
                break
        try:
            socket.create_connection(("127.0.0.1", cls.relay_port), timeout=2).close()
            cls.relay_closed = False
        except ConnectionRefusedError:
            cls.relay_closed = True
        driver.send("DRIVE {LinearVelocity -1.0}")  # back into range: the relay listens again
        while float(field(driver.sensor("GroundTruth"), "Location").split(",")[0]) > RANGE - 3:
            pass
        time.sleep(0.1)
        again = socket.create_connection(("127.0.0.1", cls.relay_port), timeout=5)
        again.sendall(b"back")
        cls.echo_again = again.recv(100)
        driver.close()

    def test_registration_and_errors_are_answered_as_wss_does(self):
        self.assertEqual(self.init, ["INITREPLY {Status OK}"] * 2)
        e = self.errors
        self.assertEqual(e["before init"], "ERROR {Reason Must.Use.INIT.Method.First}")
        self.assertEqual(e["bad ports"], "ERROR {Reason Ports.List.Must.Be.Integer}")
        self.assertEqual(e["no name"], "ERROR {Reason Robot.Name.Must.Not.Be.Empty}")
        self.assertEqual(e["not in world"], "ERROR {Reason Robot.Not.In.Simulation}")
        self.assertEqual(e["taken"], "ERROR {Reason Robot.Alread.Exists}")
        self.assertEqual(e["self"], "SS {Robot r1} {Strength INF} {Error SS.To.Self}")
        self.assertEqual(e["unknown"], "SS {Robot nobody} {Strength NaN} {Error Robot.Does.Not.Exist}")
        self.assertAlmostEqual(float(field(e["unregistered"], "Strength")), model_dbm(8), delta=0.5,
                               msg="a robot of the world answers whether or not it registered: " + e["unregistered"])
        self.assertEqual(e["dns unregistered"],
                         "DNSREPLY {Robot r2} {Port -1} {Error NoSuchRobot} {Why Not.Registered.With.WSS}")
        self.assertEqual(e["dns unknown"], "DNSREPLY {Robot nobody} {Port -1} {Error NoSuchRobot}")
        self.assertEqual(e["dns self"], "DNSREPLY {Robot r1} {Port -1} {Error NoSuchRobot}")
        self.assertEqual(e["dns port"], "DNSREPLY {Robot r2} {Port -1} {Error RobotDoesNotListenOnThisPort}")
        self.assertEqual(e["second init"], "ERROR {Reason Method.Unknown.Or.Can.INIT.only.once}")
        self.assertEqual(e["reverse unknown"], "REVERSEDNSREPLY {Port 1} {Error UnknownOrIllegalPort}")

    def test_a_relayed_connection_reaches_the_robot_and_says_who_calls(self):
        self.assertEqual(self.echo, b"hello r2")
        self.assertEqual(field(self.dns_again, "Port"), str(self.relay_port), "the same pair gets the same port")
        self.assertEqual(self.reverse, f"REVERSEDNSREPLY {{Port {self.r2_peers[0]}}} {{Robot r1}}")

    def test_signal_strength_falls_with_distance_as_the_radio_model_says(self):
        xs = [x for x, _ in self.samples]
        self.assertGreater(max(xs) - min(xs), 5)
        for x, dbm in self.samples:
            self.assertAlmostEqual(dbm, model_dbm(x), delta=0.5)  # positions move between the two reads
        strengths = [s for _, s in self.samples]
        self.assertLess(strengths[-1], strengths[0] - 5)

    def test_a_wall_lowers_the_signal_strength_by_its_loss(self):
        self.assertAlmostEqual(self.walled["beside"], model_dbm(5), delta=0.05)
        self.assertAlmostEqual(self.walled["behind"], self.walled["beside"] - WALL_LOSS, delta=0.01)

    def test_the_connection_is_cut_out_of_range_and_the_relay_comes_back(self):
        self.assertIsNotNone(self.cut_at, "the relayed connection should end when the link does")
        self.assertLess(abs(self.cut_at - RANGE), 0.5, f"cut at {self.cut_at:.2f} m, range {RANGE:.2f} m")
        self.assertTrue(self.relay_closed, "the relay port stops listening while the link is down")
        self.assertEqual(self.echo_again, b"back")


class WssUnderLoad(unittest.TestCase):
    """The WSS endpoint is a line server like the robot server: connections over a cap full of
    registered robots are told why and closed, a client that floods (without line ends, or with
    lines it never reads the answers to) does not stall the others, and a well-behaved client is
    answered throughout."""

    def test_cap_and_flooders(self):
        with tempfile.TemporaryDirectory() as tmp:
            port_file = os.path.join(tmp, "wss-port")
            server, _, _ = serve(SANET, SCENARIO.replace("duration: 25", "duration: 20"), tmp, "--wss-port", "0",
                                 "--wss-port-file", port_file, "--wss-max-clients", "3")
            try:
                with open(port_file) as f:
                    port = int(f.read())
                self.check_under_load(port)
            finally:
                server.kill()
                server.wait()

    def check_under_load(self, port):
        w1 = Wss(port)
        self.assertEqual(w1.ask("INIT {Robot r1} {Port 4999}"), "INITREPLY {Status OK}")
        # A flood without line ends ends its own connection (a line is at most 4096 bytes).
        endless = socket.create_connection(("127.0.0.1", port), timeout=5)
        try:
            for _ in range(64):
                endless.sendall(b"x" * 1024)
        except ConnectionError:
            pass
        self.assertIn(read_to_end(endless), (b"", None), "the flooder's connection is closed")
        self.assertTrue(w1.ask("GETSS {Robot r2}").startswith("SS {Robot r2}"))
        # Two more robots register and fill the cap of three. Past their handshake time a newcomer
        # would take the slot of one that never registered; registered ones keep theirs, so the
        # fourth is told why and closed.
        w2, w3 = Wss(port), Wss(port)
        self.assertEqual(w2.ask("INIT {Robot r2} {Port 5000}"), "INITREPLY {Status OK}")
        self.assertEqual(w3.ask("INIT {Robot behind} {Port 5001}"), "INITREPLY {Status OK}")
        time.sleep(HANDSHAKE_TIME + 0.5)
        refused = socket.create_connection(("127.0.0.1", port), timeout=5)
        self.assertEqual(read_to_end(refused), b"ERROR {Reason Too.Many.Connections: connection refused: the server "
                                               b"already has 3 connections (its cap, --wss-max-clients 3)}\r\n")
        for w, other in ((w1, "r2"), (w2, "r1"), (w3, "r1")):
            self.assertTrue(w.ask(f"GETSS {{Robot {other}}}").startswith(f"SS {{Robot {other}}}"), "it stays")
        w3.sock.close()
        time.sleep(0.1)
        # A client that sends lines and never reads the answers, while w1 asks and is answered.
        flooder = socket.create_connection(("127.0.0.1", port), timeout=5)
        flooder.sendall(b"INIT {Robot r2x} {Port 1}\r\n")
        stop = threading.Event()

        def flood():
            try:
                while not stop.is_set():
                    flooder.sendall(b"GETSS {Robot r1}\r\n" * 256)
            except OSError:
                pass  # the server dropped it: it never read its answers
        thread = threading.Thread(target=flood, daemon=True)
        thread.start()
        answers = [w1.ask("GETSS {Robot r2}") for _ in range(200)]
        stop.set()
        thread.join(timeout=10)
        self.assertTrue(all(a.startswith("SS {Robot r2} {Strength ") for a in answers), answers[:3])
        self.assertEqual(w2.ask("GETSS {Robot r1}")[:13], "SS {Robot r1}")


def read_to_end(sock):
    """What the server sent before it closed the connection (None if it reset it)."""
    data = b""
    try:
        while chunk := sock.recv(4096):
            data += chunk
    except ConnectionResetError:
        return None if not data else data
    return data


if __name__ == "__main__":
    warnings.simplefilter("ignore", ResourceWarning)  # relayed sockets are left to the server to cut
    unittest.main(verbosity=2, warnings="ignore")
