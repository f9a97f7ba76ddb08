#include "scenario/effective_scenario.h"

#include "scenario/declarations.h"

namespace sanet::scenario {
namespace {

YAML::Node Sensors(const robots::ModelSpec& m) {
  YAML::Node out;
  const robots::SensorSuite& s = m.sensors;
  out["ir"] = s.ir ? IrFields().Print(IrSettingsOf(*s.ir)) : YAML::Node(false);
  out["laser"] = s.laser ? LaserFields().Print(LaserSettingsOf(*s.laser)) : YAML::Node(false);
  if (m.kind != robots::ModelKind::kMote) out["odometry"] = OdometryFields().Print(s);
  out["ground_truth"] = GroundTruthFields().Print(s);
  if (s.bearing) out["bearing"] = BearingFields().Print(*s.bearing);
  return out;
}

YAML::Node Node(const sim::NodeSpec& n, bool has_network) {
  YAML::Node out;
  out["name"] = n.name;
  out["model"] = robots::ModelName(n.model.kind);
  YAML::Node pose(YAML::NodeType::Sequence);
  for (double v : {n.pose.x, n.pose.y, n.pose.theta}) pose.push_back(NumberNode(v));
  pose.SetStyle(YAML::EmitterStyle::Flow);
  out["pose"] = pose;
  out["body"] = BodyFields(n.model.kind).Print(n.model);
  out["sensors"] = Sensors(n.model);
  if (has_network && n.radio.tx_power) out["radio"] = RadioFields().Print(n.radio);
  if (n.controller) out["controller"] = ControllerFields().Print(*n.controller);
  return out;
}

YAML::Node Events(const sim::RunSpec& run) {
  YAML::Node events(YAML::NodeType::Sequence);
  for (const sim::NodeEvent& e : run.events) {
    YAML::Node event;
    event["time"] = NumberNode(e.time);
    event["node"] = run.nodes.at(e.node).name;
    event["action"] = "switch_off";
    events.push_back(event);
  }
  return events;
}

}  // namespace

std::string EffectiveScenarioYaml(const Scenario& sc) {
  const sim::RunSpec& run = sc.run;
  YAML::Node root;
  root["name"] = run.name;
  root["seed"] = run.seed;
  root["duration"] = NumberNode(run.duration);
  root["world"] = WorldFields().Print(run);
  if (run.network) root["network"] = NetworkFields().Print(*run.network);
  root["messages"] = MessagesFields().Print(run);
  if (!run.events.empty()) root["events"] = Events(run);
  if (!run.end_when_logged.empty()) root["end"] = EndFields().Print(run);
  root["loop"] = LoopFields().Print(run.loop);
  root["outputs"] = OutputsFields().Print(sc);
  YAML::Node nodes(YAML::NodeType::Sequence);
  for (const sim::NodeSpec& n : run.nodes) nodes.push_back(Node(n, run.network.has_value()));
  root["nodes"] = nodes;
  YAML::Emitter out;
  out << root;
  return std::string("# The effective scenario of ") + sc.file + ": every default of the format filled in.\n" +
         out.c_str() + "\n";
}

}  // namespace sanet::scenario
