// The scenario's `loop` section: how `sanet launch` and `sanet agent` connect the agents that
// run robots' controllers as processes of their own. A front-end section: the scenario layer
// reads it, the launcher and the agent use it, and the simulation never sees it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace sanet::sections {

// netem settings for the real links of a communication-in-the-loop launch.
struct LinkShaping {
  double delay = 0;   // s
  double jitter = 0;  // s
  double loss = 0;    // probability
  double rate = 0;    // bit/s, 0 for no limit
};

// What carries the agents' own traffic to each other in `sanet launch`.
enum class LoopNetwork {
  kHost,       // the host's links: loopback, or veth pairs and a bridge between namespaces
  kSimulated,  // the scenario's simulated radio (ns-3), through a tap in each agent's namespace
};

// Where a robot's agent listens for the other agents on the robot-to-robot segment (a radio of
// its computer's own): an address, or a network interface whose address it takes and to which
// its peer socket is bound, so that robot-to-robot datagrams leave through it alone.
struct PeerLink {
  std::string robot;
  std::string address;    // IPv4; empty: the interface's, or the default rule's
  std::string interface;  // e.g. wlan0; empty: the route decides
};

struct LoopSpec {
  LoopNetwork network = LoopNetwork::kHost;
  bool namespaces = false;  // each agent in its own network namespace (always with kSimulated)
  LinkShaping shaping;
  std::uint16_t udp_port = 47000;  // loopback: node i uses port + i; namespaces: every node this port
  std::vector<PeerLink> peers;     // agents on computers of their own (`sanet agent`)
};

}  // namespace sanet::sections
