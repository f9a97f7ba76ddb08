#include "scenario/scenario_loader.h"

#include <arpa/inet.h>
#include <net/if.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <functional>
#include <map>

#include "core/metres.h"
#include "robots/node_model.h"
#include "scenario/declarations.h"
#include "scenario/energy_fields.h"
#include "scenario/lr_wpan_fields.h"
#include "scenario/placement.h"
#include "scenario/sensor_fields.h"
#include "scenario/urdf_body.h"
#include "sensors/sensor_registry.h"
#include "sim/surroundings_of.h"
#include "sim/world.h"

namespace sanet::scenario {
namespace {

namespace fs = std::filesystem;
using robots::ModelKind;
using robots::ModelSpec;

ModelKind ReadModel(const Field& f) {
  const std::string name = f.Text();
  if (const auto kind = robots::FindModel(name)) return *kind;
  std::string known;
  for (ModelKind k : robots::AllModels()) known += std::string(known.empty() ? "" : ", ") + robots::ModelName(k);
  f.Fail("unknown model '" + name + "' (known: " + known + ")");
}

void ReadBody(const Field& f, ModelSpec& m) {
  ReadUrdfBody(f, m);  // first: the keys given beside it override what it says
  BodyFields(m.kind).Read(f, m, kUrdfBodyKeys);
  if (m.kind == ModelKind::kOmni3 && m.omni3.wheel_distance >= m.omni3.body_radius + m.omni3.wheel_radius)
    f.Fail("wheel_distance must keep the wheels under the body (less than body_radius + wheel_radius)");
}

// A row of a table that stands for nodes' starting positions (`{node: NAME}`, `{nodes: GROUP}`),
// until every node is read (ResolveNodePlaces).
constexpr const char* kNodeMark = "\x01node";
constexpr const char* kGroupMark = "\x01nodes";

bool IsNodePlace(const Field& item) { return item.IsMap() && (item.Get("node") || item.Get("nodes")); }

std::vector<std::string> NodePlaceRow(const Field& item) {
  item.ExpectKeys({"node", "nodes"});
  if (item.Get("node") && item.Get("nodes")) item.Fail("give `node: NAME` or `nodes: GROUP`, not both");
  return item.Get("node") ? std::vector<std::string>{kNodeMark, item.Require("node").Text()}
                          : std::vector<std::string>{kGroupMark, item.Require("nodes").Text()};
}

ParamValue ReadParamValue(const Field& f) {
  ParamValue v;
  v.line = f.line();
  auto scalar = [](const Field& item) {
    if (!item.IsScalar()) item.Fail("controller parameters are numbers, words or lists of them");
    return item.node().Scalar();
  };
  if (f.IsScalar()) {
    v.rows = {{f.node().Scalar()}};
  } else if (f.IsSequence()) {
    const auto items = f.Items();
    const bool table = !items.empty() && (items[0].IsSequence() || IsNodePlace(items[0]));
    v.shape = table ? ParamValue::Shape::kTable : ParamValue::Shape::kList;
    if (!table) v.rows.emplace_back();
    for (const Field& item : items) {
      if (table && IsNodePlace(item)) {
        v.rows.push_back(NodePlaceRow(item));
      } else if (table) {
        std::vector<std::string> row;
        for (const Field& cell : item.Items()) row.push_back(scalar(cell));
        v.rows.push_back(row);
      } else {
        v.rows[0].push_back(scalar(item));
      }
    }
  } else {
    f.Fail("controller parameters are numbers, words or lists of them");
  }
  return v;
}

// Fills a controller's parameters (any keys: the controller judges them later).
void ReadParams(const Field& controller, sim::ControllerSpec& c) {
  auto params = controller.Get("params");
  if (!params || params->node().IsNull()) return;
  if (!params->IsMap()) params->Fail("must be a mapping of parameter names to values");
  for (const auto& entry : params->node()) {
    const std::string key = entry.first.Scalar();
    if (c.params.Has(key))
      throw ScenarioError(controller.file(), entry.first.Mark().line + 1, params->path() + "." + key,
                          "key given twice");
    c.params.Set(key, ReadParamValue(Field(entry.second, params->path() + "." + key,
                                           std::make_shared<const std::string>(controller.file()))));
  }
}

std::vector<std::string>& ExtraPythonPath() {
  static std::vector<std::string> folders;
  return folders;
}

// `python: MODULE:CLASS` instead of `name` (and of `library`): its module is looked for in the
// scenario's folder, then in --python-path's.
void ReadPythonController(const Field& c, const fs::path& dir, sim::ControllerSpec& spec) {
  const auto python = c.Get("python");
  if (!python) return void(c.Require("name"));
  if (c.Get("name")) c.Get("name")->Fail("give `name` (a C++ controller) or `python`, not both");
  if (c.Get("library")) c.Get("library")->Fail("a Python controller has no library: its module is its code");
  const std::string text = python->Text();
  const auto colon = text.find(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 == text.size() ||
      text.find(':', colon + 1) != std::string::npos)
    python->Fail("must be MODULE:CLASS (e.g. waypoint:Waypoint for class Waypoint in waypoint.py), not '" + text + "'");
  spec.python = spec.name = text;
  spec.python_path = {fs::absolute(dir.empty() ? fs::path(".") : dir).lexically_normal().string()};
  if (spec.python_path[0].size() > 1 && spec.python_path[0].back() == '/') spec.python_path[0].pop_back();
  for (const std::string& folder : ExtraPythonPath()) spec.python_path.push_back(folder);
}

net::NetworkSpec ReadNetwork(const Field& f) {
  net::NetworkSpec n;
  NetworkFields().Read(f, n);
  if (!f.Get("data_rate")) n.data_rate = net::DataRates(n.standard).front();
  if (!n.radios.wifi && !f.Get("routing")) n.routing = net::Routing::kNone;  // 802.15.4: one hop
  return n;
}

struct NodeTemplate {
  ModelSpec model;
  std::optional<sim::ControllerSpec> controller;
  int controller_line = 0;
  net::NodeRadio radio;
  std::optional<energy::EnergySpec> energy;
  net::Radios radio_set;  // the radios it carries (none without a network)
};

// Each sensor works in the scenario's world (a satellite fix needs world.datum).
void CheckSensorsFitTheWorld(const Field& f, const ModelSpec& model, const sensors::Surroundings& world) {
  for (const auto& [name, config] : model.sensors) {
    const sensors::SensorKind* kind = sensors::FindKind(config.kind);
    const auto why = kind ? kind->RefusesWorld(world) : std::nullopt;
    if (!why) continue;
    const auto given = f.Get("sensors");
    const auto at = given && given->IsMap() ? given->Get(name) : std::nullopt;
    (at ? *at : f).Fail(*why);
  }
}

// A node with `energy` carries a battery sensor unless its `sensors` take it off; a battery
// sensor on a node without one has nothing to read.
void ReadEnergyAndSensors(const Field& f, NodeTemplate& t, const sensors::Surroundings& world) {
  if (auto energy = f.Get("energy")) {
    t.energy = ReadEnergy(*energy, robots::HasDrive(t.model), t.radio_set);
    t.model.sensors["battery"] = {"battery", sensors::FindKind("battery")->DefaultSettings(t.model)};
  }
  if (auto sensors = f.Get("sensors")) ReadSensors(*sensors, t.model);
  CheckSensorsFitTheWorld(f, t.model, world);
  if (t.energy) return;
  for (const auto& [name, config] : t.model.sensors)
    if (config.kind == "battery")
      f.Require("sensors").Require(name).Fail("a battery sensor reads the node's battery: give the node `energy`");
  const auto sensors = f.Get("sensors");
  if (!sensors) return;
  for (const auto& entry : sensors->node()) {
    const Field sensor = sensors->Require(entry.first.Scalar());
    for (const char* key : {"power_w", "energy_j"})
      if (const auto draw = sensor.IsMap() ? sensor.Get(key) : std::nullopt)
        draw->Fail("draws on the node's battery: give the node `energy` (without it the supply is infinite)");
  }
}

// What reading a node needs of the rest of the scenario: the network, and what reading the nodes'
// radios learns about it (the run's 802.11 standard, when the network's radio is 802.15.4 and a
// node with two radios names it); the world's surroundings, for sensors that need them.
struct NodeContext {
  net::NetworkSpec* network = nullptr;  // none: the scenario has no network
  bool wifi_standard_named = false;
  sensors::Surroundings surroundings;
};

NodeTemplate ReadNodeTemplate(const Field& f, const fs::path& dir, NodeContext& radios) {
  NodeTemplate t;
  if (auto radio = f.Get("radio")) {
    if (!radios.network) radio->Fail("a node's radio needs a 'network' section in the scenario");
    RadioFields().Read(*radio, t.radio);
    ResolveNodeRadio(*radio, *radios.network, radios.wifi_standard_named, t.radio);
    if (t.radio.duty_cycle && radios.network->radio_model == net::RadioModel::kAbstract &&
        t.radio.RadiosIn(*radios.network).wifi)
      radio->Require("duty_cycle")
          .Fail("the abstract radio does not sleep: a duty cycle needs network.radio_model: full");
  } else if (radios.network) {
    t.radio.wifi_standard = radios.network->standard;
  }
  t.radio_set = radios.network ? t.radio.RadiosIn(*radios.network) : net::Radios{false, false};
  t.model = sensors::DefaultModel(ReadModel(f.Require("model")));
  if (auto body = f.Get("body")) {
    ReadBody(*body, t.model);
    // The default sensors sit on the body: follow its new dimensions.
    t.model.sensors = sensors::DefaultSensors(t.model);
  }
  ReadEnergyAndSensors(f, t, radios.surroundings);
  if (auto c = f.Get("controller")) {
    sim::ControllerSpec spec;
    ControllerFields().Read(*c, spec);
    ReadPythonController(*c, dir, spec);
    if (auto lib = c->Get("library")) {
      fs::path p = lib->Text();
      // Relative to the scenario's folder, and absolute so that dlopen does not search the
      // system library path for a bare file name.
      if (p.is_relative()) p = fs::absolute(dir / p);
      if (!fs::exists(p)) lib->Fail("no such file: " + p.string());
      spec.library = p.string();
    }
    ReadParams(*c, spec);
    t.controller = spec;
    t.controller_line = c->line();
  }
  return t;
}

void ReadWorld(const Field& world, sim::RunSpec& run) { WorldFields().Read(world, run); }

// Adds nodes to a scenario, refusing a name used twice.
class NodeList {
 public:
  explicit NodeList(Scenario& sc) : sc_(sc) {}
  // `where`: the node's name; `place`: its pose, or its grid.
  void Add(const Field& where, const Field& place, sim::NodeSpec node, int controller_line) {
    auto [it, fresh] = names_.emplace(node.name, where.line());
    if (!fresh) where.Fail("node name '" + node.name + "' is already used on line " + std::to_string(it->second));
    places_.push_back({place.line(), place.path()});
    sc_.run.nodes.push_back(std::move(node));
    sc_.controller_lines.push_back(controller_line);
    sc_.controller_fields.push_back(controller_line ? where.path().substr(0, where.path().find(']') + 1) + ".controller"
                                                    : "");
  }
  const std::vector<NodePlace>& places() const { return places_; }

 private:
  Scenario& sc_;
  std::vector<NodePlace> places_;
  std::map<std::string, int> names_;  // name -> line where it was defined
};

// `grid: {name, rows, cols, origin, spacing, heading}`: nodes NAME0, NAME1, ... row by row.
constexpr long long kMaxNodes = 100000;
constexpr std::size_t kMaxTracedNodes = 200;  // beyond, a trace is written only when asked for  // far beyond, memory
                                              // for the specs alone runs out before the run starts

// Positions beyond 1e6 m lose the precision the engines need (ODE asserts on some).
void CheckPlace(const Field& where, Vec2 p) {
  if (std::fabs(p.x) > kFarthest || std::fabs(p.y) > kFarthest)
    where.Fail("lies more than 1e6 m from the origin, where the physics loses its precision");
}

void ReadGrid(const Field& n, const fs::path& dir, NodeContext& radios, NodeList& list) {
  n.ExpectKeys(GridItemFields().Keys());
  GridSettings g;
  GridFields().Read(n.Require("grid"), g);
  const Vec2 origin = g.origin, spacing = g.spacing;
  const int rows = g.rows, cols = g.cols;
  if (static_cast<long long>(rows) * cols > kMaxNodes)
    n.Require("grid").Fail("a grid of " + std::to_string(static_cast<long long>(rows) * cols) +
                           " nodes; a scenario holds at most " + std::to_string(kMaxNodes));
  const double heading = g.heading;
  CheckPlace(n.Require("grid"), origin);
  CheckPlace(n.Require("grid"), {origin.x + (cols - 1) * spacing.x, origin.y + (rows - 1) * spacing.y});
  const std::string& prefix = g.name;
  const NodeTemplate t = ReadNodeTemplate(n, dir, radios);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c)
      list.Add(n.Require("grid").Require("name"), n.Require("grid"),
               {prefix + std::to_string(r * cols + c),
                t.model,
                {origin.x + c * spacing.x, origin.y + r * spacing.y, heading},
                t.controller,
                t.radio,
                t.energy},
               t.controller_line);
}

// `scatter: {name, distribution, count | density | cluster keys, region, min_separation, seed}`:
// nodes NAME0, NAME1, ... where the seed puts them (scenario/scatter.h), clear of the obstacles
// and of the nodes listed before the item.
void ReadScattered(const Field& n, const fs::path& dir, Scenario& sc, NodeContext& radios, NodeList& list) {
  n.ExpectKeys(ScatterItemFields().Keys());
  const Field item = n.Require("scatter");
  const ScatterSettings s = ReadScatter(item);
  if (s.density && *s.density * s.region.Area() > kMaxNodes)
    item.Require("density").Fail("expects " + std::to_string(std::llround(*s.density * s.region.Area())) +
                                 " nodes over the region; a scenario holds at most " + std::to_string(kMaxNodes));
  CheckPlace(item.Require("region"), s.region.min);
  CheckPlace(item.Require("region"), s.region.max);
  const NodeTemplate t = ReadNodeTemplate(n, dir, radios);
  const double radius = robots::InscribedRadius(t.model);
  const StartingRoom room(sc.run);
  const Scattered drawn = Scatter(s, sc.run.seed, 2 * radius, [&](Vec2 p) { return room.Fits(p, radius); });
  if (!drawn.complete)
    item.Fail("only " + std::to_string(drawn.positions.size()) + " of " + std::to_string(drawn.wanted) +
              " nodes fitted: after " + std::to_string(kScatterAttempts) +
              " draws no place in the region was clear of the obstacles, the nodes listed before and " +
              Metres(std::max(s.min_separation, 2 * radius)) + " m from the others; ask for fewer or widen the region");
  if (static_cast<long long>(drawn.positions.size()) > kMaxNodes)
    item.Fail("drew " + std::to_string(drawn.positions.size()) + " nodes; a scenario holds at most " +
              std::to_string(kMaxNodes));
  for (std::size_t i = 0; i < drawn.positions.size(); ++i)
    list.Add(item.Require("name"), item,
             {s.name + std::to_string(i),
              t.model,
              {drawn.positions[i].x, drawn.positions[i].y, 0},
              t.controller,
              t.radio,
              t.energy},
             t.controller_line);
}

std::vector<NodePlace> ReadNodes(const Field& nodes, const fs::path& dir, Scenario& sc, NodeContext& radios) {
  sim::RunSpec& run = sc.run;
  NodeList list(sc);
  for (const Field& n : nodes.Items()) {
    if (n.IsMap() && n.Get("grid")) {
      ReadGrid(n, dir, radios, list);
      continue;
    }
    if (n.IsMap() && n.Get("scatter")) {
      ReadScattered(n, dir, sc, radios, list);
      continue;
    }
    n.ExpectKeys(NodeFields().Keys());
    const NodeTemplate t = ReadNodeTemplate(n, dir, radios);
    const auto pose = n.Require("pose").Numbers(3);
    CheckPlace(n.Require("pose"), {pose[0], pose[1]});
    list.Add(n.Require("name"), n.Require("pose"),
             {ReadName(n.Require("name")), t.model, {pose[0], pose[1], pose[2]}, t.controller, t.radio, t.energy},
             t.controller_line);
  }
  if (run.nodes.empty()) nodes.Fail("a scenario needs at least one node");
  if (static_cast<long long>(run.nodes.size()) > kMaxNodes)
    nodes.Fail("a scenario holds at most " + std::to_string(kMaxNodes) + " nodes, not " +
               std::to_string(run.nodes.size()));
  if (run.network && run.nodes.size() > 65534)
    nodes.Fail("a network has room for 65534 nodes (10.0.0.0/16), not " + std::to_string(run.nodes.size()));
  return list.places();
}

// A node's starting position as a table row, to the last bit.
std::vector<std::string> PlaceRow(const sim::NodeSpec& n) {
  char x[32], y[32];
  std::snprintf(x, sizeof x, "%.17g", n.pose.x);
  std::snprintf(y, sizeof y, "%.17g", n.pose.y);
  return {x, y};
}

// The rows of one table parameter, `{node: NAME}` and `{nodes: GROUP}` replaced by the starting
// positions of that node, or of the group's nodes (a grid's or scatter's: GROUP0, GROUP1, ...).
std::vector<std::vector<std::string>> ResolveRows(const ParamValue& value, const Scenario& sc,
                                                  const std::string& field) {
  std::vector<std::vector<std::string>> rows;
  for (const auto& row : value.rows) {
    if (row.empty() || (row[0] != kNodeMark && row[0] != kGroupMark)) {
      rows.push_back(row);
      continue;
    }
    const std::size_t before = rows.size();
    for (const sim::NodeSpec& n : sc.run.nodes) {
      const bool member = n.name.size() > row[1].size() && n.name.compare(0, row[1].size(), row[1]) == 0 &&
                          n.name.find_first_not_of("0123456789", row[1].size()) == std::string::npos;
      if (row[0] == kNodeMark ? n.name == row[1] : member) rows.push_back(PlaceRow(n));
    }
    if (rows.size() == before)
      throw ScenarioError(sc.file, value.line, field,
                          row[0] == kNodeMark
                              ? "no node named '" + row[1] + "' (a grid's or scatter's nodes: `{nodes: GROUP}`)"
                              : "no nodes of a grid or scatter named '" + row[1] + "' (with seed " +
                                    std::to_string(sc.run.seed) + ", a scatter may have drawn none)");
  }
  return rows;
}

// After every node is read: the places controller parameters name become numbers.
void ResolveNodePlaces(Scenario& sc) {
  for (std::size_t i = 0; i < sc.run.nodes.size(); ++i) {
    auto& controller = sc.run.nodes[i].controller;
    if (!controller) continue;
    for (const auto& [key, value] : controller->params.All()) {
      const auto marked = [](const std::vector<std::string>& row) {
        return !row.empty() && (row[0] == kNodeMark || row[0] == kGroupMark);
      };
      if (value.shape != ParamValue::Shape::kTable || std::none_of(value.rows.begin(), value.rows.end(), marked))
        continue;
      ParamValue resolved = value;
      resolved.rows = ResolveRows(value, sc, sc.controller_fields[i] + ".params." + key);
      controller->params.Set(key, resolved);
    }
  }
}

// No body starts inside another or inside an obstacle; nodes far outside the field are a warning.
void CheckWhereNodesStart(const Field& root, const std::vector<NodePlace>& places, Scenario& sc) {
  std::vector<int> obstacle_lines;
  if (const auto world = root.Get("world"))
    if (const auto obstacles = world->Get("obstacles"); obstacles && !obstacles->node().IsNull())
      for (const Field& o : obstacles->Items()) obstacle_lines.push_back(o.line());
  CheckPlacement(sc.file, sc.run, places, obstacle_lines);
  sc.warnings = FieldWarnings(sc.file, sc.run, places);
}

// What an obstacle costs the radio needs a radio, as a node's radio settings do. The values are
// the ones read (`none` and 0 cost nothing); the fields only say where they were written.
void CheckObstacleRadioNeedsANetwork(const Field& root, const Scenario& sc) {
  const sim::RunSpec& run = sc.run;
  const auto world = root.Get("world");
  if (run.network || !world) return;
  constexpr const char* kNeeds = "is a radio loss: it needs a 'network' section in the scenario";
  if (run.obstacle_material != net::Material::kNone) world->Require("obstacle_material").Fail(kNeeds);
  if (run.map && run.map->material.value_or(net::Material::kNone) != net::Material::kNone)
    world->Require("map").Require("material").Fail(kNeeds);
  const auto obstacles = world->Get("obstacles");
  if (!obstacles || obstacles->node().IsNull()) return;
  const std::vector<Field> items = obstacles->Items();  // in the order run.obstacles was read
  for (std::size_t i = 0; i < items.size(); ++i) {
    const sim::Obstacle& o = run.obstacles.at(i);
    const Field shape = items[i].Require(o.kind);
    if (o.material.value_or(net::Material::kNone) != net::Material::kNone) shape.Require("material").Fail(kNeeds);
    if (o.radio_loss_db.value_or(0) > 0) shape.Require("radio_loss_db").Fail(kNeeds);
    if (o.radio_loss_db_per_m > 0) shape.Require("radio_loss_db_per_m").Fail(kNeeds);
  }
}

void ReadMessages(const Field& messages, sim::RunSpec& run) { MessagesFields().Read(messages, run); }

void ReadEvents(const Field& events, sim::RunSpec& run) {
  for (const Field& e : events.Items()) {
    EventSettings settings;
    EventFields().Read(e, settings);
    sim::NodeEvent event;
    event.time = settings.time;
    event.action = settings.action;
    event.energy_j = settings.energy_j;
    if (settings.energy_j && settings.action != sim::NodeEvent::Action::kRecharge)
      e.Require("energy_j").Fail("is the energy of a `recharge`, not of a `" + e.Require("action").Text() + "`");
    bool found = false;
    for (std::size_t i = 0; i < run.nodes.size(); ++i)
      if (run.nodes[i].name == settings.node) event.node = static_cast<std::uint32_t>(i), found = true;
    if (!found) e.Require("node").Fail("no node named '" + settings.node + "'");
    if (event.action == sim::NodeEvent::Action::kRecharge && !run.nodes[event.node].energy)
      e.Require("node").Fail("'" + settings.node + "' has no `energy`: an infinite supply takes no recharge");
    run.events.push_back(event);
  }
}

// Each peer link names a robot that runs as an agent, once, with an address or an interface.
void CheckPeers(const Field& loop, const Scenario& sc) {
  const sim::RunSpec& run = sc.run;
  const auto items = loop.Get("peers");
  if (!items) return;
  std::vector<std::string> seen;
  for (std::size_t i = 0; i < sc.loop.peers.size(); ++i) {
    const sections::PeerLink& p = sc.loop.peers[i];
    const Field item = items->Items()[i];
    const auto node =
        std::find_if(run.nodes.begin(), run.nodes.end(), [&](const auto& n) { return n.name == p.robot; });
    if (node == run.nodes.end() || !sim::RunsAsAgent(*node))
      item.Require("robot").Fail("'" + p.robot + "' is not a robot with a controller (only those run as agents)");
    if (std::find(seen.begin(), seen.end(), p.robot) != seen.end())
      item.Require("robot").Fail("'" + p.robot + "' has a peer link already");
    seen.push_back(p.robot);
    in_addr address{};
    if (!p.address.empty() && ::inet_pton(AF_INET, p.address.c_str(), &address) != 1)
      item.Require("address").Fail("'" + p.address + "' is not an IPv4 address (a.b.c.d)");
    if (p.interface.size() >= IFNAMSIZ)
      item.Require("interface")
          .Fail("'" + p.interface + "' is longer than an interface name can be (" + std::to_string(IFNAMSIZ - 1) +
                " characters)");
    if (p.address.empty() && p.interface.empty()) item.Fail("give address, interface, or both");
  }
}

void ReadLoop(const Field& loop, Scenario& sc) {
  const sim::RunSpec& run = sc.run;
  LoopFields().Read(loop, sc.loop);
  CheckPeers(loop, sc);
  if (sc.loop.network != sections::LoopNetwork::kSimulated) return;
  const Field network = loop.Require("network");
  if (!run.network) network.Fail("simulated needs the scenario's network section: the radio that carries the agents");
  const std::uint16_t port = sc.loop.udp_port;
  if (port == run.network->port || port == net::kAodvPort || port == net::kOlsrPort || port == net::kDsdvPort)
    (loop.Get("udp_port") ? *loop.Get("udp_port") : network)
        .Fail("the agents' UDP port " + std::to_string(port) +
              " is network.port, which the simulated network serves itself");
  for (const sim::NodeSpec& n : run.nodes)
    if (sim::RunsAsAgent(n) && !n.radio.RadiosIn(*run.network).wifi)
      network.Fail("robot '" + n.name +
                   "' has no 802.11 radio: an agent's tap joins its robot's 802.11 radio (802.15.4 carries "
                   "IPv6 through 6LoWPAN, which taps do not); give it one (radio.standard) or use loop.network: host");
  sc.loop.namespaces = true;
}

void ReadEnd(const Field& end, sim::RunSpec& run) {
  EndFields().Read(end, run);
  if (!run.HasEndCondition()) end.Fail("give when_logged, when_transition or when_metric");
}

void ReadOutputs(const Field& outputs, Scenario& sc) { OutputsFields().Read(outputs, sc); }

sections::SpawnClass ReadSpawnClass(const Field& item, const fs::path& dir, NodeContext& radios) {
  item.ExpectKeys(SpawnClassFields().Keys());
  sections::SpawnClass c;
  c.usarsim_class = item.Require("class").Text();
  if (c.usarsim_class.empty()) item.Require("class").Fail("a class needs a name");
  const NodeTemplate t = ReadNodeTemplate(item, dir, radios);
  if (t.model.kind == ModelKind::kMote) item.Require("model").Fail("a spawned robot is an omni3 or a diffdrive");
  c.model = t.model;
  c.radio = t.radio;
  c.energy = t.energy;
  return c;
}

// ros2.robots: robots of the scenario (no motes), each once, with namespaces that ROS takes.
void CheckRos2Robots(const Field& ros2, const sections::Ros2Spec& spec, const Scenario& sc) {
  std::map<std::string, int> robots;
  const auto items = ros2.Get("robots");
  for (std::size_t i = 0; i < spec.robots.size(); ++i) {
    const Field item = items->Items()[i];
    const sections::Ros2Robot& r = spec.robots[i];
    const auto id = std::find_if(sc.run.nodes.begin(), sc.run.nodes.end(),
                                 [&](const sim::NodeSpec& n) { return n.name == r.robot; });
    if (id == sc.run.nodes.end()) item.Require("robot").Fail("no robot named '" + r.robot + "' in this scenario");
    if (id->model.kind == ModelKind::kMote) item.Require("robot").Fail("'" + r.robot + "' is a mote, not a robot");
    if (auto [at, fresh] = robots.emplace(r.robot, item.line()); !fresh)
      item.Require("robot").Fail("given twice (first on line " + std::to_string(at->second) + ")");
    if (!r.ns.empty() && !sections::IsRosName(r.ns))
      item.Require("namespace").Fail("'" + r.ns + "' is no ROS name: letters, digits and _, / between names");
  }
}

// Every robot's namespace (its name unless an item gives one) is a ROS name, and its own.
void CheckRos2Namespaces(const Field& ros2, const sections::Ros2Spec& spec, const Scenario& sc) {
  const auto items = ros2.Get("robots");
  const auto item = [&](const sections::Ros2Robot& r) { return items->Items()[&r - spec.robots.data()]; };
  std::map<std::string, std::string> holders;  // namespace -> robot
  for (const sim::NodeSpec& n : sc.run.nodes) {
    if (n.model.kind == ModelKind::kMote) continue;
    const auto given = std::find_if(spec.robots.begin(), spec.robots.end(),
                                    [&](const sections::Ros2Robot& r) { return r.robot == n.name; });
    const bool named = given != spec.robots.end() && !given->ns.empty();
    const std::string ns = named ? given->ns : n.name;
    if (!named && !sections::IsRosName(ns))
      (given != spec.robots.end() ? item(*given).Require("robot") : ros2)
          .Fail("robot '" + n.name +
                "': its name is no ROS name (letters, digits, _); give it a namespace in ros2.robots");
    if (auto [at, fresh] = holders.emplace(ns, n.name); !fresh) {
      // The item that gave this robot the namespace, or else the one that gave it the other.
      const auto setter = named ? given
                                : std::find_if(spec.robots.begin(), spec.robots.end(),
                                               [&](const sections::Ros2Robot& r) { return r.ns == ns; });
      item(*setter)
          .Require("namespace")
          .Fail("robots " + at->second + " and " + n.name + " would share the namespace '" + ns + "'");
    }
  }
}

void ReadRos2(const Field& ros2, Scenario& sc) {
  sections::Ros2Spec spec;
  Ros2Fields().Read(ros2, spec);
  CheckRos2Robots(ros2, spec, sc);
  CheckRos2Namespaces(ros2, spec, sc);
  sc.ros2 = spec;
}

// After the nodes and the world: the default region is the field around them.
void ReadSpawn(const Field& spawn, const fs::path& dir, Scenario& sc, NodeContext& radios) {
  const sim::RunSpec& run = sc.run;
  sections::SpawnSpec s;
  s.region = sections::DefaultSpawnRegion(run);
  SpawnFields().Read(spawn, s);
  if (auto classes = spawn.Get("classes")) {
    std::map<std::string, int> lines;  // lower-case class -> line
    for (const Field& item : classes->Items()) {
      s.classes.push_back(ReadSpawnClass(item, dir, radios));
      std::string key = s.classes.back().usarsim_class;
      for (char& ch : key) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
      if (auto [it, fresh] = lines.emplace(key, item.line()); !fresh)
        item.Require("class").Fail("class given twice (first on line " + std::to_string(it->second) + ")");
    }
    if (s.classes.empty()) classes->Fail("list at least one class, or leave 'classes' out for the default ones");
  } else {
    s.classes = sections::DefaultSpawnClasses();
  }
  sc.spawn = s;
}

// The radios of every node and spawn class.
std::vector<net::Radios> RadiosUsed(const Scenario& sc) {
  std::vector<net::Radios> used;
  for (const sim::NodeSpec& n : sc.run.nodes) used.push_back(n.radio.RadiosIn(*sc.run.network));
  if (sc.spawn)
    for (const sections::SpawnClass& c : sc.spawn->classes) used.push_back(c.radio.RadiosIn(*sc.run.network));
  return used;
}

// The whole scenario from its (overridden) tree.
void Read(const Field& root, Scenario& sc) {
  const std::string& path = sc.file;
  sim::RunSpec& run = sc.run;
  TopLevelFields().Read(root, sc);
  if (!root.Get("name")) run.name = fs::path(path).stem().string();
  if (auto network = root.Get("network")) run.network = ReadNetwork(*network);
  if (auto world = root.Get("world")) ReadWorld(*world, run);
  CheckObstacleRadioNeedsANetwork(root, sc);
  NodeContext radios{run.network ? &*run.network : nullptr, false, sim::SurroundingsOf(run)};
  CheckWhereNodesStart(root, ReadNodes(root.Require("nodes"), fs::path(path).parent_path(), sc, radios), sc);
  ResolveNodePlaces(sc);
  if (auto messages = root.Get("messages")) ReadMessages(*messages, run);
  if (auto events = root.Get("events")) ReadEvents(*events, run);
  if (auto loop = root.Get("loop")) ReadLoop(*loop, sc);
  if (auto end = root.Get("end")) ReadEnd(*end, run);
  sc.output_folder = "results/" + run.name;
  if (auto outputs = root.Get("outputs")) ReadOutputs(*outputs, sc);
  run.trace = sc.trace.value_or(run.nodes.size() <= kMaxTracedNodes);
  run.radio_contacts = sc.radio_contacts.value_or(run.nodes.size() <= kMaxTracedNodes);
  if (auto spawn = root.Get("spawn")) ReadSpawn(*spawn, fs::path(path).parent_path(), sc, radios);
  if (auto network = root.Get("network"))
    CheckRadiosInUse(*network, RadiosUsed(sc), radios.wifi_standard_named, *run.network);
  if (auto ros2 = root.Get("ros2")) ReadRos2(*ros2, sc);
  if (run.trajectory_interval < run.physics_step) {
    const auto outputs = root.Get("outputs");
    const auto interval = outputs ? outputs->Get("trajectory_interval") : std::nullopt;
    (interval ? *interval : root)
        .Fail("must be at least world.physics_step (" + std::to_string(run.physics_step) + " s)");
  }
}

void CheckEachController(const Scenario& scenario, hosting::Registry& registry) {
  for (std::size_t i = 0; i < scenario.run.nodes.size(); ++i) {
    const auto& node = scenario.run.nodes[i];
    if (!node.controller) continue;
    const int line = scenario.controller_lines[i];
    const std::string& field = scenario.controller_fields[i];
    if (!node.controller->library.empty()) {
      try {
        registry.LoadLibrary(node.controller->library);
      } catch (const hosting::RegistryError& e) {
        throw ScenarioError(scenario.file, line, field + ".library", e.what());
      }
    }
    try {
      sim::MakeController(*node.controller, registry);
    } catch (const ParamError& e) {
      const int at = e.line() ? e.line() : node.controller->params.Line(e.key());
      throw ScenarioError(scenario.file, at ? at : line, field + ".params." + e.key(), e.what());
    } catch (const hosting::RegistryError& e) {
      throw ScenarioError(scenario.file, line, field + (node.controller->python.empty() ? ".name" : ".python"),
                          e.what());
    } catch (const std::exception& e) {
      throw ScenarioError(scenario.file, line, field, std::string("cannot be created: ") + e.what());
    }
  }
}

}  // namespace

namespace {

Scenario Load(const std::string& path, const std::vector<std::string>& overrides, const std::function<Field()>& parse) {
  Scenario sc;
  sc.file = path;
  for (const std::string& text : overrides) sc.overrides.push_back(ParseOverride(text));
  const Field root = parse();
  ApplyOverrides(root.node(), sc.overrides);
  try {
    Read(root, sc);
  } catch (const ScenarioError& e) {
    throw Attributed(e, sc.overrides);
  }
  return sc;
}

}  // namespace

void SetPythonPath(const std::vector<std::string>& folders) {
  ExtraPythonPath().clear();
  for (const std::string& folder : folders)
    ExtraPythonPath().push_back(fs::absolute(folder).lexically_normal().string());
}

Scenario LoadScenario(const std::string& path, const std::vector<std::string>& overrides) {
  return Load(path, overrides, [&] { return ParseYamlFile(path); });
}

Scenario LoadScenarioText(const std::string& text, const std::string& name) {
  return Load(name, {}, [&] { return ParseYamlText(text, name); });
}

void CheckControllers(const Scenario& scenario, hosting::Registry& registry) {
  try {
    CheckEachController(scenario, registry);
  } catch (const ScenarioError& e) {
    throw Attributed(e, scenario.overrides);
  }
}

}  // namespace sanet::scenario
