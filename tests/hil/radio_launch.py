"""What the tests of programs over the simulated radio share: whether this machine permits it,
and a `sanet launch --exec` run whose bridge is watched from before its programs start."""
import os
import re
import signal
import subprocess

from dds_ports import BridgeSniffer


def permitted():
    """None where the simulated radio can run here, else why not."""
    if os.geteuid() != 0:
        return "not root"
    if not os.path.exists("/dev/net/tun"):
        return "no /dev/net/tun"
    return None


def ros2_team_environment(source):
    """The environment of ROS 2 programs in the robots' namespaces: examples/ros2/cyclonedds-team.xml,
    no host-wide ROS settings."""
    env = dict(os.environ, CYCLONEDDS_URI="file://" + os.path.join(source, "examples", "ros2", "cyclonedds-team.xml"))
    env.pop("ROS_LOCALHOST_ONLY", None)
    env.pop("ROS_DOMAIN_ID", None)
    return env


class SniffedLaunch:
    """Runs `command` (a sanet launch) to its end, sniffing its bridge from the line that names it:
    .lines (all it printed), .said (the same, joined), .sniffer, .server_address, .returncode."""

    def __init__(self, command, env, timeout=200):
        launch = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env)
        self.lines, self.sniffer = [], None
        for line in launch.stdout:  # the bridge is named before the programs start
            self.lines.append(line)
            m = re.match(r"\s*bridge (\S+): the server at (\S+),", line)  # this launch's own
            if m:
                self.sniffer = BridgeSniffer(m.group(1))
                self.sniffer.start()
                self.server_address = m.group(2)
                break
        try:
            self.lines += launch.communicate(timeout=timeout)[0].splitlines(keepends=True)
        except subprocess.TimeoutExpired:
            launch.send_signal(signal.SIGINT)  # launch then ends its run and removes its namespaces
            self.lines += launch.communicate(timeout=60)[0].splitlines(keepends=True)
            raise AssertionError(f"sanet launch still ran after {timeout} s:\n" + "".join(self.lines))
        finally:
            if self.sniffer:
                self.sniffer.finish()
        self.said = "".join(self.lines)
        self.returncode = launch.returncode
        if not self.sniffer:
            raise AssertionError("sanet launch named no bridge:\n" + self.said)
