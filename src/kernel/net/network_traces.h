// What a simulated network did during a run, handed to the outputs: per-node packet counts and
// route discoveries, with the settings that describe the network in the summary.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "sanet/message.h"

namespace sanet::net {

struct PacketCounts {
  std::uint64_t sent = 0, received = 0, forwarded = 0, dropped = 0;
  std::uint64_t messages_sent = 0, messages_received = 0;
};

struct Discovery {
  NodeId node, destination;
  double started;
  std::optional<double> established;
};

// What crossed one node's tap (a real IP stack joined to the node), counted at the taps.
struct TapCounts {
  std::uint64_t packets_sent = 0, bytes_sent = 0;          // from the real stack into the simulated network
  std::uint64_t unicast_sent = 0;                          // of those, to another node's tap (not to motes)
  std::uint64_t unicast_arrived = 0;                       // of those, delivered out of the addressee's tap
  std::uint64_t packets_received = 0, bytes_received = 0;  // out of this tap, to the real stack
  std::vector<double> delays;                              // s, from tap to tap, of the packets received here
};
// Every tap's counts, by node id.
using TapLedger = std::map<NodeId, TapCounts>;

// One radio frame a node's PHY sent or received.
struct FrameEvent {
  double t = 0;  // s
  NodeId node = 0;
  bool sent = false;
  std::optional<NodeId> peer;  // to (sent) or from (received); empty for broadcasts and unknown senders
  const char* kind = "";       // data, routing, arp, broadcast, ack, control, management
  std::uint32_t bytes = 0;     // the MPDU, MAC header included
};
using FrameObserver = std::function<void(const FrameEvent&)>;

// What the channel did: how many radios each frame was handed to.
struct ChannelCounts {
  std::string model;                                          // as in the scenario
  std::string calibration;                                    // the abstract radio's: measured or cached
  std::optional<double> floor_dbm;                            // indexed only, as are the counts
  std::uint64_t frames_sent = 0, frames_received = 0;         // by the PHYs; received: whole and decoded
  std::uint64_t candidates = 0, handed = 0;                   // radios the grid offered, receptions scheduled
  std::size_t walls = 0;                                      // obstacles that cost the radio something
  std::uint64_t wall_losses = 0, wall_walks = 0;              // pair losses asked for; computed through the grid
  bool shadowing = false;                                     // with shadowing on:
  std::uint64_t shadowing_asked = 0, shadowing_computed = 0;  // links' values asked for; computed afresh
};

struct NetworkTraces {
  std::string radio, routing;  // names as in the scenario
  double data_rate_mbps = 0, tx_power_dbm = 0;
  std::vector<PacketCounts> counts;  // per node
  std::vector<Discovery> discoveries;
  bool packet_logs = false;  // packets/<node>.csv were written through the results folder
  TapLedger taps;            // nodes joined to real IP stacks
  ChannelCounts channel;
};

}  // namespace sanet::net
