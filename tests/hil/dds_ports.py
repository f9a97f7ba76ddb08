"""What tests of DDS over sanet's networks need to tell DDS traffic apart. Every RTPS message
(DDS's wire) starts with "RTPS", its version, its vendor and the sending participant's 12-byte
GUID prefix, so a UDP payload says which participant sent it; a participant belongs to one
domain, whose discovery uses the ports 7400 + 250 d (multicast) and 7410 + 250 d + 2 i (unicast,
with participant indexes; Cyclone's default uses other, free ports for everything else)."""
import collections
import socket
import struct
import threading


def domain_of(port):
    """The DDS domain whose discovery port range holds `port`, or None."""
    return (port - 7400) // 250 if 7400 <= port < 7400 + 250 * 233 else None


def datagram(ip):
    """(source address, source port, destination port, payload) of an IPv4 packet's UDP
    datagram, or None."""
    if len(ip) < 28 or ip[0] >> 4 != 4 or ip[9] != 17:
        return None
    ihl = (ip[0] & 15) * 4
    sport, dport = struct.unpack("!HH", ip[ihl:ihl + 4])
    return socket.inet_ntoa(ip[12:16]), sport, dport, ip[ihl + 8:]


def rtps_sender(payload):
    """The GUID prefix of the participant that sent an RTPS message, or None for other payloads."""
    return payload[8:20] if len(payload) >= 20 and payload[:4] == b"RTPS" else None


class BridgeSniffer(threading.Thread):
    """Counts the frames on a bridge and the RTPS messages among them by sending participant
    (GUID prefix) and by source address."""

    def __init__(self, bridge):
        super().__init__(daemon=True)
        self.sock = socket.socket(socket.AF_PACKET, socket.SOCK_RAW, socket.htons(3))
        self.sock.bind((bridge, 0))
        self.sock.settimeout(0.2)
        self.frames, self.stop = 0, False
        self.senders = collections.Counter()  # GUID prefix -> RTPS messages
        self.addresses = collections.defaultdict(set)  # source address -> GUID prefixes

    @property
    def dds(self):
        return sum(self.senders.values())

    def run(self):
        while not self.stop:
            try:
                frame = self.sock.recv(65536)
            except socket.timeout:
                continue
            except OSError:  # the bridge is gone: the run has ended
                return
            self.frames += 1
            udp = datagram(frame[14:]) if frame[12:14] == b"\x08\x00" else None
            sender = rtps_sender(udp[3]) if udp else None
            if sender:
                self.senders[sender] += 1
                self.addresses[udp[0]].add(sender)

    def finish(self):
        self.stop = True
        self.join()
        self.sock.close()


SNAP_IPV4 = b"\xaa\xaa\x03\x00\x00\x00\x08\x00"  # 802.2 LLC/SNAP header before an IPv4 packet


def pcap_datagrams(path):
    """[(time, source address, source port, destination port, RTPS sender or None)] of the UDP
    datagrams in an 802.11 pcap file (its times are simulated time)."""
    with open(path, "rb") as f:
        data = f.read()
    assert data[:4] == b"\xd4\xc3\xb2\xa1", f"{path}: not a little-endian pcap file"
    found, at = [], 24
    while at + 16 <= len(data):
        seconds, micros, length, _ = struct.unpack("<IIII", data[at:at + 16])
        frame = data[at + 16:at + 16 + length]
        at += 16 + length
        snap = frame.find(SNAP_IPV4)
        udp = datagram(frame[snap + len(SNAP_IPV4):]) if snap >= 0 else None
        if udp:
            found.append((seconds + micros * 1e-6, *udp[:3], rtps_sender(udp[3])))
    return found
