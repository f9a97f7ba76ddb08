#include "scenario/declarations.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "scenario/calibration_field.h"
#include "scenario/energy_fields.h"
#include "scenario/link_variation_fields.h"
#include "scenario/lr_wpan_fields.h"
#include "scenario/map_field.h"
#include "scenario/sensor_fields.h"

namespace sanet::scenario {
namespace {

using robots::ModelKind;
using robots::ModelSpec;
constexpr double kInf = HUGE_VAL;

Vec2 ReadPoint(const Field& f) {
  const auto v = f.Numbers(2);
  return {v[0], v[1]};
}

YAML::Node Numbers(std::initializer_list<double> values) {
  YAML::Node out(YAML::NodeType::Sequence);
  for (double v : values) out.push_back(NumberNode(v));
  out.SetStyle(YAML::EmitterStyle::Flow);
  return out;
}

// A loss given outright replaces the material's: both at once is a contradiction.
void WithRadio(const Field& f, const ObstacleRadio& radio, sim::Obstacle& o) {
  if (radio.material && radio.loss_db)
    f.Get("radio_loss_db")->Fail("give either 'material' or 'radio_loss_db', not both");
  o.material = radio.material, o.radio_loss_db = radio.loss_db, o.radio_loss_db_per_m = radio.loss_db_per_m;
}

// The materials' names, each between `quote`s.
std::string MaterialList(const std::string& quote = "") {
  std::string list;
  for (const std::string& name : net::MaterialNames()) list += (list.empty() ? "" : ", ") + quote + name + quote;
  return list;
}

sim::Obstacle ReadBox(const Field& box) {
  BoxSettings b;
  BoxFields().Read(box, b);
  sim::Obstacle o{"box", {{b.center.x, b.center.y, b.size[2] / 2}, {b.size[0], b.size[1], b.size[2]}, b.yaw}, {}, {}};
  WithRadio(box, b.radio, o);
  o.indoor = b.indoor, o.color = b.color;
  return o;
}

sim::Obstacle ReadWall(const Field& wall) {
  WallSettings w;
  WallFields().Read(wall, w);
  const Vec2 mid = (w.from + w.to) * 0.5;
  sim::Obstacle o{"wall",
                  {{mid.x, mid.y, w.height / 2},
                   {Norm(w.to - w.from), w.thickness, w.height},
                   std::atan2(w.to.y - w.from.y, w.to.x - w.from.x)},
                  {},
                  {}};
  WithRadio(wall, w.radio, o);
  o.indoor = w.indoor, o.color = w.color;
  return o;
}

sim::Obstacle ReadObstacle(const Field& f) {
  f.ExpectKeys({"box", "wall"});
  if (auto box = f.Get("box")) {
    if (f.Get("wall")) f.Fail("an obstacle is either a box or a wall, not both");
    return ReadBox(*box);
  }
  auto wall = f.Get("wall");
  if (!wall) f.Fail("an obstacle needs a 'box' or a 'wall'");
  return ReadWall(*wall);
}

// Every obstacle as the box it is (a wall's ends are not kept, its box is exact).
YAML::Node PrintObstacles(const std::vector<sim::Obstacle>& obstacles) {
  YAML::Node list(YAML::NodeType::Sequence);
  for (const sim::Obstacle& o : obstacles) {
    if (o.from_map) continue;  // printed with world.map
    YAML::Node box;
    box["center"] = Numbers({o.box.center.x, o.box.center.y});
    box["size"] = Numbers({o.box.size.x, o.box.size.y, o.box.size.z});
    box["yaw"] = NumberNode(o.box.yaw);
    if (o.material) box["material"] = net::MaterialName(*o.material);
    if (o.radio_loss_db) box["radio_loss_db"] = NumberNode(*o.radio_loss_db);
    if (o.radio_loss_db_per_m > 0) box["radio_loss_db_per_m"] = NumberNode(o.radio_loss_db_per_m);
    if (o.indoor) box["indoor"] = true;
    if (o.color) box["color"] = RgbText(*o.color);
    YAML::Node item;
    item["box"] = box;
    list.push_back(item);
  }
  return list.size() == 0 ? YAML::Node() : list;
}

}  // namespace

net::Material ReadMaterial(const Field& v) {
  const std::string text = v.Text();
  const auto material = net::MaterialNamed(text);
  if (!material) v.Fail("unknown material '" + text + "' (expected one of: " + MaterialList() + ")");
  return *material;
}

const Fields<sim::Charger>& ChargerFields() {
  static const Fields<sim::Charger> fields = [] {
    Fields<sim::Charger> f;
    f.Custom(
        {"position", "point `[x, y]`", "m", kRequired, "", "the charger's centre"},
        [](const Field& v, sim::Charger& c) { c.position = ReadPoint(v); },
        [](const sim::Charger& c) {
          return Numbers({c.position.x, c.position.y});
        });
    f.Number("radius", Member(&sim::Charger::radius), "m", 0, 1e4, "a node whose reference point is this close charges",
             true)
        .Required();
    f.Number("power_w", Member(&sim::Charger::power_w), "W", 0, 1e6,
             "what a node inside receives into its battery (never past full)", true)
        .Required();
    return f;
  }();
  return fields;
}

namespace {

void CheckPlace(const Field& where, Vec2 p) {
  if (std::fabs(p.x) > kFarthest || std::fabs(p.y) > kFarthest) where.Fail("lies more than 1e6 m from the origin");
}

// world.datum: the world's origin on the Earth, {latitude, longitude, altitude}.
sensors::GeoDatum ReadDatum(const Field& v) {
  v.ExpectKeys({"latitude", "longitude", "altitude"});
  sensors::GeoDatum d;
  d.latitude = v.Require("latitude").Number(-90, 90);
  d.longitude = v.Require("longitude").Number(-180, 180);
  if (auto altitude = v.Get("altitude")) d.altitude = altitude->Number(-11000, 100000);
  return d;
}

// One of world.gnss_denied: `{polygon: [[x, y], ...]}` (three corners or more, in order) or a box
// `{center, size: [length, width], yaw}`. Printed as its polygon.
sensors::Region ReadDeniedRegion(const Field& v) {
  if (!v.IsMap())
    v.Fail("a region is a mapping: `{polygon: [[x, y], ...]}` or `{center: [x, y], size: [length, width]}`");
  v.ExpectKeys({"polygon", "center", "size", "yaw"});
  sensors::Region region;
  if (auto polygon = v.Get("polygon")) {
    for (const char* key : {"center", "size", "yaw"})
      if (auto box = v.Get(key)) box->Fail("is a box's: a region is either a `polygon` or a box, not both");
    for (const Field& corner : polygon->Items()) {
      region.push_back(ReadPoint(corner));
      CheckPlace(corner, region.back());
    }
    if (region.size() < 3) polygon->Fail("a polygon needs three corners or more");
    double twice_area = 0;  // the shoelace formula
    for (std::size_t i = 0, j = region.size() - 1; i < region.size(); j = i++)
      twice_area += region[j].x * region[i].y - region[i].x * region[j].y;
    if (std::fabs(twice_area) < 1e-9) polygon->Fail("the polygon's corners enclose no area");
    return region;
  }
  const Vec2 center = ReadPoint(v.Require("center"));
  CheckPlace(v.Require("center"), center);
  const std::vector<double> size = v.Require("size").Numbers(2);
  if (size[0] <= 0 || size[1] <= 0) v.Require("size").Fail("both sides must be greater than 0");
  const double yaw = v.Get("yaw") ? v.Require("yaw").Number(-kInf, kInf) : 0;
  for (const Vec2 corner : physics::FootprintCorners({{center.x, center.y, 0}, {size[0], size[1], 0}, yaw}))
    region.push_back(corner);
  return region;
}

// world.datum and world.gnss_denied: where the world lies, and where satellites are not heard.
void AddGeography(Fields<sim::RunSpec>& f) {
  f.Custom(
      {"datum", "mapping `{latitude, longitude, altitude}`", "degrees, degrees, m", "none", "",
       "the world's origin on the WGS 84 ellipsoid (x east, y north): see [satellite fixes](#satellite-fixes)"},
      [](const Field& v, sim::RunSpec& s) { s.datum = ReadDatum(v); },
      [](const sim::RunSpec& s) {
        if (!s.datum) return YAML::Node();
        YAML::Node out;
        out["latitude"] = NumberNode(s.datum->latitude);
        out["longitude"] = NumberNode(s.datum->longitude);
        out["altitude"] = NumberNode(s.datum->altitude);
        return out;
      });
  f.Custom(
      {"gnss_denied", "list of regions", "m", "none", "",
       "no satellite fix inside: each `{polygon: [[x, y], ...]}` or `{center, size: [length, width], yaw}`"},
      [](const Field& v, sim::RunSpec& s) {
        if (!v.node().IsNull())
          for (const Field& r : v.Items()) s.gnss_denied.push_back(ReadDeniedRegion(r));
      },
      [](const sim::RunSpec& s) {
        if (s.gnss_denied.empty()) return YAML::Node();
        YAML::Node list(YAML::NodeType::Sequence);
        for (const sensors::Region& r : s.gnss_denied) {
          YAML::Node polygon(YAML::NodeType::Sequence);
          for (Vec2 p : r) polygon.push_back(Numbers({p.x, p.y}));
          YAML::Node item;
          item["polygon"] = polygon;
          list.push_back(item);
        }
        return list;
      });
}

// world.ground_color and world.sky_color, for cameras.
void AddSceneColors(Fields<sim::RunSpec>& f) {
  for (const auto& [key, member, meaning] :
       {std::tuple{"ground_color", &sim::RunSpec::ground_color, "what cameras see of the ground"},
        std::tuple{"sky_color", &sim::RunSpec::sky_color, "what cameras see where nothing is"}}) {
    const std::string fallback = "`\"" + RgbText(sim::RunSpec{}.*member) + "\"`";
    f.Custom(
        {key, "text `\"#rrggbb\"`", "", fallback, "", meaning},
        [member = member](const Field& v, sim::RunSpec& s) { s.*member = ReadColor(v); },
        [member = member](const sim::RunSpec& s) { return YAML::Node(RgbText(s.*member)); });
  }
}

// world.chargers: a list of ChargerFields, printed where there are any.
void AddChargers(Fields<sim::RunSpec>& f) {
  f.Custom(
      {"chargers", "list of chargers", "", "none", "", "see [chargers](#chargers): they charge nodes with `energy`"},
      [](const Field& v, sim::RunSpec& s) {
        if (v.node().IsNull()) return;
        for (const Field& c : v.Items()) ChargerFields().Read(c, s.chargers.emplace_back());
      },
      [](const sim::RunSpec& s) {
        if (s.chargers.empty()) return YAML::Node();
        YAML::Node list(YAML::NodeType::Sequence);
        for (const sim::Charger& c : s.chargers) list.push_back(ChargerFields().Print(c));
        return list;
      });
}

}  // namespace

const Fields<sim::RunSpec>& WorldFields() {
  using sim::RunSpec;
  static const Fields<RunSpec> fields = [] {
    Fields<RunSpec> f;
    f.Custom(
        {"size", "point `[x, y]`", "m", "", "both > 0", "extent of the field, for plots"},
        [](const Field& v, RunSpec& s) {
          s.world_size = ReadPoint(v);
          if (s.world_size.x <= 0 || s.world_size.y <= 0) v.Fail("both sides must be greater than 0");
          if (s.world_size.x > kFarthest || s.world_size.y > kFarthest) v.Fail("both sides must be at most 1e6 m");
        },
        [](const RunSpec& s) {
          return Numbers({s.world_size.x, s.world_size.y});
        });
    f.Choice<physics::Engine>(
        "physics", [](RunSpec& s) -> physics::Engine& { return s.physics.engine; },
        {{"3d", physics::Engine::k3d}, {"2d", physics::Engine::k2d}},
        "the physics engine: `3d` (ODE: wheels, casters, contacts) or `2d` (Box2D, seen from above: for swarms)");
    // Below 0.1 ms a run of any length takes hours; the engines are not built for it either.
    f.Number("physics_step", Member(&RunSpec::physics_step), "s", 1e-4, 0.1, "length of each physics step");
    f.Number(
        "gravity", [](RunSpec& s) -> double& { return s.physics.gravity; }, "m/s²", 0, 100,
        "magnitude, pointing along −z");
    f.Number(
        "ground_friction", [](RunSpec& s) -> double& { return s.physics.ground_friction; }, "", 0, 10,
        "Coulomb coefficient of the ground and obstacles");
    f.Whole<int>("threads", Member(&RunSpec::threads), "", 1, 2,
                 "`2` steps the physics on a second thread while ns-3 runs the network; same results as `1`");
    f.Choice<physics::Solver>(
        "solver", [](RunSpec& s) -> physics::Solver& { return s.physics.solver; },
        {{"exact", physics::Solver::kExact}, {"quick", physics::Solver::kQuick}}, "how ODE solves contacts and joints");
    f.Whole<int>(
        "solver_iterations", [](RunSpec& s) -> int& { return s.physics.solver_iterations; }, "", 1, 1000,
        "iterations of the `quick` solver");
    f.Custom(
        {"obstacles", "list of obstacles", "", "none", "", "see [obstacles](#obstacles)"},
        [](const Field& v, RunSpec& s) {
          if (!v.node().IsNull())
            for (const Field& o : v.Items()) s.obstacles.push_back(ReadObstacle(o));
        },
        [](const RunSpec& s) { return PrintObstacles(s.obstacles); });
    AddWorldMap(f);  // after obstacles: its boxes come after theirs
    AddChargers(f);
    AddGeography(f);
    AddSceneColors(f);
    f.Custom(
        {"obstacle_material", "text", "", "`none`", MaterialList("`"),
         "material of the obstacles that name none: `none` costs the radio nothing"},
        [](const Field& v, RunSpec& s) { s.obstacle_material = ReadMaterial(v); },
        [](const RunSpec& s) { return YAML::Node(net::MaterialName(s.obstacle_material)); });
    return f;
  }();
  return fields;
}

namespace {

bool AppliesTo(const std::string& key, net::LossModel model) {
  if (key == "exponent" || key == "reference_loss" || key == "reference_distance")
    return model == net::LossModel::kLogDistance;
  if (key == "antenna_height") return model == net::LossModel::kTwoRayGround;
  return true;
}

void ReadPropagation(const Field& p, net::NetworkSpec& n) {
  PropagationFields().Read(p, n);
  for (const char* key : {"exponent", "reference_loss", "reference_distance", "antenna_height"})
    if (auto k = p.Get(key); k && !AppliesTo(key, n.loss))
      k->Fail(std::string("applies to the ") +
              (std::string(key) == "antenna_height" ? "two_ray_ground" : "log_distance") + " model only");
}

YAML::Node PrintPropagation(const net::NetworkSpec& n) {
  YAML::Node all = PropagationFields().Print(n), out(YAML::NodeType::Map);
  for (const auto& entry : all)
    if (AppliesTo(entry.first.as<std::string>(), n.loss)) out[entry.first] = entry.second;
  return out;
}

void ReadChannel(const Field& c, net::NetworkSpec& n) {
  ChannelFields().Read(c, n);
  auto floor = c.Get("floor");
  if (floor && n.channel != net::ChannelModel::kIndexed) floor->Fail("applies to the indexed channel only");
  if (floor && n.ChannelFloor() > n.rx_threshold)
    floor->Fail("is above rx_threshold (" + ShortNumber(n.rx_threshold) +
                " dBm): frames strong enough to be detected would be skipped");
}

YAML::Node PrintChannel(const net::NetworkSpec& n) {
  if (!n.wifi_in_use) return YAML::Node();
  YAML::Node out = ChannelFields().Print(n);
  if (n.channel != net::ChannelModel::kIndexed) out.remove("floor");
  return out;
}

// `ns3: {"ns3::aodv::RoutingProtocol::ActiveRouteTimeout": 10s, ...}`, checked against ns-3's
// attribute lists; each error is on the attribute's own line.
void ReadNs3(const Field& f, net::NetworkSpec& n) {
  if (!f.IsMap()) f.Fail("must be a mapping of ns-3 attribute names to values");
  for (const auto& entry : f.node()) {
    const std::string name = entry.first.Scalar();
    const Field value = *f.Get(name);
    if (!value.IsScalar()) value.Fail("must be a single value as ns-3 writes it (e.g. 10s, 3, true)");
    for (const auto& [seen, ignored] : n.ns3)
      if (seen == name) value.Fail("given twice");
    const std::string why = net::CheckNs3Attribute(name, value.node().Scalar());
    if (!why.empty()) value.Fail(why);
    n.ns3.emplace_back(name, value.node().Scalar());
  }
}

YAML::Node PrintNs3(const net::NetworkSpec& n) {
  if (n.ns3.empty()) return YAML::Node();
  YAML::Node out(YAML::NodeType::Map);
  for (const auto& [name, value] : n.ns3) out[name] = value;
  return out;
}

void ReadDataRate(const Field& rate, net::NetworkSpec& n) {
  const std::vector<double> rates = net::DataRates(n.standard);
  n.data_rate = rate.Number(0, 1000);
  if (!n.radios.wifi) return;  // the 802.11 standard is the one a node names: checked once it has
  if (std::find(rates.begin(), rates.end(), n.data_rate) != rates.end()) return;
  std::string list;
  for (double r : rates) list += (list.empty() ? "" : ", ") + ShortNumber(r);
  rate.Fail(std::string(net::StandardName(n.standard)) + " offers " + list + " Mbps");
}

void ReadPort(const Field& port, net::NetworkSpec& n) {
  n.port = static_cast<std::uint16_t>(port.Integer(1, 65535));
  for (auto [taken, by] : {std::pair{654, "AODV"}, {698, "OLSR"}, {269, "DSDV"}})
    if (n.port == taken) port.Fail(std::string("is the port of ") + by + "'s own messages");
}

void ReadRadioModel(const Field& f, net::NetworkSpec& n) {
  const std::string text = f.Text();
  if (text != "full" && text != "abstract") f.Fail("unknown value '" + text + "' (expected one of: full, abstract)");
  n.radio_model = text == "abstract" ? net::RadioModel::kAbstract : net::RadioModel::kFull;
}

// How 802.11 radios are simulated, and the 802.15.4 radios' section.
void RadioKinds(Fields<net::NetworkSpec>& f) {
  using net::NetworkSpec;
  f.Custom({"radio_model", "text", "", "`full`", "`full`, `abstract`",
            "how 802.11 radios are simulated: ns-3's whole 802.11 model, or an abstraction calibrated against it, "
            "for swarms (see [swarms.md](swarms.md#the-abstract-radio))"},
           ReadRadioModel, [](const NetworkSpec& n) {
             return n.radio_model == net::RadioModel::kAbstract ? YAML::Node("abstract") : YAML::Node();
           });
  f.Custom(CalibrationEntry(), ReadCalibration, PrintCalibration);
  f.Custom(LrWpanEntry(), ReadLrWpan,
           [](const NetworkSpec& n) { return n.lr_wpan_in_use ? PrintLrWpan(n) : YAML::Node(); });
}

// What the network writes besides the run's own results.
void TraceFlags(Fields<net::NetworkSpec>& f) {
  using net::NetworkSpec;
  f.Flag("pcap", Member(&NetworkSpec::pcap),
         "write `pcap/<node>.pcap` (802.11 frames; `pcap/<node>-802.15.4.pcap` for an 802.15.4 radio)");
  f.Flag("flow_monitor", Member(&NetworkSpec::flow_monitor), "write `flowmon.xml`");
  f.Flag("packet_log", Member(&NetworkSpec::packet_log), "write `packets/<node>.csv`");
}

// A number of the 802.11 radios', printed only when some node has one.
void WifiNumber(Fields<net::NetworkSpec>& f, const char* key, double net::NetworkSpec::*member, const char* unit,
                double min, double max, const char* meaning) {
  f.Custom(
      {key, "number", unit, "", RangeText(min, max, false), meaning},
      [=](const Field& v, net::NetworkSpec& n) { n.*member = v.Number(min, max); },
      [=](const net::NetworkSpec& n) { return n.wifi_in_use ? NumberNode(n.*member) : YAML::Node(); });
}

}  // namespace

const Fields<net::NetworkSpec>& NetworkFields() {
  using net::NetworkSpec;
  static const Fields<NetworkSpec> fields = [] {
    Fields<NetworkSpec> f;
    f.Custom(NetworkRadioEntry(), ReadNetworkRadio, PrintNetworkRadio);
    f.Custom(
        {"data_rate", "number", "Mbps", "the standard's lowest: `1` (802.11b), `6` (802.11g, 802.11a)",
         "802.11b: 1, 2, 5.5, 11; 802.11g and 802.11a: 6, 9, 12, 18, 24, 36, 48, 54", "rate of unicast data frames"},
        ReadDataRate, [](const NetworkSpec& n) { return n.wifi_in_use ? NumberNode(n.data_rate) : YAML::Node(); });
    WifiNumber(f, "tx_power", &NetworkSpec::tx_power, "dBm", -50, 60,
               "every 802.11 radio's transmit power unless a node sets its own");
    WifiNumber(f, "rx_threshold", &NetworkSpec::rx_threshold, "dBm", -150, 0,
               "weakest signal at which an 802.11 radio detects a frame");
    f.Custom(
        {"propagation", "mapping", "", "log-distance, see below", "see [propagation](#propagation)", "path loss model"},
        ReadPropagation, PrintPropagation);
    f.Custom({"channel", "mapping", "", "indexed, see below", "see [channel](#channel)",
              "which radios each frame is handed to"},
             ReadChannel, PrintChannel);
    f.Custom(HardwareSpreadEntry(), ReadHardwareSpread, PrintHardwareSpread);
    f.Choice<net::DelayModel>(
        "delay", Member(&NetworkSpec::delay),
        {{"constant_speed", net::DelayModel::kConstantSpeed}, {"random", net::DelayModel::kRandom}},
        "propagation delay: the speed of light, or uniform in [0, `random_delay_max`]");
    f.Custom(
        {"random_delay_max", "number", "s", "`1e-6`", "[0, 0.001]; with `delay: random` only",
         "upper bound of `random` delays"},
        [](const Field& v, NetworkSpec& n) {
          if (n.delay != net::DelayModel::kRandom) v.Fail("applies to delay: random only");
          n.random_delay_max = v.Number(0, 1e-3);  // beyond a millisecond acknowledgements time out
        },
        [](const NetworkSpec& n) {
          return n.delay == net::DelayModel::kRandom ? NumberNode(n.random_delay_max) : YAML::Node();
        });
    f.Choice<net::Routing>("routing", Member(&NetworkSpec::routing),
                           {{"aodv", net::Routing::kAodv},
                            {"olsr", net::Routing::kOlsr},
                            {"dsdv", net::Routing::kDsdv},
                            {"dsr", net::Routing::kDsr},
                            {"none", net::Routing::kNone}},
                           "routing protocol (ns-3's), or one hop only");
    f.Flag("aodv_hello", Member(&NetworkSpec::aodv_hello), "AODV's hello messages (neighbour sensing)");
    f.Whole<int>("flood_ttl", Member(&NetworkSpec::flood_ttl), "hops", 1, 255, "how far a flood travels");
    f.Number("broadcast_jitter", Member(&NetworkSpec::broadcast_jitter), "s", 0, 10,
             "a broadcast waits a uniform random time up to this before it is sent");
    f.Custom({"port", "whole number", "", "", "[1, 65535], not 654, 698 or 269 (AODV, OLSR, DSDV)",
              "UDP port of controller messages"},
             ReadPort, [](const NetworkSpec& n) { return YAML::Node(static_cast<int>(n.port)); });
    RadioKinds(f);
    TraceFlags(f);
    f.Custom({"ns3", "mapping", "", "none", "ns-3 attribute names to values, see [ns-3 attributes](#ns-3-attributes)",
              "defaults of ns-3's own attributes (routing, MAC, PHY, channel)"},
             ReadNs3, PrintNs3);
    return f;
  }();
  return fields;
}

const Fields<net::NetworkSpec>& PropagationFields() {
  using net::NetworkSpec;
  static const Fields<NetworkSpec> fields = [] {
    Fields<NetworkSpec> f;
    f.Choice<net::LossModel>("model", Member(&NetworkSpec::loss),
                             {{"log_distance", net::LossModel::kLogDistance},
                              {"friis", net::LossModel::kFriis},
                              {"two_ray_ground", net::LossModel::kTwoRayGround}},
                             "path loss model");
    f.Number("exponent", Member(&NetworkSpec::exponent), "", 1, 10, "`log_distance` only");
    f.Number("reference_loss", Member(&NetworkSpec::reference_loss), "dB", 0, 200, "`log_distance` only");
    f.Number("reference_distance", Member(&NetworkSpec::reference_distance), "m", 0, 1e6, "`log_distance` only", true);
    f.Number("antenna_height", Member(&NetworkSpec::antenna_height), "m", 0, 1000, "`two_ray_ground` only");
    f.Number("max_range", Member(&NetworkSpec::max_range), "m", 0, 1e7,
             "every model: nothing is received from farther (`0`: no cut-off)");
    f.Custom(ShadowingEntry(), ReadShadowing, PrintShadowing);
    f.Custom(FadingEntry(), ReadFading, PrintFading);
    return f;
  }();
  return fields;
}

const Fields<net::NetworkSpec>& ChannelFields() {
  using net::NetworkSpec;
  static const Fields<NetworkSpec> fields = [] {
    Fields<NetworkSpec> f;
    f.Choice<net::ChannelModel>("model", Member(&NetworkSpec::channel),
                                {{"indexed", net::ChannelModel::kIndexed}, {"yans", net::ChannelModel::kYans}},
                                "`indexed`: only radios where a frame arrives at `floor` or stronger get it; "
                                "`yans`: every radio (ns-3's YansWifiChannel)");
    f.Custom(
        {"floor", "number", "dBm", "9 dB under `rx_threshold` (`-91`); with fading 19 dB (`-101`)",
         "[-200, `rx_threshold`]; indexed only", "frames arriving weaker are not handed to the radio"},
        [](const Field& v, NetworkSpec& n) { n.channel_floor = v.Number(-200, 0); },
        [](const NetworkSpec& n) { return NumberNode(n.ChannelFloor()); });
    return f;
  }();
  return fields;
}

const Fields<sim::RunSpec>& MessagesFields() {
  using sim::RunSpec;
  static const Fields<RunSpec> fields = [] {
    Fields<RunSpec> f;
    f.Custom(
        {"latency", "number", "s", "`0.001`", "[0, 1000]; without a network only", "delay of the local transport"},
        [](const Field& v, RunSpec& s) {
          if (s.network) v.Fail("is for runs without a network; with one, the network delivers");
          s.message_latency = v.Number(0, 1000);
        },
        [](const RunSpec& s) { return s.network ? YAML::Node() : NumberNode(s.message_latency); });
    f.Number("loss", Member(&RunSpec::message_loss), "", 0, 1, "probability that a controller never gets a message");
    f.Number("delay", Member(&RunSpec::message_delay), "s", 0, 1000, "added before a controller gets a message");
    return f;
  }();
  return fields;
}

const Fields<sections::LinkShaping>& NetemFields() {
  using sections::LinkShaping;
  static const Fields<LinkShaping> fields = [] {
    Fields<LinkShaping> f;
    f.Number("delay", Member(&LinkShaping::delay), "s", 0, 60, "added to each agent's outgoing packets");
    f.Number("jitter", Member(&LinkShaping::jitter), "s", 0, 60, "spread of that delay");
    f.Number("loss", Member(&LinkShaping::loss), "", 0, 1, "probability that a packet is dropped");
    f.Number("rate", Member(&LinkShaping::rate), "bit/s", 0, 1e12, "link rate (`0`: no limit)");
    return f;
  }();
  return fields;
}

// A text field of a peer link (optional unless the declaration says so).
void PeerText(Fields<sections::PeerLink>& f, const char* key, std::string sections::PeerLink::*member,
              const char* range, const char* meaning) {
  f.Custom(
      {key, "text", "", "none", range, meaning},
      [member](const Field& v, sections::PeerLink& p) { p.*member = v.Text(); },
      [member](const sections::PeerLink& p) { return (p.*member).empty() ? YAML::Node() : YAML::Node(p.*member); });
}

const Fields<sections::PeerLink>& PeerFields() {
  static const Fields<sections::PeerLink> fields = [] {
    Fields<sections::PeerLink> f;
    PeerText(f, "robot", &sections::PeerLink::robot, "a robot with a controller", "whose agent this is");
    f.Required();
    PeerText(f, "address", &sections::PeerLink::address, "IPv4",
             "where its agent listens for the other agents (port: `udp_port` + the node's index)");
    PeerText(f, "interface", &sections::PeerLink::interface, "",
             "the network interface its agent binds its peer socket to (e.g. `wlan0`), taking its address "
             "unless `address` is given");
    return f;
  }();
  return fields;
}

const Fields<sections::LoopSpec>& LoopFields() {
  using sections::LoopSpec;
  static const Fields<LoopSpec> fields = [] {
    Fields<LoopSpec> f;
    f.Choice<sections::LoopNetwork>(
        "network", Member(&LoopSpec::network),
        {{"host", sections::LoopNetwork::kHost}, {"simulated", sections::LoopNetwork::kSimulated}},
        "what carries the agents' traffic to each other: the host's links, or the scenario's simulated radio "
        "(ns-3; each agent in its own namespace with an interface `radio0`; needs root)");
    f.Flag("namespaces", Member(&LoopSpec::namespaces),
           "one network namespace per agent (`sanet launch`); always with `network: simulated`");
    f.Custom(
        {"netem", "mapping", "", "none", "see [netem](#netem)", "shaping of each agent's link; needs `namespaces`"},
        [](const Field& v, LoopSpec& s) {
          if (s.network == sections::LoopNetwork::kSimulated)
            v.Fail("shapes the host's links; with network: simulated the simulated radio shapes them");
          if (!s.namespaces) v.Fail("shapes the links between namespaces: set loop.namespaces: true");
          NetemFields().Read(v, s.shaping);
        },
        [](const LoopSpec& s) {
          const bool shaped = s.namespaces && s.network != sections::LoopNetwork::kSimulated;
          return shaped ? NetemFields().Print(s.shaping) : YAML::Node();
        });
    f.Whole<std::uint16_t>("udp_port", Member(&LoopSpec::udp_port), "", 1024, 60000,
                           "loopback: node i uses this + i; namespaces: every node uses it");
    f.Custom(
        {"peers", "list of mappings", "", "none", "see [peers](#peers)",
         "agents on computers of their own: the robot-to-robot segment each one's agent uses"},
        [](const Field& v, LoopSpec& s) {
          for (const Field& item : v.Items()) PeerFields().Read(item, s.peers.emplace_back());
        },
        [](const LoopSpec& s) {
          YAML::Node items(YAML::NodeType::Sequence);
          for (const sections::PeerLink& p : s.peers) items.push_back(PeerFields().Print(p));
          return s.peers.empty() ? YAML::Node() : items;
        });
    return f;
  }();
  return fields;
}

const Fields<sections::Ros2Robot>& Ros2RobotFields() {
  using sections::Ros2Robot;
  static const Fields<Ros2Robot> fields = [] {
    Fields<Ros2Robot> f;
    f.Custom(
        {"robot", "text", "", kRequired, "a robot of the scenario", "whose topics these are"},
        [](const Field& v, Ros2Robot& r) { r.robot = v.Text(); },
        [](const Ros2Robot& r) { return YAML::Node(r.robot); });
    f.Custom(
        {"namespace", "text", "", "the robot's name", "letters, digits, `_`, `/` between names",
         "its topics' namespace and its frames' prefix: `/NS/odom`, frame `NS/base_link`"},
        [](const Field& v, Ros2Robot& r) { r.ns = v.Text(); },
        [](const Ros2Robot& r) { return r.ns.empty() ? YAML::Node() : YAML::Node(r.ns); });
    f.Number("rate", Member(&Ros2Robot::rate), "Hz", 0, 1000, "its sensor messages; 0: the section's `rate`");
    return f;
  }();
  return fields;
}

const Fields<sections::Ros2Spec>& Ros2Fields() {
  using sections::Ros2Spec;
  static const Fields<Ros2Spec> fields = [] {
    Fields<Ros2Spec> f;
    f.Custom(
        {"domain", "whole number", "", "`ROS_DOMAIN_ID`, else 0", "[0, 232]", "the DDS domain (ROS_DOMAIN_ID)"},
        [](const Field& v, Ros2Spec& s) { s.domain = static_cast<int>(v.Integer(0, 232)); },
        [](const Ros2Spec& s) { return s.domain < 0 ? YAML::Node() : YAML::Node(s.domain); });
    f.Number("rate", Member(&Ros2Spec::rate), "Hz", 0.1, 1000, "each robot's sensor messages (odom, scan, ranges, tf)");
    f.Choice<sections::CmdVelType>(
        "cmd_vel", Member(&Ros2Spec::cmd_vel),
        {{"twist", sections::CmdVelType::kTwist}, {"twist_stamped", sections::CmdVelType::kTwistStamped}},
        "the type cmd_vel takes: `geometry_msgs/msg/Twist`, or `TwistStamped` (as ROS 2 Jazzy's "
        "diff_drive_controller subscribes to it)");
    f.Choice<sections::Ros2Distro>(
        "distro", Member(&Ros2Spec::distro),
        {{"humble", sections::Ros2Distro::kHumble}, {"jazzy", sections::Ros2Distro::kJazzy}},
        "the ROS 2 release whose `ros2 node list` lists the face (its `ros_discovery_info`: Humble's, or Iron's and "
        "Jazzy's); topics are the same for both");
    f.Number("cmd_vel_timeout", Member(&Ros2Spec::cmd_vel_timeout), "s", 0, 3600,
             "a robot the face drives stops when no cmd_vel came for this long (as ROS 2's diff_drive_controller); "
             "0: it keeps the last command");
    f.Custom(
        {"robots", "list of mappings", "", "none", "see [ros2](#ros2)", "robots whose namespace or rate differ"},
        [](const Field& v, Ros2Spec& s) {
          for (const Field& item : v.Items()) Ros2RobotFields().Read(item, s.robots.emplace_back());
        },
        [](const Ros2Spec& s) {
          YAML::Node items(YAML::NodeType::Sequence);
          for (const sections::Ros2Robot& r : s.robots) items.push_back(Ros2RobotFields().Print(r));
          return s.robots.empty() ? YAML::Node() : items;
        });
    return f;
  }();
  return fields;
}

// An end condition's list of texts (a single text is a list of one).
void EndTexts(Fields<sim::RunSpec>& f, const char* key, std::vector<std::string> sim::RunSpec::*member,
              const std::string& what) {
  f.Custom(
      {key, "text or list of texts", "", "none", "", "counts when " + what},
      [member](const Field& v, sim::RunSpec& s) {
        if (v.IsScalar()) return (s.*member).push_back(v.Text());
        for (const Field& item : v.Items()) (s.*member).push_back(item.Text());
      },
      [member](const sim::RunSpec& s) {
        YAML::Node items(YAML::NodeType::Sequence);
        for (const std::string& item : s.*member) items.push_back(item);
        return (s.*member).empty() ? YAML::Node() : items;
      });
}

const Fields<sim::RunSpec>& EndFields() {
  using sim::RunSpec;
  static const Fields<RunSpec> fields = [] {
    Fields<RunSpec> f;
    EndTexts(f, "when_logged", &RunSpec::end_when_logged, "a controller logs exactly one of these lines");
    EndTexts(f, "when_transition", &RunSpec::end_when_transition, "a node enters one of these states");
    EndTexts(f, "when_metric", &RunSpec::end_when_metric, "a node reports one of these metrics");
    f.Whole<int>("count", Member(&RunSpec::end_count), "", 1, 1000000,
                 "the run ends when this many of those have happened, over all nodes");
    f.Number("grace", Member(&RunSpec::end_grace), "s", 0, 1e6,
             "the run goes on this long after, for messages in flight");
    return f;
  }();
  return fields;
}

namespace {

void ReadRegion(const Field& v, sections::SpawnSpec& s) {
  v.ExpectKeys({"min", "max"});
  const Vec2 low = ReadPoint(v.Require("min")), high = ReadPoint(v.Require("max"));
  if (!(low.x < high.x && low.y < high.y)) v.Require("max").Fail("must be above and to the right of 'min'");
  s.region = {low, high};
}

YAML::Node PrintRegion(const sections::SpawnSpec& s) {
  YAML::Node region;
  region["min"] = Numbers({s.region.first.x, s.region.first.y});
  region["max"] = Numbers({s.region.second.x, s.region.second.y});
  return region;
}

// `true`, `false` or `{silence_s: N}` (on, with its own silence).
void ReadRadioContacts(const Field& v, Scenario& s) {
  if (v.IsSequence()) v.Fail("must be true, false or a mapping {silence_s: N}, not a list");
  if (!v.IsMap()) return void(s.radio_contacts = v.Bool());
  v.ExpectKeys({"silence_s"});
  s.radio_contacts = true;
  if (auto silence = v.Get("silence_s")) s.run.contact_silence = silence->NumberAbove(0, 1e9);
}

YAML::Node PrintRadioContacts(const Scenario& s) {
  if (!s.run.radio_contacts) return YAML::Node(false);
  YAML::Node on;
  on["silence_s"] = NumberNode(s.run.contact_silence);
  return on;
}

}  // namespace

const Fields<sections::SpawnSpec>& SpawnFields() {
  using sections::SpawnSpec;
  static const Fields<SpawnSpec> fields = [] {
    Fields<SpawnSpec> f;
    f.Whole<std::size_t>("max", Member(&SpawnSpec::max), "", 0, 65534, "robots clients may add over the whole run");
    f.Custom({"region", "mapping `{min: [x, y], max: [x, y]}`", "m",
              "the field of `world.size` centred on the scenario's nodes and obstacles", "min below and left of max",
              "where a spawned robot may stand; INIT elsewhere is refused"},
             ReadRegion, PrintRegion);
    f.Custom({"classes", "list of classes (see below)", "",
              "USARBot.P2DX, USARBot.P2AT, USARBot.P3AT (diffdrive), "
              "sanet.DiffDrive, sanet.Omni3",
              "", "the robot classes INIT may name, and what each becomes"},
             nullptr, [](const SpawnSpec&) { return YAML::Node(); });
    return f;
  }();
  return fields;
}

const Fields<Scenario>& OutputsFields() {
  static const Fields<Scenario> fields = [] {
    Fields<Scenario> f;
    f.Custom(
        {"folder", "text", "", "`results/<name>`", "", "the results folder"},
        [](const Field& v, Scenario& s) { s.output_folder = v.Text(); },
        [](const Scenario& s) { return YAML::Node(s.output_folder); });
    f.Number(
        "trajectory_interval", [](Scenario& s) -> double& { return s.run.trajectory_interval; }, "s", 0, 1e6,
        "between trajectory samples; at least `world.physics_step`", true);
    f.Custom(
        {"energy_interval", "number", "s", "`10`", "(0, 1e9]",
         "between rows of `energy.csv` (with nodes that have `energy`)"},
        [](const Field& v, Scenario& s) { s.run.energy_interval = v.NumberAbove(0, 1e9); },
        [](const Scenario& s) {
          const auto& nodes = s.run.nodes;
          const bool energy = std::any_of(nodes.begin(), nodes.end(), [](const auto& n) { return n.energy; });
          return energy ? NumberNode(s.run.energy_interval) : YAML::Node();
        });
    f.Flag(
        "figures", [](Scenario& s) -> bool& { return s.run.figures; },
        "draw `map.svg` and `packets.svg` (and PNG copies); see [figures](#figures)");
    f.Number(
        "figure_tick", [](Scenario& s) -> double& { return s.run.figure_tick; }, "s", 0.1, 1e9,
        "between time marks on trajectories");
    f.Flag(
        "min_distance", [](Scenario& s) -> bool& { return s.run.min_distance; },
        "record the smallest distance between robots (`min_distance.csv`)");
    f.Custom(
        {"distance_reference", "number", "m", "none", "(0, 1e6]",
         "the summary says how long the smallest distance stayed within 10 % of it; sets `min_distance`"},
        [](const Field& v, Scenario& s) {
          s.run.distance_reference = v.NumberAbove(0, 1e6);
          s.run.min_distance = true;
        },
        [](const Scenario& s) {
          return s.run.distance_reference > 0 ? NumberNode(s.run.distance_reference) : YAML::Node();
        });
    f.Custom(
        {"trace", "boolean", "", "`true` for runs of up to 200 nodes", "",
         "write the trace of both worlds: `trace.sqlite` (docs/trace.md) and `trace.mcap`, ROS 2 messages for ROS 2 "
         "tools, Foxglove and PlotJuggler (docs/mcap.md); never changes the fingerprint"},
        [](const Field& v, Scenario& s) { s.trace = v.Bool(); },
        [](const Scenario& s) { return YAML::Node(s.run.trace); });
    f.Custom(
        {"radio_contacts", "boolean, or mapping `{silence_s: N}`", "s",
         "`true` for runs of up to 200 nodes, `silence_s: 15`", "silence_s in (0, 1e9]",
         "write `radio_contacts.csv`: each pair of nodes' contacts, from the frames their radios heard from each "
         "other, and their quartiles in summary.json (see [radio_contacts.csv](#radio_contactscsv)); a contact ends "
         "after more than `silence_s` without a frame; with a `network` only; never changes the fingerprint"},
        ReadRadioContacts, PrintRadioContacts);
    return f;
  }();
  return fields;
}

void DriveLimits(Fields<ModelSpec>& f, const char* speed_meaning, const char* turn_meaning) {
  f.Number("max_speed", Member(&ModelSpec::max_speed), "m/s", 0, 100, speed_meaning);
  f.Number("max_turn_rate", Member(&ModelSpec::max_turn_rate), "rad/s", 0, 100, turn_meaning);
}

Rgb ReadColor(const Field& v) {
  if (v.node().IsNull())
    v.Fail("is empty: write the colour in quotes, \"#rrggbb\" (without them YAML reads # as the start of a comment)");
  const auto color = ParseRgb(v.Text());
  if (!color) v.Fail("is not a colour: write \"#rrggbb\", red, green and blue in two hexadecimal digits each");
  return *color;
}

void BodyColor(Fields<ModelSpec>& f) {
  f.Custom(
      {"color", "text `\"#rrggbb\"`", "", "the model's", "", "what cameras see of the body"},
      [](const Field& v, ModelSpec& m) { m.color = ReadColor(v); },
      [](const ModelSpec& m) { return m.color ? YAML::Node(RgbText(*m.color)) : YAML::Node(); });
}

void BodyInertia(Fields<ModelSpec>& f, std::function<std::array<double, 3>&(ModelSpec&)> at) {
  f.Custom(
      {"body_inertia", "list `[ixx, iyy, izz]`", "kg·m²", "its shape's",
       "each > 0, none above the sum of the other two",
       "the chassis's principal moments of inertia about its centre of mass (from a URDF: `<inertia>`)"},
      [at](const Field& v, ModelSpec& m) {
        const std::vector<Field> items = v.IsSequence() ? v.Items() : std::vector<Field>{};
        if (items.size() != 3) v.Fail("must be a list of three moments [ixx, iyy, izz] in kg·m²");
        std::array<double, 3> moments{};
        for (std::size_t i = 0; i < 3; ++i) moments[i] = items[i].NumberAbove(0, 1e6);
        for (std::size_t i = 0; i < 3; ++i)
          if (moments[i] > moments[(i + 1) % 3] + moments[(i + 2) % 3] + 1e-12)
            v.Fail("no body has these moments: each must be at most the sum of the other two");
        at(m) = moments;
      },
      [at](const ModelSpec& m) {
        const std::array<double, 3>& moments = at(const_cast<ModelSpec&>(m));
        return moments[2] > 0 ? Numbers({moments[0], moments[1], moments[2]}) : YAML::Node();
      });
}

const Fields<ModelSpec>& BodyFields(ModelKind kind) {
  switch (kind) {
#define SANET_BODY_FIELDS_CASE(name, Name, kind) \
  case ModelKind::kind:                          \
    return Name##BodyFields();
    SANET_ROBOT_MODELS(SANET_BODY_FIELDS_CASE)
#undef SANET_BODY_FIELDS_CASE
  }
  return MoteBodyFields();
}

namespace {

void ReadDutyCycle(const Field& v, net::NodeRadio& r) {
  if (!v.IsMap()) v.Fail("must be a mapping {period_s, awake_s, phase_s}");
  v.ExpectKeys({"period_s", "awake_s", "phase_s"});
  net::DutyCycle cycle;
  cycle.period = v.Require("period_s").NumberAbove(0, 1e6);
  cycle.awake = v.Require("awake_s").NumberAbove(0, cycle.period);
  if (auto phase = v.Get("phase_s"); phase && phase->IsScalar() && phase->node().Scalar() == "random") {
    cycle.random_phase = true;
  } else if (phase) {
    cycle.phase = phase->Number(0, cycle.period);
    if (cycle.phase >= cycle.period)
      phase->Fail("must be under period_s (" + ShortNumber(cycle.period) + "), or random");
  }
  r.duty_cycle = cycle;
}

YAML::Node PrintDutyCycle(const net::NodeRadio& r) {
  if (!r.duty_cycle) return YAML::Node();
  YAML::Node cycle;
  cycle["period_s"] = NumberNode(r.duty_cycle->period);
  cycle["awake_s"] = NumberNode(r.duty_cycle->awake);
  cycle["phase_s"] = r.duty_cycle->random_phase ? YAML::Node("random") : NumberNode(r.duty_cycle->phase);
  cycle.SetStyle(YAML::EmitterStyle::Flow);
  return cycle;
}

}  // namespace

const Fields<net::NodeRadio>& RadioFields() {
  static const Fields<net::NodeRadio> fields = [] {
    Fields<net::NodeRadio> f;
    f.Custom(NodeStandardEntry(), ReadNodeStandard, PrintNodeStandard);
    f.Custom(NodeTxPowerEntry(), ReadNodeTxPower, PrintNodeTxPower);
    f.Custom(
        {"antenna_height", "number", "m", "`0`", "[0, 1000]",
         "the antenna above the node's centre, for the walls between antennas only (path loss keeps its distances)"},
        [](const Field& v, net::NodeRadio& r) { r.antenna_height = v.Number(0, 1000); },
        [](const net::NodeRadio& r) { return r.antenna_height > 0 ? NumberNode(r.antenna_height) : YAML::Node(); });
    f.Custom(
        {"duty_cycle", "mapping `{period_s, awake_s, phase_s}`", "s", "none: always awake; phase_s `0`",
         "period_s in (0, 1e6], awake_s in (0, period_s], phase_s in [0, period_s) or `random`",
         "the radio is awake `awake_s` of every `period_s`, from `phase_s` on (`random`: each node's drawn "
         "from the seed), and asleep (802.11 sleep, `energy.radio.sleep_a`; an 802.15.4 radio's receiver off, "
         "`energy.lr_wpan_radio.sleep_a`) the rest; frames an 802.11 radio is given while asleep "
         "wait in the MAC's queue, an 802.15.4 radio sends them at once (see [duty cycles](energy.md#duty-cycles))"},
        ReadDutyCycle, PrintDutyCycle);
    return f;
  }();
  return fields;
}

namespace {

// A parameter as it was written: a scalar, a list, or a table of scalars.
YAML::Node ParamNode(const ParamValue& value) {
  const auto row = [](const std::vector<std::string>& cells) {
    YAML::Node out(YAML::NodeType::Sequence);
    for (const std::string& cell : cells) out.push_back(cell);
    out.SetStyle(YAML::EmitterStyle::Flow);
    return out;
  };
  if (value.shape == ParamValue::Shape::kScalar) return YAML::Node(value.rows.at(0).at(0));
  if (value.shape == ParamValue::Shape::kList) return row(value.rows.at(0));
  YAML::Node table(YAML::NodeType::Sequence);
  for (const auto& r : value.rows) table.push_back(row(r));
  table.SetStyle(YAML::EmitterStyle::Flow);
  return table;
}

}  // namespace

const Fields<sim::ControllerSpec>& ControllerFields() {
  using sim::ControllerSpec;
  static const Fields<ControllerSpec> fields = [] {
    Fields<ControllerSpec> f;
    f.Custom(
        {"name", "text", "", "required unless `python`", "a built-in controller, or one registered by `library`",
         "the controller's registered name"},
        [](const Field& v, ControllerSpec& c) { c.name = v.Text(); },
        [](const ControllerSpec& c) { return c.python.empty() ? YAML::Node(c.name) : YAML::Node(); });
    f.Custom({"python", "text", "", "none",
              "MODULE:CLASS; the module in the scenario file's folder, on `--python-path` or on PYTHONPATH",
              "a controller written in Python instead ([python.md](python.md))"},
             nullptr,  // the loader checks it with `name` and `library`
             [](const ControllerSpec& c) { return c.python.empty() ? YAML::Node() : YAML::Node(c.python); });
    f.Custom({"library", "text (path)", "", "none",
              "must exist when the file is loaded; a relative path is taken from the scenario file's folder",
              "a controller library to load first"},
             nullptr,  // the loader resolves the path against the scenario's folder
             [](const ControllerSpec& c) { return c.library.empty() ? YAML::Node() : YAML::Node(c.library); });
    f.Number("rate", Member(&ControllerSpec::rate), "Hz", 0, 10000, "control steps per second", true);
    f.Custom({"params", "mapping", "", "none", "read by the controller", "the controller's parameters"}, nullptr,
             [](const ControllerSpec& c) {
               YAML::Node params(YAML::NodeType::Map);
               for (const auto& [key, value] : c.params.All()) params[key] = ParamNode(value);
               return c.params.All().empty() ? YAML::Node() : params;
             });
    return f;
  }();
  return fields;
}

}  // namespace sanet::scenario

namespace sanet::scenario {

std::string ReadName(const Field& f) {
  const std::string name = f.Text();
  for (char c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-' && c != '.')
      f.Fail("'" + name + "' may hold only letters, digits, '_', '-' and '.'");
  if (name == "." || name == "..") f.Fail("'" + name + "' is not a name");
  return name;
}

namespace {

template <typename S>
std::function<YAML::Node(const S&)> Unprinted() {
  return [](const S&) { return YAML::Node(); };
}

template <typename S>
std::function<void(const Field&, S&)> ReadPointInto(Vec2 S::*m) {
  return [m](const Field& v, S& s) { s.*m = ReadPoint(v); };
}

}  // namespace

namespace {

// What every obstacle may say about the radio (docs/network.md#walls).
template <typename S>
void AddObstacleRadioFields(Fields<S>& f) {
  f.Custom(
      {"material", "text", "", "`world.obstacle_material`", MaterialList("`"),
       "what it is made of: its loss per crossing is its slab loss at its thickness and the radio's band"},
      [](const Field& v, S& s) { s.radio.material = ReadMaterial(v); }, Unprinted<S>());
  f.Custom(
      {"radio_loss_db", "number", "dB", "the material's", "[0, 1000]; not with `material`",
       "loss of a frame per crossing, given outright"},
      [](const Field& v, S& s) { s.radio.loss_db = v.Number(0, 1000); }, Unprinted<S>());
  f.Custom(
      {"radio_loss_db_per_m", "number", "dB/m", "`0`", "[0, 1000]",
       "loss per metre of the path inside it, added to the loss per crossing"},
      [](const Field& v, S& s) { s.radio.loss_db_per_m = v.Number(0, 1000); }, Unprinted<S>());
  f.Custom(
      {"indoor", "`true` or `false`", "", "`false`", "",
       "part of a building: no satellite fix inside it (see [world.gnss_denied](#satellite-fixes))"},
      [](const Field& v, S& s) { s.indoor = v.Bool(); }, Unprinted<S>());
  f.Custom(
      {"color", "text `\"#rrggbb\"`", "", "`\"#969696\"`", "", "what cameras see of it"},
      [](const Field& v, S& s) { s.color = ReadColor(v); }, Unprinted<S>());
}

}  // namespace

const Fields<BoxSettings>& BoxFields() {
  static const Fields<BoxSettings> fields = [] {
    Fields<BoxSettings> f;
    f.Custom({"center", "point `[x, y]`", "m", kRequired, "any", "the middle of the box, on the ground"},
             ReadPointInto(&BoxSettings::center), Unprinted<BoxSettings>());
    f.Custom(
        {"size", "list of 3 numbers `[length, width, height]`", "m", kRequired, "each > 0",
         "`length` runs along `yaw`"},
        [](const Field& v, BoxSettings& b) {
          b.size = v.Numbers(3);
          for (double side : b.size)
            if (side <= 0) v.Fail("every side must be greater than 0");
        },
        Unprinted<BoxSettings>());
    f.Number("yaw", Member(&BoxSettings::yaw), "rad", -kInf, kInf, "counter-clockwise from +x");
    AddObstacleRadioFields(f);
    return f;
  }();
  return fields;
}

const Fields<WallSettings>& WallFields() {
  static const Fields<WallSettings> fields = [] {
    Fields<WallSettings> f;
    f.Custom({"from", "point `[x, y]`", "m", kRequired, "any", "one end"}, ReadPointInto(&WallSettings::from),
             Unprinted<WallSettings>());
    f.Custom(
        {"to", "point `[x, y]`", "m", kRequired, "at least 1e-6 m from `from`", "the other end"},
        [](const Field& v, WallSettings& w) {
          w.to = ReadPoint(v);
          if (Norm(w.to - w.from) < 1e-6) v.Fail("a wall's two ends must differ");
        },
        Unprinted<WallSettings>());
    f.Number("height", Member(&WallSettings::height), "m", 0, 1000, "", true);
    f.Number("thickness", Member(&WallSettings::thickness), "m", 0, 1000, "split evenly on both sides of the line",
             true);
    AddObstacleRadioFields(f);
    return f;
  }();
  return fields;
}

const Fields<GridSettings>& GridFields() {
  static const Fields<GridSettings> fields = [] {
    Fields<GridSettings> f;
    f.Custom(
        {"name", "text", "", kRequired, "letters, digits, `_`, `-`, `.`", "name prefix: nodes NAME0, NAME1, ..."},
        [](const Field& v, GridSettings& g) { g.name = ReadName(v); }, Unprinted<GridSettings>());
    f.Whole<int>("rows", Member(&GridSettings::rows), "", 1, 10000, "along +y").Required();
    f.Whole<int>("cols", Member(&GridSettings::cols), "", 1, 10000, "along +x").Required();
    f.Custom({"origin", "point `[x, y]`", "m", "`[0, 0]`", "any", "where node 0 stands"},
             ReadPointInto(&GridSettings::origin), Unprinted<GridSettings>());
    f.Custom(
        {"spacing", "number, or point `[dx, dy]`", "m", "`[1, 1]`", "> 0; a single number ≤ 1e6",
         "between columns and rows"},
        [](const Field& v, GridSettings& g) {
          g.spacing = v.IsSequence() ? ReadPoint(v) : Vec2{v.Number(0, 1e6), v.Number(0, 1e6)};
          if (g.spacing.x <= 0 || g.spacing.y <= 0) v.Fail("spacing must be greater than 0");
        },
        Unprinted<GridSettings>());
    f.Number("heading", Member(&GridSettings::heading), "rad", -kInf, kInf, "every node's heading");
    return f;
  }();
  return fields;
}

const Fields<EventSettings>& EventFields() {
  static const Fields<EventSettings> fields = [] {
    Fields<EventSettings> f;
    f.Number("time", Member(&EventSettings::time), "s", 0, 1e9, "when it happens").Required();
    f.Custom(
        {"node", "text", "", kRequired, "a node's name", "to whom"},
        [](const Field& v, EventSettings& e) { e.node = v.Text(); }, Unprinted<EventSettings>());
    f.Choice<sim::NodeEvent::Action>(
         "action", Member(&EventSettings::action),
         {{"switch_off", sim::NodeEvent::Action::kSwitchOff}, {"recharge", sim::NodeEvent::Action::kRecharge}},
         "`switch_off`: the node's controller stops, its motors stop and its radio goes off (ns-3's Wi-Fi off mode), "
         "for good; `recharge`: energy goes into the node's battery (it needs `energy`), and a node dead of an empty "
         "battery comes back once above its `revive` level (docs/energy.md)")
        .Required();
    f.Custom(
        {"energy_j", "number", "J", "to full", "(0, 1e12]", "with `recharge`: the energy added (never past full)"},
        [](const Field& v, EventSettings& e) { e.energy_j = v.NumberAbove(0, 1e12); },
        [](const EventSettings& e) { return e.energy_j ? NumberNode(*e.energy_j) : YAML::Node(); });
    return f;
  }();
  return fields;
}

namespace {

Fields<Keys>& Key(Fields<Keys>& f, const char* key, const char* type, const char* default_text, const char* meaning) {
  return f.Custom({key, type, "", default_text, "", meaning}, nullptr, Unprinted<Keys>());
}

// Keys of a node, declared again for a section that takes them too.
void NodeKeys(Fields<Keys>& f, std::initializer_list<const char*> keys, const char* meaning) {
  const std::vector<FieldInfo> node = NodeFields().Describe(Keys{});
  for (const char* key : keys)
    for (const FieldInfo& i : node)
      if (i.key == key) Key(f, key, i.type.c_str(), i.default_text.c_str(), meaning);
}

}  // namespace

const Fields<Scenario>& TopLevelFields() {
  static const Fields<Scenario> fields = [] {
    Fields<Scenario> f;
    const auto section = [&](const char* key, const char* type, const char* default_text, const char* meaning) {
      f.Custom({key, type, "", default_text, "", meaning}, nullptr, Unprinted<Scenario>());
    };
    f.Custom(
        {"name", "text", "", "the file name without its extension", "letters, digits, `_`, `-`, `.`",
         "names the run and its results folder"},
        [](const Field& v, Scenario& sc) { sc.run.name = ReadName(v); }, Unprinted<Scenario>());
    f.Custom(
        {"seed", "whole number", "", "`1`", "[0, 2^64)", "seeds every random stream of the run"},
        [](const Field& v, Scenario& sc) { sc.run.seed = v.Unsigned(); }, Unprinted<Scenario>());
    f.Number(
         "duration", [](Scenario& sc) -> double& { return sc.run.duration; }, "s", 0, 1e9, "simulated time", true)
        .Required();
    section("world", "mapping", "see [world](#world)", "field, physics, obstacles");
    section("network", "mapping", "no network", "ns-3's radios and routing; without it messages are delivered locally");
    section("nodes", "list, at least one node", kRequired, "see [nodes](#nodes)");
    section("messages", "mapping", "see [messages](#messages)", "impairments and the local transport");
    section("events", "list", "none", "see [events](#events)");
    section("end", "mapping", "the run lasts `duration`", "see [end](#end)");
    section("loop", "mapping", "see [loop](#loop)", "how `sanet launch` links its agents");
    section("spawn", "mapping", "no spawning",
            "robots that clients of `sanet serve` may add with INIT; see [spawn](#spawn)");
    section("ros2", "mapping", "no ROS 2 face unless `sanet serve --ros2`",
            "`sanet serve` makes the robots ROS 2 robots over DDS; see [ros2](#ros2)");
    section("outputs", "mapping", "see [outputs](#outputs)", "what is written where");
    return f;
  }();
  return fields;
}

const Fields<Keys>& NodeFields() {
  static const Fields<Keys> fields = [] {
    Fields<Keys> f;
    Key(f, "name", "text", kRequired, "unique; letters, digits, `_`, `-`, `.`");
    Key(f, "model", "`mote`, `omni3` or `diffdrive`", kRequired, "see [model](#model)");
    Key(f, "pose", "`[x, y, theta]`", kRequired, "m, m, rad; the node starts on the ground");
    Key(f, "body", "mapping", "the model's", "overrides the model's dimensions; see [body](#body)");
    Key(f, "sensors", "mapping", "the model's", "adds, changes or removes sensors; see [sensors](#sensors)");
    Key(f, "radio", "mapping", "the network's", "this node's radio settings; see [radio](#radio)");
    Key(f, "energy", "mapping", "none: an infinite supply",
        "a battery, and what draws on it; see [energy](#energy) and docs/energy.md");
    Key(f, "controller", "mapping", "none", "without one, a node only acts when something pushes it");
    return f;
  }();
  return fields;
}

namespace {

// `region: {min: [x, y], max: [x, y]}` or `region: {polygon: [[x, y], ...]}`.
void ReadScatterRegion(const Field& v, ScatterSettings& s) {
  if (const auto polygon = v.Get("polygon")) {
    v.ExpectKeys({"polygon"});
    for (const Field& corner : polygon->Items()) s.region.polygon.push_back(ReadPoint(corner));
    if (s.region.polygon.size() < 3) polygon->Fail("a polygon needs three corners or more");
    s.region.min = s.region.max = s.region.polygon.front();
    for (Vec2 p : s.region.polygon) {
      s.region.min = {std::min(s.region.min.x, p.x), std::min(s.region.min.y, p.y)};
      s.region.max = {std::max(s.region.max.x, p.x), std::max(s.region.max.y, p.y)};
    }
    if (s.region.Area() <= 0) polygon->Fail("its corners enclose no area");
    return;
  }
  v.ExpectKeys({"min", "max"});
  s.region.min = ReadPoint(v.Require("min"));
  s.region.max = ReadPoint(v.Require("max"));
  if (!(s.region.min.x < s.region.max.x && s.region.min.y < s.region.max.y))
    v.Require("max").Fail("must be above and to the right of 'min'");
}

}  // namespace

const Fields<ScatterSettings>& ScatterFields() {
  static const Fields<ScatterSettings> fields = [] {
    Fields<ScatterSettings> f;
    f.Custom(
        {"name", "text", "", kRequired, "letters, digits, `_`, `-`, `.`", "name prefix: nodes NAME0, NAME1, ..."},
        [](const Field& v, ScatterSettings& s) { s.name = ReadName(v); }, Unprinted<ScatterSettings>());
    f.Choice<ScatterDistribution>("distribution", Member(&ScatterSettings::distribution),
                                  {{"uniform", ScatterDistribution::kUniform},
                                   {"poisson", ScatterDistribution::kPoisson},
                                   {"clustered", ScatterDistribution::kClustered}},
                                  "`count` nodes uniformly; a Poisson number at `density`; or Thomas clusters");
    f.Custom(
        {"count", "whole number", "", "none", "[1, 100000]; uniform only", "how many nodes"},
        [](const Field& v, ScatterSettings& s) { s.count = v.Integer(1, 100000); }, Unprinted<ScatterSettings>());
    f.Custom(
        {"density", "number", "nodes/m²", "none", "(0, 1000]; poisson only",
         "mean nodes per square metre: the count is drawn, mean density × area"},
        [](const Field& v, ScatterSettings& s) { s.density = v.NumberAbove(0, 1000); }, Unprinted<ScatterSettings>());
    f.Custom({"region", "mapping `{min: [x, y], max: [x, y]}` or `{polygon: [[x, y], ...]}`", "m", kRequired,
              "min below and left of max; a polygon of three corners or more", "where the nodes may stand"},
             ReadScatterRegion, Unprinted<ScatterSettings>());
    f.Number("min_separation", Member(&ScatterSettings::min_separation), "m", 0, 1e6,
             "least distance between two of the item's nodes (their bodies never overlap in any case)");
    f.Custom(
        {"seed", "whole number", "", "the run's", "[0, 2^64)",
         "draw the positions from this seed: the same deployment in every run"},
        [](const Field& v, ScatterSettings& s) { s.seed = v.Unsigned(); }, Unprinted<ScatterSettings>());
    const auto clustered = [&](const char* key, double ScatterSettings::*at, const char* unit, double max,
                               const char* meaning) {
      f.Custom(
          {key, "number", unit, "none", "(0, " + ShortNumber(max) + "]; clustered only", meaning},
          [=](const Field& v, ScatterSettings& s) { s.*at = v.NumberAbove(0, max); }, Unprinted<ScatterSettings>());
    };
    clustered("parent_density", &ScatterSettings::parent_density, "1/m²", 1e3, "cluster centres per square metre");
    clustered("per_cluster", &ScatterSettings::per_cluster, "", 1e5, "mean nodes per cluster");
    clustered("cluster_sigma", &ScatterSettings::cluster_sigma, "m", 1e6,
              "deviation of a node's offset from its centre, each axis");
    return f;
  }();
  return fields;
}

ScatterSettings ReadScatter(const Field& f) {
  ScatterSettings s;
  ScatterFields().Read(f, s);
  using D = ScatterDistribution;
  const std::pair<const char*, D> only[] = {{"count", D::kUniform},
                                            {"density", D::kPoisson},
                                            {"parent_density", D::kClustered},
                                            {"per_cluster", D::kClustered},
                                            {"cluster_sigma", D::kClustered}};
  const char* const names[] = {"uniform", "poisson", "clustered"};
  for (const auto& [key, distribution] : only) {
    const auto given = f.Get(key);
    if (given && s.distribution != distribution)
      given->Fail(std::string("applies to `distribution: ") + names[static_cast<int>(distribution)] + "` only");
    if (!given && s.distribution == distribution)
      f.Fail(std::string("`distribution: ") + names[static_cast<int>(distribution)] + "` needs `" + key + "`");
  }
  return s;
}

const Fields<Keys>& GridItemFields() {
  static const Fields<Keys> fields = [] {
    Fields<Keys> f;
    Key(f, "grid", "mapping", kRequired, "see the table below");
    NodeKeys(f, {"model", "body", "sensors", "radio", "energy", "controller"},
             "as for a single node; shared by the grid's nodes");
    return f;
  }();
  return fields;
}

const Fields<Keys>& ScatterItemFields() {
  static const Fields<Keys> fields = [] {
    Fields<Keys> f;
    Key(f, "scatter", "mapping", kRequired, "see the table below");
    NodeKeys(f, {"model", "body", "sensors", "radio", "energy", "controller"},
             "as for a single node; shared by the scattered nodes");
    return f;
  }();
  return fields;
}

const Fields<Keys>& SpawnClassFields() {
  static const Fields<Keys> fields = [] {
    Fields<Keys> f;
    Key(f, "class", "text", kRequired, "the class name INIT gives in {ClassName}, matched without regard to case");
    Key(f, "model", "`omni3` or `diffdrive`", kRequired, "see [model](#model); a spawned robot is no mote");
    NodeKeys(f, {"body", "sensors", "radio", "energy"}, "as for a node");
    return f;
  }();
  return fields;
}

std::vector<SectionTable> SectionTables() {
  std::vector<SectionTable> tables = {
      {"top", TopLevelFields().Describe(Scenario{})},
      {"world", WorldFields().Describe(sim::RunSpec{})},
      {"obstacles.box", BoxFields().Describe(BoxSettings{})},
      {"obstacles.wall", WallFields().Describe(WallSettings{})},
      {"network", NetworkFields().Describe(net::NetworkSpec{})},
      {"network.propagation", PropagationFields().Describe(net::NetworkSpec{})},
      {"network.propagation.shadowing", ShadowingFields().Describe(net::NetworkSpec{})},
      {"network.propagation.fading", FadingFields().Describe(net::NetworkSpec{})},
      {"network.hardware_spread", HardwareSpreadFields().Describe(net::NetworkSpec{})},
      {"network.channel", ChannelFields().Describe(net::NetworkSpec{})},
      {"network.lr_wpan", LrWpanFields().Describe(net::LrWpanSpec{})},
      {"nodes.node", NodeFields().Describe(Keys{})},
      {"nodes.grid_item", GridItemFields().Describe(Keys{})},
      {"nodes.grid", GridFields().Describe(GridSettings{})},
      {"nodes.scatter_item", ScatterItemFields().Describe(Keys{})},
      {"nodes.scatter", ScatterFields().Describe(ScatterSettings{})},
      {"radio", RadioFields().Describe(net::NodeRadio{})},
      {"energy", EnergyFields().Describe(energy::EnergySpec{})},
      {"energy.radio", RadioEnergyFields().Describe(energy::EnergySpec{})},
      {"energy.lr_wpan_radio", LrWpanRadioEnergyFields().Describe(energy::EnergySpec{})},
      {"energy.wireless_charger", WirelessChargerFields().Describe(energy::WirelessCharger{})},
      {"world.chargers", ChargerFields().Describe(sim::Charger{})},
      {"controller", ControllerFields().Describe(sim::ControllerSpec{})},
      {"messages", MessagesFields().Describe(sim::RunSpec{})},
      {"events", EventFields().Describe(EventSettings{})},
      {"end", EndFields().Describe(sim::RunSpec{})},
      {"loop", LoopFields().Describe(sections::LoopSpec{})},
      {"loop.netem", NetemFields().Describe(sections::LinkShaping{})},
      {"loop.peers", PeerFields().Describe(sections::PeerLink{})},
      {"spawn", SpawnFields().Describe(sections::SpawnSpec{})},
      {"spawn.class", SpawnClassFields().Describe(Keys{})},
      {"ros2", Ros2Fields().Describe(sections::Ros2Spec{})},
      {"ros2.robots", Ros2RobotFields().Describe(sections::Ros2Robot{})},
      {"outputs", OutputsFields().Describe(Scenario{})},
  };
  // Each model's body (src/models/<model>/<model>_fields.cc), then each sensor kind's
  // (scenario/sensor_fields.h), before the radio's.
  std::vector<SectionTable> parts;
  for (ModelKind kind : robots::AllModels())
    parts.push_back(
        {std::string("body.") + robots::ModelName(kind), BodyFields(kind).Describe(ModelSpec::Defaults(kind))});
  for (auto& [name, fields] : SensorTables()) parts.push_back({name, std::move(fields)});
  const auto radio =
      std::find_if(tables.begin(), tables.end(), [](const SectionTable& t) { return t.name == "radio"; });
  tables.insert(radio, parts.begin(), parts.end());
  return tables;
}

}  // namespace sanet::scenario
