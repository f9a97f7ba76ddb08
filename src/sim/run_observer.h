// Typed streams of what happens in a run, for front ends and sinks beside the run's own outputs
// (a live view, a log in another format, a script): the world after every physics step, radio
// frames, messages delivered or lost, routing-table changes, controllers' state transitions,
// metrics and log lines. Calls come on the simulation thread, in the run's order, stamped with
// simulated time, each after the run's outputs have recorded the same event, so an observer sees
// what the results hold. Override what you need. Frames and route changes cost something to
// watch: a run watches them when its trace does or an observer asks (Wants).
#pragma once

#include <optional>
#include <string>

#include "net/network_traces.h"
#include "sanet/message.h"
#include "sim/snapshot.h"

namespace sanet::sim {

// A node's route to `destination` appeared, changed or went away (next_hop empty). Routing
// tables are compared at every trajectory sample (ns-3's routing protocols trace no changes).
struct RouteChange {
  double time = 0;  // s
  NodeId node = 0, destination = 0;
  std::optional<NodeId> next_hop;
  int hops = 0;
};

class RunObserver {
 public:
  virtual ~RunObserver() = default;

  struct Streams {
    bool frames = false;  // every frame each radio sends and receives (runs with ns-3's network)
    bool routes = false;  // route changes
  };
  virtual Streams Wants() const { return {}; }

  // After every physics step (or, in a world without moving bodies, every trajectory sample).
  virtual void AfterStep(const WorldSnapshot&) {}
  virtual void Frame(const net::FrameEvent&) {}
  // A message reached `to`'s controller (or the front end driving `to`): time_received is now.
  virtual void Delivered(NodeId /*to*/, const Message&) {}
  // A message reached `to`'s radio but not its controller (`why`, e.g. no client drives it).
  virtual void Lost(NodeId /*to*/, const Message&, const std::string& /*why*/) {}
  virtual void RouteChanged(const RouteChange&) {}
  virtual void Transition(double /*t*/, NodeId /*node*/, const std::string& /*from*/, const std::string& /*to*/,
                          const std::string& /*why*/) {}
  virtual void Metric(double /*t*/, NodeId /*node*/, const std::string& /*name*/, double /*value*/) {}
  virtual void Log(double /*t*/, NodeId /*node*/, const std::string& /*text*/) {}
};

}  // namespace sanet::sim
