// The description of one run, as the scenario loader produces it (with the command line's
// --seed, --duration and the like) and tests and benchmarks build it directly; a World takes it
// as it is and never changes it (robots spawned at run time live in sim/run_nodes.h). Units are
// SI. Defaults match the scenario format's, except that a scenario must give its duration and is
// named after its file by default. The scenario's sections for front ends (loop, spawn) are not
// here: sim never sees them (sections/).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "energy/energy_spec.h"
#include "hosting/controller_spec.h"
#include "net/network_spec.h"
#include "net/wall_materials.h"
#include "physics/physics_world.h"
#include "robots/node_model.h"
#include "sensors/surroundings.h"

namespace sanet::sim {

using ControllerSpec = hosting::ControllerSpec;

struct NodeSpec {
  std::string name;
  robots::ModelSpec model;
  Pose2D pose;
  std::optional<ControllerSpec> controller;
  net::NodeRadio radio;                      // overrides of the network's radio settings
  std::optional<energy::EnergySpec> energy;  // none: an infinite supply
};

// A robot with a controller: `sanet launch` runs it as an agent process, which talks to the
// other agents over UDP and to the server's nodes through the server.
inline bool RunsAsAgent(const NodeSpec& n) { return robots::HasDrive(n.model) && n.controller.has_value(); }

struct Obstacle {
  std::string kind;  // "box", "wall" or "map" (a box of world.map), for plots
  physics::StaticBox box;
  // What it costs a radio frame crossing it (net/obstacle_loss_model.h): its material's loss
  // (unset: the world's obstacle_material), or an explicit loss per crossing; plus a loss per
  // metre of the path inside it.
  std::optional<net::Material> material;
  std::optional<double> radio_loss_db;  // dB per crossing
  double radio_loss_db_per_m = 0;       // dB/m inside it
  bool from_map = false;                // one of world.map's boxes (printed with the map, not as an obstacle)
  bool indoor = false;                  // part of a building: no satellite fix within (sim/surroundings_of.h)
  std::optional<Rgb> color;             // what cameras see; unset: the default obstacles' (sim/surroundings_of.h)
};

// world.map: a ROS map's blocked cells, merged into boxes (scenario/map_field.h). The boxes are
// kept in cells so that the effective scenario carries them exactly, without the map's files.
struct WorldMap {
  std::string file;          // the map's YAML, as the scenario named it
  double wall_height = 2.5;  // m
  // m: a radio's path through a wall (a run of its boxes, whatever their number) costs the
  // material's slab loss at this thickness.
  double wall_thickness = 0.15;
  std::optional<net::Material> material;  // of its walls; unset: the world's obstacle_material
  bool unknown_blocked = false;           // unknown cells are walls too
  bool indoor = false;                    // the map is a building's: no satellite fix over it
  std::optional<Rgb> color;               // of its walls, for cameras
  double resolution = 0;                  // m per cell
  std::array<double, 3> origin{};         // x, y (m), yaw (rad) of the lower-left cell's corner
  int columns = 0, rows = 0;              // the map's size in cells
  std::vector<std::array<int, 4>> boxes;  // column, row, columns, rows of each box
};

// Something that happens to a node at a given time.
struct NodeEvent {
  enum class Action {
    kSwitchOff,  // the node stops: controller, radio and motors
    kRecharge,   // energy goes into its battery (a dead node recharged above its revive level comes back)
  };
  double time = 0;  // s
  std::uint32_t node = 0;
  Action action = Action::kSwitchOff;
  std::optional<double> energy_j;  // recharge: J added; unset: to full
};

// A charger in the world (docs/energy.md#chargers): a node with a battery whose reference point is
// within `radius` of `position` receives `power_w`.
struct Charger {
  Vec2 position;
  double radius = 0;   // m
  double power_w = 0;  // W into the battery
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
  std::vector<Obstacle> obstacles;  // world.obstacles, then world.map's boxes
  std::optional<WorldMap> map;
  net::Material obstacle_material = net::Material::kNone;  // of obstacles that name none
  std::vector<Charger> chargers;
  std::optional<sensors::GeoDatum> datum;                     // world.datum: where the world lies on the Earth
  std::vector<sensors::Region> gnss_denied;                   // world.gnss_denied: no satellite fix inside
  Rgb ground_color{110, 110, 100}, sky_color{170, 200, 235};  // what cameras see below and above
  std::vector<NodeSpec> nodes;
  // The wireless network; without one, messages are delivered locally after message_latency.
  std::optional<net::NetworkSpec> network;
  double message_latency = 0.001;    // s, of the local transport
  double message_loss = 0;           // probability that a controller never gets a message
  double message_delay = 0;          // s added before a controller gets a message
  double trajectory_interval = 0.1;  // s between trajectory samples
  double energy_interval = 10;       // s between rows of energy.csv (nodes with `energy` only)
  std::vector<NodeEvent> events;
  // Each controller runs in a child process of its own (hosting/isolated_controller.h): a crash
  // in a plugin ends the run with its results instead of the process. Results are the same.
  bool isolate_controllers = false;
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
  // Write radio_contacts.csv (sim/radio_contact_outputs.h): a contact ends after more than
  // `contact_silence` s without a frame between its pair.
  bool radio_contacts = false;
  double contact_silence = 15;  // s
};

// Who drives a run's robots: their scenario controllers, or front ends (`sanet serve`'s clients),
// in which case their controllers do not run here (motes' controllers still do). The command
// that builds the World decides; the scenario does not say.
enum class RobotDrivers { kScenarioControllers, kFrontEnds };

}  // namespace sanet::sim
