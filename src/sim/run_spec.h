// The immutable description of one run, as the scenario loader produces it and tests and
// benchmarks build it directly. Units are SI. Defaults match the scenario format's, except
// that a scenario must give its duration and is named after its file by default.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "agents/controller_spec.h"
#include "net/network_spec.h"
#include "physics/physics_world.h"
#include "robots/node_model.h"

namespace sanet::sim {

using ControllerSpec = agents::ControllerSpec;

struct NodeSpec {
  std::string name;
  robots::ModelSpec model;
  Pose2D pose;
  std::optional<ControllerSpec> controller;
  net::NodeRadio radio;  // overrides of the network's radio settings
};

// A robot with a controller: `sanet launch` runs it as an agent process, which talks to the
// other agents over UDP and to the server's nodes through the server.
inline bool RunsAsAgent(const NodeSpec& n) {
  return n.model.kind != robots::ModelKind::kMote && n.controller.has_value();
}

struct Obstacle {
  std::string kind;  // "box" or "wall", for plots
  physics::StaticBox box;
};

// Something that happens to a node at a given time.
struct NodeEvent {
  enum class Action { kSwitchOff };  // the node stops: controller, radio and motors
  double time = 0;                   // s
  std::uint32_t node = 0;
  Action action = Action::kSwitchOff;
};

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

// How `sanet launch` connects the agents.
struct LoopSpec {
  LoopNetwork network = LoopNetwork::kHost;
  bool namespaces = false;  // each agent in its own network namespace (always with kSimulated)
  LinkShaping shaping;
  std::uint16_t udp_port = 47000;  // loopback: node i uses port + i; namespaces: every node this port
  std::vector<PeerLink> peers;     // agents on computers of their own (`sanet agent`)
};

// A robot class that clients of the server may add with INIT (a USARSim class name, e.g.
// USARBot.P2DX) and the robot it becomes here.
struct SpawnClass {
  std::string usarsim_class;  // matched without regard to case, as Unreal's class names are
  robots::ModelSpec model;
  net::NodeRadio radio;
};

// Which robots clients may add to a running world, how many, and where.
struct SpawnSpec {
  std::vector<SpawnClass> classes;
  std::size_t max = 8;  // robots added over the whole run
  // Where they may stand: min and max corners (the scenario loader's default is the field of
  // `world_size` around the scenario's nodes and obstacles, sim::DefaultSpawnRegion).
  std::pair<Vec2, Vec2> region{{-1e6, -1e6}, {1e6, 1e6}};
};

struct RunSpec {
  std::string name = "run";
  std::uint64_t seed = 1;
  double duration = 60;         // s of simulated time
  double physics_step = 0.005;  // s
  Vec2 world_size{100, 100};    // m, extent of the field around the origin-based area (for plots)
  physics::WorldSettings physics;
  // 2: the physics step runs on a second thread while ns-3 processes the network events of the
  // same step (same results as 1).
  int threads = 1;
  std::vector<Obstacle> obstacles;
  std::vector<NodeSpec> nodes;
  // The wireless network; without one, messages are delivered locally after message_latency.
  std::optional<net::NetworkSpec> network;
  double message_latency = 0.001;    // s, of the local transport
  double message_loss = 0;           // probability that a controller never gets a message
  double message_delay = 0;          // s added before a controller gets a message
  double trajectory_interval = 0.1;  // s between trajectory samples
  std::vector<NodeEvent> events;
  // Robots are driven by clients of the simulation server: their scenario controllers do not run
  // here (motes' controllers still do).
  bool robots_remote = false;
  // Each controller runs in a child process of its own (agents/isolated_controller.h): a crash
  // in a plugin ends the run with its results instead of the process. Results are the same.
  bool isolate_controllers = false;
  LoopSpec loop;
  std::optional<SpawnSpec> spawn;  // clients may add robots with INIT (server only)
  // The run ends early when, over all nodes, `end_count` of these have happened: a controller logs
  // one of the lines, a node enters one of the states, a node reports one of the metrics.
  std::vector<std::string> end_when_logged, end_when_transition, end_when_metric;
  int end_count = 1;
  bool HasEndCondition() const {
    return !end_when_logged.empty() || !end_when_transition.empty() || !end_when_metric.empty();
  }
  double end_grace = 0;           // s the run goes on after the end condition, for messages in flight
  bool figures = false;           // draw map.svg and packets.svg (and min_distance.svg)
  bool trace = false;             // write trace.sqlite (trace/run_trace.h)
  bool min_distance = false;      // record the smallest distance between robots over time
  double distance_reference = 0;  // m; the summary says how long the smallest distance stayed within 10 % of it
  double figure_tick = 50;        // s between time marks on trajectories
};

}  // namespace sanet::sim
