// What a simulated network did during a run, handed to the outputs: per-node packet counts and
// route discoveries, with the settings that describe the network in the summary.
#pragma once

#include <cstdint>
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

struct NetworkTraces {
  std::string radio, routing;  // names as in the scenario
  double data_rate_mbps = 0, tx_power_dbm = 0;
  std::vector<PacketCounts> counts;  // per node
  std::vector<Discovery> discoveries;
  bool packet_logs = false;  // packets/<node>.csv were written through the results folder
};

}  // namespace sanet::net
