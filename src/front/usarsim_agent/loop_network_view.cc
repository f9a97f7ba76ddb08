#include "usarsim_agent/loop_network_view.h"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace sanet::usarsim_agent {

LoopNetworkView::LoopNetworkView(const sim::RunSpec& spec, NodeId self, ServerLink* link, Hooks hooks)
    : spec_(spec),
      self_(self),
      link_(link),
      hooks_(std::move(hooks)),
      source_(link ? Source::kUnknown : Source::kKernel) {}

std::string LoopNetworkView::Protocol() const { return Current().protocol; }
std::vector<RouteEntry> LoopNetworkView::RoutingTable() const { return Current().routes; }
std::vector<NodeId> LoopNetworkView::Neighbours() const { return Current().neighbours; }

const LoopNetworkView::Snapshot& LoopNetworkView::Current() const {
  const double now = hooks_.now();
  if (!fetched_at_ || std::fabs(now - *fetched_at_) >= kFresh || now < *fetched_at_) Fetch();
  return snapshot_;
}

void LoopNetworkView::Fetch() const {
  fetched_at_ = hooks_.now();
  if (source_ == Source::kKernel) return FetchFromKernel();
  const auto line = link_->Ask(wire::ProtocolMessage{"GETNET"}, "NET", kWait);
  if (line && line->type == "NET") return TakeNetLine(*line);
  if (said_no_answer_) return;  // the last snapshot stays
  said_no_answer_ = true;
  const std::string* text = line ? line->Get("Message") : nullptr;
  hooks_.log("network view: the server " +
             (text ? "refused GETNET: " + *text : "did not answer GETNET within " + std::to_string(kWait) + " s") +
             "; the view keeps its last answer (said once)");
}

void LoopNetworkView::FetchFromKernel() const {
  snapshot_ = {"kernel", {}, {}};
  try {
    const KernelTables tables = ReadKernelTables(self_, hooks_.addresses());
    snapshot_.routes = tables.routes;
    snapshot_.neighbours = tables.neighbours;
  } catch (const std::runtime_error& e) {
    if (!said_no_answer_) hooks_.log(std::string("network view: ") + e.what() + "; the kernel's tables read as empty");
    said_no_answer_ = true;
  }
}

void LoopNetworkView::TakeNetLine(const wire::ProtocolMessage& line) const {
  const std::string* source = line.Get("Source");
  if (source && *source == "Kernel") {
    source_ = Source::kKernel;
    return Fetch();
  }
  source_ = Source::kSimulated;
  Snapshot s;
  if (const std::string* protocol = line.Get("Protocol")) s.protocol = *protocol;
  for (const auto& [key, value] : line.fields) {
    if (key == "Route")
      if (const auto r = ParseRoute(value)) s.routes.push_back(*r);
    if (key == "Neighbour")
      if (const auto n = hooks_.lookup(value)) s.neighbours.push_back(*n);
  }
  snapshot_ = std::move(s);
}

// "D Next N Hops h Valid True Expires e"; a node this agent's scenario does not have (a robot
// spawned after it fetched the scenario) is left out.
std::optional<RouteEntry> LoopNetworkView::ParseRoute(const std::string& text) const {
  std::istringstream in(text);
  std::string destination, next, valid, k1, k2, k3, k4;
  RouteEntry r;
  if (!(in >> destination >> k1 >> next >> k2 >> r.hops >> k3 >> valid >> k4 >> r.expires_in) || k1 != "Next" ||
      k2 != "Hops" || k3 != "Valid" || k4 != "Expires")
    return std::nullopt;
  const auto d = hooks_.lookup(destination), n = hooks_.lookup(next);
  if (!d || !n) return std::nullopt;
  r.destination = *d;
  r.next_hop = *n;
  r.valid = valid == "True";
  return r;
}

bool LoopNetworkView::InvalidateRoute(NodeId destination) {
  if (destination >= spec_.nodes.size()) return false;
  if (source_ == Source::kUnknown) Current();
  if (source_ != Source::kSimulated) return false;  // the kernel's routes are not the controller's to drop
  wire::ProtocolMessage ask{"INVALIDATEROUTE"};
  const auto answer = link_->Ask(ask.Add("To", spec_.nodes[destination].name), "INVALIDATED", kWait);
  fetched_at_.reset();  // the next read asks again
  const std::string* done = answer ? answer->Get("Done") : nullptr;
  return done && *done == "True";
}

void LoopNetworkView::RequestRoute(NodeId destination) {
  if (destination >= spec_.nodes.size()) return;
  if (source_ == Source::kUnknown) Current();
  if (source_ != Source::kSimulated) return;  // the kernel finds its neighbours when traffic goes
  wire::ProtocolMessage ask{"REQUESTROUTE"};
  link_->Send(ask.Add("To", spec_.nodes[destination].name));
  fetched_at_.reset();
}

}  // namespace sanet::usarsim_agent
