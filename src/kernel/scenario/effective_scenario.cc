#include "scenario/effective_scenario.h"

#include "core/fingerprint.h"
#include "scenario/declarations.h"
#include "scenario/energy_fields.h"
#include "scenario/sensor_fields.h"
#include "scenario/urdf_body.h"

namespace sanet::scenario {
namespace {

// model, body, sensors and radio, as a node and a spawn class give them.
void PutRobot(YAML::Node& out, const robots::ModelSpec& model, const net::NodeRadio& radio,
              const std::optional<energy::EnergySpec>& energy, bool has_network) {
  out["model"] = robots::ModelName(model.kind);
  out["body"] = BodyFields(model.kind).Print(model);
  YAML::Node body = out["body"];
  PrintUrdfBody(model, body);
  out["sensors"] = PrintSensors(model);
  const bool own_radio =
      radio.radios || radio.tx_power || radio.lr_wpan_tx_power || radio.antenna_height > 0 || radio.duty_cycle;
  if (has_network && own_radio) out["radio"] = RadioFields().Print(radio);
  if (energy) out["energy"] = EnergyFields().Print(*energy);
}

YAML::Node Node(const sim::NodeSpec& n, bool has_network) {
  YAML::Node out;
  out["name"] = n.name;
  YAML::Node pose(YAML::NodeType::Sequence);
  for (double v : {n.pose.x, n.pose.y, n.pose.theta}) pose.push_back(NumberNode(v));
  pose.SetStyle(YAML::EmitterStyle::Flow);
  out["pose"] = pose;
  PutRobot(out, n.model, n.radio, n.energy, has_network);
  if (n.controller) out["controller"] = ControllerFields().Print(*n.controller);
  return out;
}

YAML::Node Spawn(const sections::SpawnSpec& spawn, bool has_network) {
  YAML::Node out = SpawnFields().Print(spawn);
  YAML::Node classes(YAML::NodeType::Sequence);
  for (const sections::SpawnClass& c : spawn.classes) {
    YAML::Node item;
    item["class"] = c.usarsim_class;
    PutRobot(item, c.model, c.radio, c.energy, has_network);
    classes.push_back(item);
  }
  out["classes"] = classes;
  return out;
}

YAML::Node Events(const sim::RunSpec& run) {
  YAML::Node events(YAML::NodeType::Sequence);
  for (const sim::NodeEvent& e : run.events) {
    YAML::Node event;
    event["time"] = NumberNode(e.time);
    event["node"] = run.nodes.at(e.node).name;
    event["action"] = e.action == sim::NodeEvent::Action::kRecharge ? "recharge" : "switch_off";
    if (e.energy_j) event["energy_j"] = NumberNode(*e.energy_j);
    events.push_back(event);
  }
  return events;
}

std::string EffectiveBody(const Scenario& sc) {
  const sim::RunSpec& run = sc.run;
  YAML::Node root;
  root["name"] = run.name;
  root["seed"] = run.seed;
  root["duration"] = NumberNode(run.duration);
  root["world"] = WorldFields().Print(run);
  if (run.network) root["network"] = NetworkFields().Print(*run.network);
  root["messages"] = MessagesFields().Print(run);
  if (!run.events.empty()) root["events"] = Events(run);
  if (run.HasEndCondition()) root["end"] = EndFields().Print(run);
  root["loop"] = LoopFields().Print(sc.loop);
  if (sc.spawn) root["spawn"] = Spawn(*sc.spawn, run.network.has_value());
  if (sc.ros2) root["ros2"] = Ros2Fields().Print(*sc.ros2);
  root["outputs"] = OutputsFields().Print(sc);
  YAML::Node nodes(YAML::NodeType::Sequence);
  for (const sim::NodeSpec& n : run.nodes) nodes.push_back(Node(n, run.network.has_value()));
  root["nodes"] = nodes;
  YAML::Emitter out;
  out << root;
  return std::string(out.c_str()) + "\n";
}

std::string Head(const Scenario& sc) {
  std::string head = "# The effective scenario of " + sc.file;
  for (const Override& o : sc.overrides) head += " --set " + o.text;
  for (char& c : head)
    if (c == '\n' || c == '\r') c = ' ';  // one comment line, whatever the values hold
  return head + ": every default of the format filled in.\n";
}

std::string FingerprintOf(const std::string& body) {
  Fingerprint f;
  f.Add(body);
  return f.Hex();
}

}  // namespace

EffectiveScenario Effective(const Scenario& sc) {
  const std::string body = EffectiveBody(sc);
  return {Head(sc) + body, FingerprintOf(body)};
}

std::string EffectiveScenarioYaml(const Scenario& sc) { return Head(sc) + EffectiveBody(sc); }

std::string ScenarioFingerprint(const Scenario& sc) { return FingerprintOf(EffectiveBody(sc)); }

}  // namespace sanet::scenario
