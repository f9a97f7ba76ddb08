// The scenario format's fields, section by section, declared once (scenario/fields.h). The
// loader reads through these, `sanet validate --print` prints through them, and `sanet list`
// and the tables of docs/scenario.md are made from them.
#pragma once

#include <string>
#include <vector>

#include "scenario/fields.h"
#include "scenario/scatter.h"
#include "scenario/scenario_loader.h"

namespace sanet::scenario {

// The farthest a node may stand from the origin, and the largest world side (m): beyond, the
// physics engines lose the precision they need (ODE asserts on some).
constexpr double kFarthest = 1e6;

const Fields<sim::RunSpec>& WorldFields();
const Fields<sim::Charger>& ChargerFields();  // an item of world.chargers
const Fields<net::NetworkSpec>& NetworkFields();
const Fields<net::NetworkSpec>& PropagationFields();
const Fields<net::NetworkSpec>& ChannelFields();
const Fields<sim::RunSpec>& MessagesFields();
const Fields<sections::LoopSpec>& LoopFields();
const Fields<sections::LinkShaping>& NetemFields();
const Fields<sim::RunSpec>& EndFields();
// `spawn:` (max, region; its classes are read by the loader, each as a SpawnClassFields item).
const Fields<sections::SpawnSpec>& SpawnFields();
// `ros2:` (domain, rate, cmd_vel, robots: each a Ros2RobotFields item).
const Fields<sections::Ros2Spec>& Ros2Fields();
const Fields<sections::Ros2Robot>& Ros2RobotFields();
const Fields<Scenario>& OutputsFields();
// A model's `body` keys (with its drive limits for robots): each model's folder defines its own,
// src/models/<model>/<model>_fields.cc.
const Fields<robots::ModelSpec>& BodyFields(robots::ModelKind kind);
#define SANET_DECLARE_BODY_FIELDS(name, Name, kind) const Fields<robots::ModelSpec>& Name##BodyFields();
SANET_ROBOT_MODELS(SANET_DECLARE_BODY_FIELDS)
#undef SANET_DECLARE_BODY_FIELDS
// The keys every robot's body has: its drive limits.
// A radio material's name (net/materials.h), or an error listing them.
net::Material ReadMaterial(const Field& v);
void DriveLimits(Fields<robots::ModelSpec>& fields, const char* speed_meaning, const char* turn_meaning);
// A colour's text, "#rrggbb", or an error saying so.
Rgb ReadColor(const Field& v);
// `color: "#rrggbb"`: what cameras see of the body, printed only where it is given.
void BodyColor(Fields<robots::ModelSpec>& fields);
// `body_inertia: [ixx, iyy, izz]`, printed only where it is given (or a URDF gives it).
void BodyInertia(Fields<robots::ModelSpec>& fields, std::function<std::array<double, 3>&(robots::ModelSpec&)> at);
const Fields<net::NodeRadio>& RadioFields();
const Fields<sim::ControllerSpec>& ControllerFields();

// Obstacles, grids, events: read into these, then into the run.
struct ObstacleRadio {  // what an obstacle costs a radio frame, as sim::Obstacle keeps it
  std::optional<net::Material> material;
  std::optional<double> loss_db;
  double loss_db_per_m = 0;
};
struct BoxSettings {
  Vec2 center;
  std::vector<double> size;  // length, width, height
  double yaw = 0;
  ObstacleRadio radio;
  bool indoor = false;
  std::optional<Rgb> color;
};
struct WallSettings {
  Vec2 from, to;
  double height = 1.0, thickness = 0.2;
  ObstacleRadio radio;
  bool indoor = false;
  std::optional<Rgb> color;
};
struct GridSettings {
  std::string name;
  int rows = 0, cols = 0;
  Vec2 origin{0, 0}, spacing{1, 1};
  double heading = 0;
};
struct EventSettings {
  double time = 0;
  std::string node;
  sim::NodeEvent::Action action = sim::NodeEvent::Action::kSwitchOff;
  std::optional<double> energy_j;  // recharge: J added; unset: to full
};
const Fields<BoxSettings>& BoxFields();
const Fields<WallSettings>& WallFields();
const Fields<GridSettings>& GridFields();
// A scatter item's `scatter` (scenario/scatter.h); ReadScatter checks what no single key can.
const Fields<ScatterSettings>& ScatterFields();
ScatterSettings ReadScatter(const Field& f);
const Fields<EventSettings>& EventFields();
// The top level: name, seed and duration are read here; the sections by their own code, in the
// order declared (network before nodes, nodes before events).
const Fields<Scenario>& TopLevelFields();
// Keys whose values other code reads (a node's): declared for the key list and the docs.
struct Keys {};
const Fields<Keys>& NodeFields();
const Fields<Keys>& GridItemFields();
const Fields<Keys>& ScatterItemFields();
const Fields<Keys>& SpawnClassFields();

// Names keep to letters, digits, '_', '-' and '.': they end up in CSV files and folder names.
std::string ReadName(const Field& f);

// Every declared table with its name ("network", "body.omni3", ...) and defaults, in the order
// of docs/scenario.md.
struct SectionTable {
  std::string name;
  std::vector<FieldInfo> fields;
};
std::vector<SectionTable> SectionTables();

}  // namespace sanet::scenario
