#include "scenario/scenario_loader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>

#include "sim/world.h"

namespace sanet::scenario {
namespace {

namespace fs = std::filesystem;
using robots::ModelKind;
using robots::ModelSpec;
using robots::RangeSensorSpec;

constexpr double kInf = HUGE_VAL;

// Names end up in CSV files and folder names: keep them to letters, digits, '_', '-' and '.'.
std::string ReadName(const Field& f) {
  const std::string name = f.Text();
  for (char c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-' && c != '.')
      f.Fail("'" + name + "' may hold only letters, digits, '_', '-' and '.'");
  if (name == "." || name == "..") f.Fail("'" + name + "' is not a name");
  return name;
}

std::string FormatNumber(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

Vec2 ReadPoint(const Field& f) {
  const auto v = f.Numbers(2);
  return {v[0], v[1]};
}

sim::Obstacle ReadObstacle(const Field& f) {
  f.ExpectKeys({"box", "wall"});
  if (auto box = f.Get("box")) {
    if (f.Get("wall")) f.Fail("an obstacle is either a box or a wall, not both");
    box->ExpectKeys({"center", "size", "yaw"});
    const Vec2 c = ReadPoint(box->Require("center"));
    const Field size_field = box->Require("size");
    const auto size = size_field.Numbers(3);
    for (double s : size)
      if (s <= 0) size_field.Fail("every side must be greater than 0");
    const double yaw = box->Get("yaw") ? box->Get("yaw")->Number(-kInf, kInf) : 0;
    return {"box", {{c.x, c.y, size[2] / 2}, {size[0], size[1], size[2]}, yaw}};
  }
  auto wall = f.Get("wall");
  if (!wall) f.Fail("an obstacle needs a 'box' or a 'wall'");
  wall->ExpectKeys({"from", "to", "height", "thickness"});
  const Vec2 a = ReadPoint(wall->Require("from"));
  const Vec2 b = ReadPoint(wall->Require("to"));
  if (Norm(b - a) < 1e-6) wall->Require("to").Fail("a wall's two ends must differ");
  const double height = wall->Get("height") ? wall->Get("height")->NumberAbove(0, 1000) : 1.0;
  const double thickness = wall->Get("thickness") ? wall->Get("thickness")->NumberAbove(0, 1000) : 0.2;
  const Vec2 mid = (a + b) * 0.5;
  return {"wall", {{mid.x, mid.y, height / 2}, {Norm(b - a), thickness, height}, std::atan2(b.y - a.y, b.x - a.x)}};
}

ModelKind ReadModel(const Field& f) {
  const std::string name = f.Text();
  for (ModelKind k : {ModelKind::kMote, ModelKind::kOmni3, ModelKind::kDiffDrive})
    if (name == robots::ModelName(k)) return k;
  f.Fail("unknown model '" + name + "' (known: mote, omni3, diffdrive)");
}

// Sets `target` from `key` when present, checking its range.
void Optional(const Field& f, const char* key, double& target, double min, double max) {
  if (auto v = f.Get(key)) target = v->Number(min, max);
}

void ReadBody(const Field& f, ModelSpec& m) {
  switch (m.kind) {
    case ModelKind::kMote:
      f.ExpectKeys({"size", "mass"});
      Optional(f, "size", m.mote.size, 0.005, 10);
      Optional(f, "mass", m.mote.mass, 0.001, 1000);
      break;
    case ModelKind::kOmni3:
      f.ExpectKeys({"body_radius", "body_height", "body_mass", "ground_clearance", "wheel_radius", "wheel_mass",
                    "wheel_distance", "max_wheel_torque", "grip_friction", "slip_friction", "max_speed",
                    "max_turn_rate"});
      Optional(f, "body_radius", m.omni3.body_radius, 0.02, 5);
      Optional(f, "body_height", m.omni3.body_height, 0.02, 5);
      Optional(f, "body_mass", m.omni3.body_mass, 0.01, 1000);
      Optional(f, "ground_clearance", m.omni3.ground_clearance, 0, 1);
      Optional(f, "wheel_radius", m.omni3.wheel_radius, 0.005, 1);
      Optional(f, "wheel_mass", m.omni3.wheel_mass, 0.001, 100);
      Optional(f, "wheel_distance", m.omni3.wheel_distance, 0.01, 5);
      Optional(f, "max_wheel_torque", m.omni3.max_wheel_torque, 0.001, 1000);
      Optional(f, "grip_friction", m.omni3.grip_friction, 0, 10);
      Optional(f, "slip_friction", m.omni3.slip_friction, 0, 10);
      break;
    case ModelKind::kDiffDrive:
      f.ExpectKeys({"body_length", "body_width", "body_height", "body_mass", "ground_clearance", "wheel_radius",
                    "wheel_mass", "axle_length", "caster_offset", "caster_radius", "max_wheel_torque", "wheel_friction",
                    "max_speed", "max_turn_rate"});
      Optional(f, "body_length", m.diffdrive.body_length, 0.02, 10);
      Optional(f, "body_width", m.diffdrive.body_width, 0.02, 10);
      Optional(f, "body_height", m.diffdrive.body_height, 0.02, 10);
      Optional(f, "body_mass", m.diffdrive.body_mass, 0.01, 10000);
      Optional(f, "ground_clearance", m.diffdrive.ground_clearance, 0, 1);
      Optional(f, "wheel_radius", m.diffdrive.wheel_radius, 0.005, 2);
      Optional(f, "wheel_mass", m.diffdrive.wheel_mass, 0.001, 100);
      Optional(f, "axle_length", m.diffdrive.axle_length, 0.02, 10);
      Optional(f, "caster_offset", m.diffdrive.caster_offset, 0.01, 10);
      Optional(f, "caster_radius", m.diffdrive.caster_radius, 0.005, 1);
      Optional(f, "max_wheel_torque", m.diffdrive.max_wheel_torque, 0.001, 10000);
      Optional(f, "wheel_friction", m.diffdrive.wheel_friction, 0, 10);
      break;
  }
  if (m.kind != ModelKind::kMote) {
    Optional(f, "max_speed", m.max_speed, 0, 100);
    Optional(f, "max_turn_rate", m.max_turn_rate, 0, 100);
  }
  if (m.kind == ModelKind::kOmni3 && m.omni3.wheel_distance >= m.omni3.body_radius + m.omni3.wheel_radius)
    f.Fail("wheel_distance must keep the wheels under the body (less than body_radius + wheel_radius)");
}

void ReadIr(const Field& ir, ModelSpec& m) {
  robots::SensorSuite& s = m.sensors;
  if (ir.IsScalar()) {
    s.ir.reset();
    if (ir.Bool()) s.ir = robots::DefaultIr(m);
  } else {
    ir.ExpectKeys({"count", "angles", "max_range", "height", "noise"});
    if (!s.ir) s.ir = robots::DefaultIr(m);
    if (auto count = ir.Get("count")) s.ir->angles = RangeSensorSpec::Ring(count->Integer(1, 360), 0, 0, 1).angles;
    if (auto angles = ir.Get("angles")) {
      if (ir.Get("count")) angles->Fail("give either count (evenly spaced) or angles, not both");
      s.ir->angles.clear();
      for (const Field& a : angles->Items()) s.ir->angles.push_back(a.Number(-2 * kPi, 2 * kPi));
      if (s.ir->angles.empty()) angles->Fail("needs at least one angle");
    }
    if (auto range = ir.Get("max_range")) s.ir->max_range = range->NumberAbove(0, 100);
    Optional(ir, "height", s.ir->mount_height, 0, 10);
    Optional(ir, "noise", s.ir->noise, 0, 100);
  }
}

void ReadLaser(const Field& laser, ModelSpec& m) {
  robots::SensorSuite& s = m.sensors;
  if (laser.IsScalar()) {
    s.laser.reset();
    if (laser.Bool()) s.laser = robots::DefaultLaser(m);
  } else {
    laser.ExpectKeys({"fov", "beams", "max_range", "height", "mount_x", "noise"});
    if (!s.laser) s.laser = robots::DefaultLaser(m);
    const RangeSensorSpec& d = *s.laser;
    const double fov =
        laser.Get("fov") ? laser.Get("fov")->NumberAbove(0, 2 * kPi) : d.angles.back() - d.angles.front();
    const int beams = laser.Get("beams") ? laser.Get("beams")->Integer(1, 10000) : static_cast<int>(d.angles.size());
    const double max_range = laser.Get("max_range") ? laser.Get("max_range")->NumberAbove(0, 1000) : d.max_range;
    const double height = laser.Get("height") ? laser.Get("height")->Number(0, 10) : d.mount_height;
    const double mount_x = laser.Get("mount_x") ? laser.Get("mount_x")->Number(-10, 10) : d.mount_x;
    const double noise = d.noise;
    s.laser = RangeSensorSpec::Fan(fov, beams, mount_x, height, max_range);
    s.laser->noise = noise;
    Optional(laser, "noise", s.laser->noise, 0, 100);
  }
}

void ReadSensors(const Field& f, ModelSpec& m) {
  f.ExpectKeys({"ir", "laser", "odometry", "ground_truth", "bearing"});
  robots::SensorSuite& s = m.sensors;
  const bool mote = m.kind == ModelKind::kMote;
  // `ir: false` removes a sensor, `ir: true` adds the default one, a mapping changes the keys it
  // names on the default (or already present) sensor.
  if (auto ir = f.Get("ir")) ReadIr(*ir, m);
  if (auto laser = f.Get("laser")) ReadLaser(*laser, m);
  if (auto odo = f.Get("odometry")) {
    if (mote) odo->Fail("a mote has no wheels, so no odometry");
    odo->ExpectKeys({"noise"});
    Optional(*odo, "noise", s.odometry_noise, 0, 10);
  }
  if (auto gt = f.Get("ground_truth")) {
    gt->ExpectKeys({"noise_position", "noise_angle"});
    Optional(*gt, "noise_position", s.ground_truth_noise_position, 0, 1000);
    Optional(*gt, "noise_angle", s.ground_truth_noise_angle, 0, 10);
  }
  if (auto b = f.Get("bearing")) {
    b->ExpectKeys({"range", "noise_distance", "noise_angle"});
    robots::BearingSpec spec;
    spec.range = b->Require("range").NumberAbove(0, 1e6);
    Optional(*b, "noise_distance", spec.noise_distance, 0, 1000);
    Optional(*b, "noise_angle", spec.noise_angle, 0, 10);
    s.bearing = spec;
  }
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
    const bool table = !items.empty() && items[0].IsSequence();
    v.shape = table ? ParamValue::Shape::kTable : ParamValue::Shape::kList;
    if (!table) v.rows.emplace_back();
    for (const Field& item : items) {
      if (table) {
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

// Picks one of `choices` (name -> value) by the field's text.
template <typename T>
T ReadChoice(const Field& f, std::initializer_list<std::pair<const char*, T>> choices) {
  const std::string text = f.Text();
  std::string list;
  for (const auto& [name, value] : choices) {
    if (text == name) return value;
    list += std::string(list.empty() ? "" : ", ") + name;
  }
  f.Fail("unknown value '" + text + "' (expected one of: " + list + ")");
}

void ReadPropagation(const Field& p, net::NetworkSpec& n) {
  using namespace net;
  p.ExpectKeys({"model", "exponent", "reference_loss", "reference_distance", "antenna_height", "max_range"});
  if (auto model = p.Get("model"))
    n.loss = ReadChoice<LossModel>(*model, {{"log_distance", LossModel::kLogDistance},
                                            {"friis", LossModel::kFriis},
                                            {"two_ray_ground", LossModel::kTwoRayGround}});
  if (n.loss != LossModel::kLogDistance)
    for (const char* key : {"exponent", "reference_loss", "reference_distance"})
      if (auto k = p.Get(key)) k->Fail("applies to the log_distance model only");
  if (n.loss != LossModel::kTwoRayGround)
    if (auto k = p.Get("antenna_height")) k->Fail("applies to the two_ray_ground model only");
  Optional(p, "exponent", n.exponent, 1, 10);
  Optional(p, "reference_loss", n.reference_loss, 0, 200);
  if (auto d = p.Get("reference_distance")) n.reference_distance = d->NumberAbove(0, 1e6);
  Optional(p, "antenna_height", n.antenna_height, 0, 1000);
  Optional(p, "max_range", n.max_range, 0, 1e7);
}

net::NetworkSpec ReadNetwork(const Field& f) {
  using namespace net;
  f.ExpectKeys({"radio", "data_rate", "tx_power", "rx_threshold", "propagation", "delay", "random_delay_max", "routing",
                "aodv_hello", "flood_ttl", "port", "pcap", "flow_monitor", "packet_log"});
  NetworkSpec n;
  if (auto radio = f.Get("radio")) {
    const std::string text = radio->Text();
    if (text == "802.15.4" || text == "lr-wpan" || text == "lrwpan")
      radio->Fail(
          "802.15.4 is not available: ns-3 carries only IPv6 (6LoWPAN) over it, and its AODV, "
          "OLSR, DSDV and DSR route IPv4 only");
    n.standard = ReadChoice<WifiStandard>(
        *radio,
        {{"802.11b", WifiStandard::k80211b}, {"802.11g", WifiStandard::k80211g}, {"802.11a", WifiStandard::k80211a}});
  }
  const std::vector<double> rates = DataRates(n.standard);
  n.data_rate = rates.front();
  if (auto rate = f.Get("data_rate")) {
    n.data_rate = rate->Number(0, 1000);
    if (std::find(rates.begin(), rates.end(), n.data_rate) == rates.end()) {
      std::string list;
      for (double r : rates) list += (list.empty() ? "" : ", ") + FormatNumber(r);
      rate->Fail(std::string(StandardName(n.standard)) + " offers " + list + " Mbps");
    }
  }
  Optional(f, "tx_power", n.tx_power, -50, 60);
  Optional(f, "rx_threshold", n.rx_threshold, -150, 0);
  if (auto p = f.Get("propagation")) ReadPropagation(*p, n);
  if (auto delay = f.Get("delay"))
    n.delay = ReadChoice<DelayModel>(*delay,
                                     {{"constant_speed", DelayModel::kConstantSpeed}, {"random", DelayModel::kRandom}});
  if (auto max = f.Get("random_delay_max")) {
    if (n.delay != DelayModel::kRandom) max->Fail("applies to delay: random only");
    n.random_delay_max = max->Number(0, 1e-3);  // beyond a millisecond acknowledgements time out
  }
  if (auto routing = f.Get("routing"))
    n.routing = ReadChoice<Routing>(*routing, {{"aodv", Routing::kAodv},
                                               {"olsr", Routing::kOlsr},
                                               {"dsdv", Routing::kDsdv},
                                               {"dsr", Routing::kDsr},
                                               {"none", Routing::kNone}});
  if (auto hello = f.Get("aodv_hello")) n.aodv_hello = hello->Bool();
  if (auto ttl = f.Get("flood_ttl")) n.flood_ttl = ttl->Integer(1, 255);
  if (auto port = f.Get("port")) {
    n.port = static_cast<std::uint16_t>(port->Integer(1, 65535));
    for (auto [taken, by] : {std::pair{654, "AODV"}, {698, "OLSR"}, {269, "DSDV"}})
      if (n.port == taken) port->Fail(std::string("is the port of ") + by + "'s own messages");
  }
  if (auto pcap = f.Get("pcap")) n.pcap = pcap->Bool();
  if (auto fm = f.Get("flow_monitor")) n.flow_monitor = fm->Bool();
  if (auto log = f.Get("packet_log")) n.packet_log = log->Bool();
  return n;
}

struct NodeTemplate {
  ModelSpec model;
  std::optional<sim::ControllerSpec> controller;
  int controller_line = 0;
  net::NodeRadio radio;
};

NodeTemplate ReadNodeTemplate(const Field& f, const fs::path& dir, bool has_network) {
  NodeTemplate t;
  if (auto radio = f.Get("radio")) {
    if (!has_network) radio->Fail("a node's radio needs a 'network' section in the scenario");
    radio->ExpectKeys({"tx_power"});
    if (auto power = radio->Get("tx_power")) t.radio.tx_power = power->Number(-50, 60);
  }
  t.model = ModelSpec::Defaults(ReadModel(f.Require("model")));
  if (auto body = f.Get("body")) {
    ReadBody(*body, t.model);
    // The default sensors sit on the body: follow its new dimensions.
    if (t.model.sensors.ir) t.model.sensors.ir = robots::DefaultIr(t.model);
    if (t.model.sensors.laser) t.model.sensors.laser = robots::DefaultLaser(t.model);
  }
  if (auto sensors = f.Get("sensors")) ReadSensors(*sensors, t.model);
  if (auto c = f.Get("controller")) {
    c->ExpectKeys({"name", "library", "rate", "params"});
    sim::ControllerSpec spec;
    spec.name = c->Require("name").Text();
    if (auto lib = c->Get("library")) {
      fs::path p = lib->Text();
      // Relative to the scenario's folder, and absolute so that dlopen does not search the
      // system library path for a bare file name.
      if (p.is_relative()) p = fs::absolute(dir / p);
      if (!fs::exists(p)) lib->Fail("no such file: " + p.string());
      spec.library = p.string();
    }
    if (auto rate = c->Get("rate")) spec.rate = rate->NumberAbove(0, 10000);
    ReadParams(*c, spec);
    t.controller = spec;
    t.controller_line = c->line();
  }
  return t;
}

void ReadWorld(const Field& world, sim::RunSpec& run) {
  world.ExpectKeys({"size", "physics_step", "gravity", "ground_friction", "solver", "solver_iterations", "obstacles"});
  if (auto solver = world.Get("solver")) {
    const std::string name = solver->Text();
    if (name != "exact" && name != "quick") solver->Fail("must be exact or quick, not '" + name + "'");
    run.physics.solver = name == "exact" ? physics::Solver::kExact : physics::Solver::kQuick;
  }
  if (auto size = world.Get("size")) {
    run.world_size = ReadPoint(*size);
    if (run.world_size.x <= 0 || run.world_size.y <= 0) size->Fail("both sides must be greater than 0");
  }
  if (auto step = world.Get("physics_step")) run.physics_step = step->NumberAbove(0, 0.1);
  Optional(world, "gravity", run.physics.gravity, 0, 100);
  Optional(world, "ground_friction", run.physics.ground_friction, 0, 10);
  if (auto it = world.Get("solver_iterations")) run.physics.solver_iterations = it->Integer(1, 1000);
  if (auto obstacles = world.Get("obstacles"))
    if (!obstacles->node().IsNull())
      for (const Field& o : obstacles->Items()) run.obstacles.push_back(ReadObstacle(o));
}

// Adds nodes to a scenario, refusing a name used twice.
class NodeList {
 public:
  explicit NodeList(Scenario& sc) : sc_(sc) {}
  void Add(const Field& where, sim::NodeSpec node, int controller_line) {
    auto [it, fresh] = names_.emplace(node.name, where.line());
    if (!fresh) where.Fail("node name '" + node.name + "' is already used on line " + std::to_string(it->second));
    sc_.run.nodes.push_back(std::move(node));
    sc_.controller_lines.push_back(controller_line);
    sc_.controller_fields.push_back(controller_line ? where.path().substr(0, where.path().find(']') + 1) + ".controller"
                                                    : "");
  }

 private:
  Scenario& sc_;
  std::map<std::string, int> names_;  // name -> line where it was defined
};

// `grid: {name, rows, cols, origin, spacing, heading}`: nodes NAME0, NAME1, ... row by row.
void ReadGrid(const Field& n, const fs::path& dir, bool has_network, NodeList& list) {
  n.ExpectKeys({"grid", "model", "body", "sensors", "radio", "controller"});
  const Field g = n.Require("grid");
  g.ExpectKeys({"name", "rows", "cols", "origin", "spacing", "heading"});
  const std::string prefix = ReadName(g.Require("name"));
  const int rows = g.Require("rows").Integer(1, 10000);
  const int cols = g.Require("cols").Integer(1, 10000);
  const Vec2 origin = g.Get("origin") ? ReadPoint(*g.Get("origin")) : Vec2{0, 0};
  Vec2 spacing{1, 1};
  if (auto s = g.Get("spacing")) {
    spacing = s->IsSequence() ? ReadPoint(*s) : Vec2{s->Number(0, 1e6), s->Number(0, 1e6)};
    if (spacing.x <= 0 || spacing.y <= 0) s->Fail("spacing must be greater than 0");
  }
  const double heading = g.Get("heading") ? g.Get("heading")->Number(-kInf, kInf) : 0;
  const NodeTemplate t = ReadNodeTemplate(n, dir, has_network);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c)
      list.Add(g.Require("name"),
               {prefix + std::to_string(r * cols + c),
                t.model,
                {origin.x + c * spacing.x, origin.y + r * spacing.y, heading},
                t.controller,
                t.radio},
               t.controller_line);
}

void ReadNodes(const Field& nodes, const fs::path& dir, Scenario& sc) {
  sim::RunSpec& run = sc.run;
  NodeList list(sc);
  for (const Field& n : nodes.Items()) {
    if (n.IsMap() && n.Get("grid")) {
      ReadGrid(n, dir, run.network.has_value(), list);
      continue;
    }
    n.ExpectKeys({"name", "model", "pose", "body", "sensors", "radio", "controller"});
    const NodeTemplate t = ReadNodeTemplate(n, dir, run.network.has_value());
    const auto pose = n.Require("pose").Numbers(3);
    list.Add(n.Require("name"),
             {ReadName(n.Require("name")), t.model, {pose[0], pose[1], pose[2]}, t.controller, t.radio},
             t.controller_line);
  }
  if (run.nodes.empty()) nodes.Fail("a scenario needs at least one node");
  if (run.network && run.nodes.size() > 65534)
    nodes.Fail("a network has room for 65534 nodes (10.0.0.0/16), not " + std::to_string(run.nodes.size()));
}

void ReadMessages(const Field& messages, sim::RunSpec& run) {
  if (run.network && messages.Get("latency"))
    messages.Get("latency")->Fail("is for runs without a network; with one, the network delivers");
  messages.ExpectKeys({"latency", "loss", "delay"});
  Optional(messages, "latency", run.message_latency, 0, 1000);
  Optional(messages, "loss", run.message_loss, 0, 1);
  Optional(messages, "delay", run.message_delay, 0, 1000);
}

void ReadEvents(const Field& events, sim::RunSpec& run) {
  for (const Field& e : events.Items()) {
    e.ExpectKeys({"time", "node", "action"});
    sim::NodeEvent event;
    event.time = e.Require("time").Number(0, 1e9);
    const Field node = e.Require("node");
    bool found = false;
    for (std::size_t i = 0; i < run.nodes.size(); ++i)
      if (run.nodes[i].name == node.Text()) event.node = static_cast<std::uint32_t>(i), found = true;
    if (!found) node.Fail("no node named '" + node.Text() + "'");
    event.action =
        ReadChoice<sim::NodeEvent::Action>(e.Require("action"), {{"switch_off", sim::NodeEvent::Action::kSwitchOff}});
    run.events.push_back(event);
  }
}

void ReadLoop(const Field& loop, sim::RunSpec& run) {
  loop.ExpectKeys({"namespaces", "netem", "udp_port"});
  if (auto ns = loop.Get("namespaces")) run.loop.namespaces = ns->Bool();
  if (auto port = loop.Get("udp_port")) run.loop.udp_port = static_cast<std::uint16_t>(port->Integer(1024, 60000));
  if (auto netem = loop.Get("netem")) {
    netem->ExpectKeys({"delay", "jitter", "loss", "rate"});
    if (!run.loop.namespaces) netem->Fail("shapes the links between namespaces: set loop.namespaces: true");
    Optional(*netem, "delay", run.loop.shaping.delay, 0, 60);
    Optional(*netem, "jitter", run.loop.shaping.jitter, 0, 60);
    Optional(*netem, "loss", run.loop.shaping.loss, 0, 1);
    Optional(*netem, "rate", run.loop.shaping.rate, 0, 1e12);
  }
}

void ReadEnd(const Field& end, sim::RunSpec& run) {
  end.ExpectKeys({"when_logged", "grace"});
  if (auto grace = end.Get("grace")) run.end_grace = grace->Number(0, 1e6);
  const Field logged = end.Require("when_logged");
  if (logged.IsScalar())
    run.end_when_logged.push_back(logged.Text());
  else
    for (const Field& line : logged.Items()) run.end_when_logged.push_back(line.Text());
}

void ReadOutputs(const Field& outputs, Scenario& sc) {
  sim::RunSpec& run = sc.run;
  outputs.ExpectKeys({"folder", "trajectory_interval", "figures", "figure_tick", "min_distance", "distance_reference"});
  if (auto md = outputs.Get("min_distance")) run.min_distance = md->Bool();
  if (auto ref = outputs.Get("distance_reference")) {
    run.distance_reference = ref->NumberAbove(0, 1e6);
    run.min_distance = true;
  }
  if (auto figures = outputs.Get("figures")) run.figures = figures->Bool();
  if (auto tick = outputs.Get("figure_tick")) run.figure_tick = tick->NumberAbove(0, 1e9);
  if (auto folder = outputs.Get("folder")) sc.output_folder = folder->Text();
  if (auto interval = outputs.Get("trajectory_interval")) run.trajectory_interval = interval->NumberAbove(0, 1e6);
}

}  // namespace

Scenario LoadScenario(const std::string& path) {
  const Field root = ParseYamlFile(path);
  Scenario sc;
  sc.file = path;
  sim::RunSpec& run = sc.run;
  root.ExpectKeys(
      {"name", "seed", "duration", "world", "network", "nodes", "messages", "events", "end", "loop", "outputs"});
  if (auto network = root.Get("network")) run.network = ReadNetwork(*network);
  run.name = root.Get("name") ? ReadName(*root.Get("name")) : fs::path(path).stem().string();
  if (auto seed = root.Get("seed")) run.seed = seed->Unsigned();
  run.duration = root.Require("duration").NumberAbove(0, 1e9);
  if (auto world = root.Get("world")) ReadWorld(*world, run);
  ReadNodes(root.Require("nodes"), fs::path(path).parent_path(), sc);
  if (auto messages = root.Get("messages")) ReadMessages(*messages, run);
  if (auto events = root.Get("events")) ReadEvents(*events, run);
  if (auto loop = root.Get("loop")) ReadLoop(*loop, run);
  if (auto end = root.Get("end")) ReadEnd(*end, run);
  sc.output_folder = "results/" + run.name;
  if (auto outputs = root.Get("outputs")) ReadOutputs(*outputs, sc);
  if (run.trajectory_interval < run.physics_step) {
    const auto outputs = root.Get("outputs");
    const auto interval = outputs ? outputs->Get("trajectory_interval") : std::nullopt;
    (interval ? *interval : root)
        .Fail("must be at least world.physics_step (" + std::to_string(run.physics_step) + " s)");
  }
  return sc;
}

void CheckControllers(const Scenario& scenario, agents::Registry& registry) {
  for (std::size_t i = 0; i < scenario.run.nodes.size(); ++i) {
    const auto& node = scenario.run.nodes[i];
    if (!node.controller) continue;
    const int line = scenario.controller_lines[i];
    const std::string& field = scenario.controller_fields[i];
    if (!node.controller->library.empty()) {
      try {
        registry.LoadLibrary(node.controller->library);
      } catch (const agents::RegistryError& e) {
        throw ScenarioError(scenario.file, line, field + ".library", e.what());
      }
    }
    try {
      sim::MakeController(*node.controller, registry);
    } catch (const ParamError& e) {
      const int at = e.line() ? e.line() : node.controller->params.Line(e.key());
      throw ScenarioError(scenario.file, at ? at : line, field + ".params." + e.key(), e.what());
    } catch (const agents::RegistryError& e) {
      throw ScenarioError(scenario.file, line, field + ".name", e.what());
    } catch (const std::exception& e) {
      throw ScenarioError(scenario.file, line, field, std::string("cannot be created: ") + e.what());
    }
  }
}

}  // namespace sanet::scenario
