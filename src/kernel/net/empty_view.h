// The network view of a transport without routing tables: nothing to read, nothing to
// invalidate; `protocol` names the transport ("none" for local delivery, "udp" for agents).
#pragma once

#include <string>
#include <vector>

#include "sanet/node.h"

namespace sanet::net {

class EmptyView : public NetworkView {
 public:
  explicit EmptyView(std::string protocol) : protocol_(std::move(protocol)) {}
  std::string Protocol() const override { return protocol_; }
  std::vector<RouteEntry> RoutingTable() const override { return {}; }
  std::vector<NodeId> Neighbours() const override { return {}; }
  bool InvalidateRoute(NodeId) override { return false; }
  void RequestRoute(NodeId) override {}

 private:
  std::string protocol_;
};

}  // namespace sanet::net
