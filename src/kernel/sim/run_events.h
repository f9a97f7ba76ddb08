// Everything that happens in a run, as one typed event stream (core/event_bus.h): each event is
// published once, by the part where it happens, stamped with simulated time, on the simulation
// thread and in the run's order. The results (CSV files, summary, trace.sqlite), trace.mcap, live
// streams and scripts subscribe to the kinds they want (docs/architecture.md draws the flow).
//
// Stages order the subscribers of one event: the run's records first, then observers (so that an
// observer sees what the results hold), then the clock (end conditions, a failure's stop).
//
// Events refer to what their publisher holds (texts, messages, readings): a subscriber copies
// what it keeps. Adding a kind: a struct here, in RunBus's list, a Publish where it happens, and
// the subscribers that care.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/event_bus.h"
#include "net/network_traces.h"
#include "sanet/message.h"
#include "sanet/readings.h"
#include "sim/snapshot.h"

namespace sanet::sim {

enum class RunStage { kRecord, kObserve, kControl };

// A line of a node's log (its controller's, a front end's, the run's own).
struct LogLine {
  double t;  // s, simulated
  NodeId node;
  const std::string& text;
};

// A controller changed its state.
struct Transitioned {
  double t;
  NodeId node;
  const std::string &from, &to, &why;
};

struct MetricReported {
  double t;
  NodeId node;
  const std::string& name;
  double value;
};

// A message reached `to`'s controller (or the front end driving `to`): its time_received is now.
struct MessageDelivered {
  NodeId to;
  const Message& message;
};

// A message the scenario's impairments (message_loss) dropped before `to`'s controller.
struct MessageDropped {
  NodeId to;
  const Message& message;
};

// A message reached `to`'s radio but not its controller (`why`: e.g. no client drives it). The
// run logs why in `to`'s log just after.
struct MessageLost {
  double t;
  NodeId to;
  const Message& message;
  const std::string& why;
};

// A controller failed: the run ends at once, keeping what it recorded.
struct ControllerFailed {
  const std::string& why;
};

// A robot joined the running world (a front end spawned it, as the class it names).
struct NodeSpawned {
  double t;
  NodeId node;
  const std::string& spawned_as;
  Pose2D pose;
};

// The node stopped for good (a scenario's switch-off event, or a script's).
struct SwitchedOff {
  double t;
  NodeId node;
};

// A node's battery fell to its cutoff: it stopped as a switched-off node does (docs/energy.md).
struct Died {
  double t;
  NodeId node;
};

// A dead node's battery was recharged above its revive level: it goes on.
struct Revived {
  double t;
  NodeId node;
};

// Every battery at a sample (RunSpec::energy_interval, and the run's end): for energy.csv and
// the ROS 2 presentation's BatteryState.
struct EnergyLevel {
  NodeId node;
  BatteryReading battery;
};
struct EnergySampled {
  double t;
  const std::vector<EnergyLevel>& levels;
};

// What a node's driver read from its sensor `instance` of `kind`, with where its body truly is.
struct SensorRead {
  double t;
  NodeId node;
  const std::string &instance, &kind;
  const SensorReading& reading;
  BodyState body;
};

// A row of trajectories.csv: a body's true pose at a trajectory sample (after it moved).
struct PoseRow {
  double t;
  NodeId node;
  Pose2D pose;
  Twist2D velocity;                      // world frame
  std::array<double, 3> wheel_angles{};  // rad, as BodyState's
};

// A node's route to `destination` appeared, changed or went away (next_hop empty). Routing
// tables are compared at every trajectory sample (ns-3's routing protocols trace no changes), and
// only while someone hears this kind.
struct RouteChange {
  double time = 0;  // s
  NodeId node = 0, destination = 0;
  std::optional<NodeId> next_hop;
  int hops = 0;
};

// A message of the physics engine (sim/run_warnings.h), with the bodies in contact it names.
struct EngineWarning {
  double t;
  const std::string &kind, &text;
  const std::vector<std::string>& contacts;
};

// The world after a physics step (or, in a world without moving bodies, a trajectory sample).
struct StepEnded {
  const WorldSnapshot& world;
};

// The run is over (its duration, an end condition, a failure or a stop): its last rows are
// recorded; whoever holds events back (the ROS 2 presentation's radio window) sends them now.
struct RunEnded {
  double t;
};

// Radio frames (net::FrameEvent) cost something to hear: the network traces them only while
// someone hears them.
using RunBus = EventBus<RunStage, LogLine, Transitioned, MetricReported, MessageDelivered, MessageDropped, MessageLost,
                        ControllerFailed, NodeSpawned, SwitchedOff, Died, Revived, EnergySampled, SensorRead, PoseRow,
                        net::FrameEvent, RouteChange, EngineWarning, StepEnded, RunEnded>;

}  // namespace sanet::sim
