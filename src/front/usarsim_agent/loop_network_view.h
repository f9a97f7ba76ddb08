// An agent's NetworkView: what the robot's network knows, fetched when the controller asks.
// Where a tap joins the robot's programs to the simulated radio, that is its ns-3 node's routing
// table and neighbours, asked of the server (GETNET, answered from the world between two steps)
// and changed through it (INVALIDATEROUTE, REQUESTROUTE). Otherwise its traffic to other robots
// crosses real networks, and the view is this host's kernel's (kernel_tables.h), "kernel".
// The server says which on the first ask. One answer serves every call within a control step
// (and, outside steps, within kFresh s); an invalidation makes the next call ask again.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "sanet/node.h"
#include "sim/run_spec.h"
#include "usarsim_agent/kernel_tables.h"
#include "usarsim_agent/server_link.h"

namespace sanet::usarsim_agent {

class LoopNetworkView : public NetworkView {
 public:
  static constexpr double kFresh = 0.02;  // s: the server's rate limit, one answer per period
  static constexpr double kWait = 1.0;    // s of wall-clock time for the server's answer

  struct Hooks {
    std::function<double()> now;                                      // the node's Now()
    std::function<std::vector<std::optional<Ipv4>>()> addresses;      // where each node's agent listens
    std::function<void(const std::string&)> log;                      // the node's log
    std::function<std::optional<NodeId>(const std::string&)> lookup;  // the node's Lookup
  };
  // Without a server (`link` null: a robot driven over ROS 2), the view is the kernel's.
  LoopNetworkView(const sim::RunSpec& spec, NodeId self, ServerLink* link, Hooks hooks);

  std::string Protocol() const override;
  std::vector<RouteEntry> RoutingTable() const override;
  std::vector<NodeId> Neighbours() const override;
  bool InvalidateRoute(NodeId destination) override;
  void RequestRoute(NodeId destination) override;

 private:
  enum class Source { kUnknown, kSimulated, kKernel };
  struct Snapshot {
    std::string protocol;
    std::vector<RouteEntry> routes;
    std::vector<NodeId> neighbours;
  };
  const Snapshot& Current() const;
  void Fetch() const;
  void FetchFromKernel() const;
  void TakeNetLine(const wire::ProtocolMessage& line) const;
  std::optional<RouteEntry> ParseRoute(const std::string& text) const;

  const sim::RunSpec& spec_;
  NodeId self_;
  ServerLink* link_;
  Hooks hooks_;
  mutable Source source_;
  mutable Snapshot snapshot_{"none", {}, {}};  // until the server's first answer
  mutable std::optional<double> fetched_at_;   // the node's Now() at the last fetch
  mutable bool said_no_answer_ = false;        // a failed fetch is logged once
};

}  // namespace sanet::usarsim_agent
