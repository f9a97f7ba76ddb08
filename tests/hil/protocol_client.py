"""What the in-the-loop tests share: a robot-protocol client written from docs/protocol.md
(standard library only) and a `sanet serve` started on a free port."""
import os
import re
import socket
import subprocess
import time


class Client:
    """One connection: `TYPE {Key Value} ...` lines, CR LF. Reads the server's greeting."""

    def __init__(self, port):
        self.sock = socket.create_connection(("127.0.0.1", port), timeout=5)
        self.file = self.sock.makefile("rwb")
        assert self.file.readline().startswith(b"NFO")

    def send(self, line):
        self.file.write(line.encode() + b"\r\n")
        self.file.flush()

    def lines(self):
        """Every line until the server closes the connection."""
        while True:
            line = self.file.readline().decode().strip()
            if not line:
                return
            yield line

    def next(self, prefix):
        """The next line that starts with `prefix`, or an ERR line, whichever comes first."""
        for line in self.lines():
            if line.startswith(prefix) or line.startswith("ERR"):
                return line
        raise EOFError("connection closed while waiting for " + prefix)

    def sensor(self, kind):
        """The next SEN line of sensor type `kind`; an ERR line fails."""
        while True:
            line = self.next("SEN")
            if line.startswith("ERR"):
                raise AssertionError(line)
            if field(line, "Type") == kind:
                return line

    def close(self):
        self.sock.close()


class Wss:
    """A WSS control connection."""

    def __init__(self, port):
        self.sock = socket.create_connection(("127.0.0.1", port), timeout=5)
        self.file = self.sock.makefile("rwb")

    def ask(self, line):
        self.file.write(line.encode() + b"\r\n")
        self.file.flush()
        return self.file.readline().decode().strip()


def field(line, key):
    m = re.search(r"\{" + key + r" ([^}]*)\}", line)
    return m.group(1) if m else None


def serve(sanet, scenario_text, folder, *extra):
    """Starts `sanet serve` on the scenario in `folder` (with `extra` options); returns (process,
    port, results folder) once it listens."""
    path = os.path.join(folder, "scenario.yaml")
    with open(path, "w") as f:
        f.write(scenario_text)
    port_file = os.path.join(folder, "port")
    out = os.path.join(folder, "out")
    server = subprocess.Popen([sanet, "serve", path, "--port", "0", "--port-file", port_file, "-o", out, "-q", *extra],
                              stdout=subprocess.DEVNULL)
    for _ in range(1000):
        if os.path.exists(port_file):
            break
        time.sleep(0.01)
    with open(port_file) as f:
        return server, int(f.read()), out
