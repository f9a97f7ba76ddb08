#include "sim/assembly.h"

#include <ns3/core-module.h>
#include <ns3/node-container.h>

#include <cmath>
#include <cstdio>

#include "hosting/isolated_controller.h"
#include "net/body_mobility_model.h"
#include "net/local_transport.h"
#include "net/wireless_network.h"
#include "sensors/sensor_registry.h"
#include "sim/radio_calibration.h"
#include "sim/radio_walls.h"
#include "sim/surroundings_of.h"

namespace sanet::sim {
namespace {

bool g_assembly_exists = false;

// How many physics steps the physics thread may be queued ahead of the network's: enough to carry
// it through a burst of network events, or the network through a stretch of silence.
constexpr std::size_t kStepsAhead = 8;

// The controllers' clock in a simulated run: ns-3's.
class SimulationClock : public hosting::HostClock {
 public:
  double Now() const override { return ns3::Simulator::Now().GetSeconds(); }
  void After(double delay, std::function<void()> action) override {
    ns3::Simulator::Schedule(ns3::NanoSeconds(std::llround(delay * 1e9)), std::move(action));
  }
};

// An ns-3 node with a mobility model for the run to publish its body's poses to.
ns3::Ptr<ns3::Node> Ns3Node() {
  auto node = ns3::CreateObject<ns3::Node>();
  node->AggregateObject(ns3::CreateObject<net::BodyMobilityModel>());
  return node;
}

// "12.5 J", "3.700 V": a quantity for a log line.
std::string Quantity(const char* format, double value) {
  char text[32];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

}  // namespace

Assembly::Assembly(const RunSpec& spec, hosting::Registry& registry, RobotDrivers drivers)
    : spec_(spec), surroundings_(SurroundingsOf(spec)), run_nodes_(spec.nodes), drivers_(drivers) {
  if (g_assembly_exists) throw WorldError("only one World may exist at a time (ns-3 is process-wide)");
  if (spec.physics_step <= 0) throw WorldError("physics step must be positive");
  g_assembly_exists = true;
  try {
    clock_ = std::make_unique<SimulationClock>();
    poses_ = std::make_unique<PosePipeline>([this](const std::vector<NodeId>& moved) { transport_->Moved(moved); });
    // Before any ns-3 object of the run: measuring runs simulations of its own.
    if (spec.network && spec.network->radio_model == net::RadioModel::kAbstract) calibration_ = CalibrationFor(spec);
    ns3::RngSeedManager::SetSeed(net::Ns3Seed(spec.seed));
    BuildBodies();
    BuildTransport();
    BuildNodes(registry);
  } catch (...) {
    hosts_.clear();
    ns3::Simulator::Destroy();
    g_assembly_exists = false;
    throw;
  }
}

Assembly::~Assembly() {
  // Controllers may hold code from libraries and state tied to nodes: drop them first.
  hosts_.clear();
  ns3::Simulator::Destroy();
  g_assembly_exists = false;
}

void Assembly::BuildBodies() {
  physics_ = std::make_unique<physics::PipelinedWorld>(physics::CreatePhysicsWorld(spec_.physics), spec_.threads == 2,
                                                       kStepsAhead);
  for (const Obstacle& o : spec_.obstacles) physics_->add_static_box(o.box);
  for (const NodeSpec& n : run_nodes_) AddBody(n);
  // On the physics thread too (a camera's samples): the bodies are its between its steps.
  surroundings_.scenery.bodies = [this](std::vector<sensors::SceneBody>& out) {
    out.clear();
    for (NodeId id = 0; id < models_.size(); ++id)
      out.push_back(SceneBodyOf(id, run_nodes_[id].model, models_[id]->body().pose()));
  };
}

// A node's body and its sensors (whose noise streams are named after the node).
void Assembly::AddBody(const NodeSpec& n) {
  models_.push_back(std::make_unique<robots::NodeModel>(*physics_, n.model, n.pose));
  sensors_.push_back(std::make_unique<sensors::SensorSet>(*physics_, *models_.back(), n.pose, spec_.seed,
                                                          "node/" + n.name, surroundings_,
                                                          static_cast<NodeId>(sensors_.size())));
}

// One ns-3 node per body, in node order (ns-3's node ids are sanet's).
void Assembly::BuildTransport() {
  ns3::NodeContainer nodes;
  for (NodeId id = 0; id < models_.size(); ++id) {
    nodes.Add(Ns3Node());
    FollowBody(id, ns3::PeekPointer(nodes.Get(id)->GetObject<net::BodyMobilityModel>()));
  }
  std::unique_ptr<net::Transport> inner;
  if (spec_.network) {
    std::vector<std::string> names;
    std::vector<net::NodeRadio> radios;
    for (const NodeSpec& n : run_nodes_) names.push_back(n.name), radios.push_back(n.radio);
    net::NetworkSpec network = *spec_.network;
    network.seed = spec_.seed;  // shadowing, fading and hardware spread draw from the run's seed
    if (calibration_) network.calibration = calibration_->table, network.calibration_source = calibration_->source;
    auto wireless = std::make_unique<net::WirelessNetwork>(
        network, nodes, names, radios, RadioWalls(spec_),
        network.lr_wpan_in_use ? RadioWalls(spec_, net::kLrWpanFrequencyHz) : std::vector<net::RadioObstacle>{});
    wireless_ = wireless.get();
    wireless_->ObserveAbstractAirtime([this](std::uint32_t node, bool sent, double seconds) {
      if (energy::NodeEnergy* energy = batteries_.Of(node)) energy->AbstractRadioOnAir(sent, seconds);
    });
    inner = std::move(wireless);
  } else {
    auto local = std::make_unique<net::LocalTransport>(run_nodes_.size(), spec_.message_latency);
    local_ = local.get();
    inner = std::move(local);
  }
  transport_ = std::make_unique<MessageLedger>(std::move(inner), [this] { return clock_->Now(); });
  transport_->SetReceiver([this](NodeId to, const Message& m) { Receive(to, m); });
}

bool Assembly::remote(NodeId id) const {
  return drivers_ == RobotDrivers::kFrontEnds && robots::HasDrive(run_nodes_.at(id).model);
}

void Assembly::BuildNodes(hosting::Registry& registry) {
  registry.StartRun(spec_.seed);  // before any controller is made (isolated ones fork from here)
  for (NodeId id = 0; id < run_nodes_.size(); ++id) {
    const NodeSpec& n = run_nodes_[id];
    if (!n.controller || remote(id)) {
      AddNode(id, nullptr);
      continue;
    }
    AddNode(id, spec_.isolate_controllers ? hosting::MakeIsolatedController(*n.controller, registry)
                                          : hosting::MakeController(*n.controller, registry));
  }
}

// The simulated node and the controller's host of node `id`, whose body exists.
void Assembly::AddNode(NodeId id, std::unique_ptr<Controller> controller) {
  const NodeSpec& n = run_nodes_[id];
  nodes_.push_back(
      std::make_unique<hosting::SimulatedNode>(id, n.name, *models_[id], *sensors_[id], *transport_, *this, *clock_,
                                               RandomStream(spec_.seed, "node/" + n.name + "/controller")));
  const hosting::MessageImpairments impairments{spec_.message_loss, spec_.message_delay};
  hosts_.push_back(std::make_unique<hosting::ControllerHost>(*nodes_.back(), std::move(controller),
                                                             n.controller ? n.controller->rate : 1, impairments,
                                                             spec_.seed, *clock_, HostHooks(id)));
  states_.emplace_back();
  off_for_good_.push_back(false);
  AddBattery(id);
}

// Depletion and revival are handled in an event of their own at the same instant: the battery
// notices them inside ns-3's PHY and energy calls, which must not switch the radio meanwhile.
void Assembly::AddBattery(NodeId id) {
  energy::NodeEnergy::Radios radio;
  if (wireless_)
    radio = {wireless_->Device(id), wireless_->LrWpanDevice(id), wireless_->LrWpan(), id,
             wireless_->HasAbstractRadio(id)};
  double sensors_w = 0;
  for (const auto& [name, config] : run_nodes_[id].model.sensors) sensors_w += config.power_w;
  batteries_.Add(id, run_nodes_[id].energy, radio, sensors_w,
                 {[this, id] { ns3::Simulator::ScheduleNow(&Assembly::Die, this, id); },
                  [this, id] { ns3::Simulator::ScheduleNow(&Assembly::Revive, this, id); }});
}

void Assembly::Die(NodeId id) {
  energy::NodeEnergy* energy = batteries_.Of(id);
  if (!energy || !energy->depleted() || batteries_.dead(id) || off_for_good_[id]) return;
  batteries_.Died(id, Now());
  energy->SetOn(false);
  nodes_.at(id)->SwitchOff();  // not off already: neither dead nor switched off for good
  hosts_.at(id)->SwitchOff();
  Log(id, "died: its battery is exhausted (" + Quantity("%.6g J", energy->remaining_j()) + " left at " +
              Quantity("%.3f V", energy->Reading().voltage) + ")");
  Tell(Died{Now(), id});
}

void Assembly::Revive(NodeId id) {
  energy::NodeEnergy* energy = batteries_.Of(id);
  if (!energy || energy->depleted() || !batteries_.dead(id) || off_for_good_[id]) return;
  batteries_.Revived(id);
  energy->SetOn(true);
  energy->RadioSwitchedOn();  // its new model hears the radio come back (and what it hears at once)
  nodes_.at(id)->SwitchOn();
  hosts_.at(id)->SwitchOn();
  Log(id, "revived: its battery was recharged to " + Quantity("%.6g J", energy->remaining_j()));
  Tell(Revived{Now(), id});
}

void Assembly::Recharge(NodeId id, std::optional<double> joules) {
  energy::NodeEnergy* energy = batteries_.Of(id);
  if (!energy) return Log(id, "recharge refused: the node has no energy section (an infinite supply)");
  energy->Recharge(joules.value_or(energy->spec().battery_j));
  if (batteries_.dead(id) && energy->depleted())
    Log(id, "recharged to " + Quantity("%.6g J", energy->remaining_j()) + ": below its revive level (" +
                Quantity("%.6g", energy->spec().RevivesAbove() * 100) + " %), it stays dead");
}

void Assembly::Drove(NodeId id, const physics::DriveTally& tally, double dt) {
  if (energy::NodeEnergy* energy = batteries_.Of(id)) energy->Drove(tally.motor_work_j, tally.weight_rolled_j, dt);
}

std::optional<BatteryReading> Assembly::Battery(NodeId node) const {
  const energy::NodeEnergy* energy = batteries_.Of(node);
  if (!energy) return std::nullopt;
  return energy->Reading();
}

NodeId Assembly::Spawn(const NodeSpec& node, const std::string& spawned_as, const std::string& why) {
  const NodeId id = run_nodes_.Add(node, spawned_as);
  AddBody(node);
  ns3::Ptr<ns3::Node> ns3_node = Ns3Node();
  FollowBody(id, ns3::PeekPointer(ns3_node->GetObject<net::BodyMobilityModel>()));
  if (wireless_) wireless_->AddNode(ns3_node, node.name, node.radio);
  if (local_) local_->AddNode();
  AddNode(id, nullptr);
  physics_->Settle();  // the physics thread reads the lists grown here
  Tell(NodeSpawned{Now(), id, spawned_as, models_.at(id)->body().pose()});
  Log(id, why);
  return id;
}

hosting::ControllerHost::Hooks Assembly::HostHooks(NodeId id) {
  hosting::ControllerHost::Hooks hooks;
  hooks.delivered = [this, id](const Message& m) { Tell(MessageDelivered{id, m}); };
  hooks.dropped = [this, id](const Message& m) { Tell(MessageDropped{id, m}); };
  hooks.failed = [this](const std::string& why) { Tell(ControllerFailed{why}); };
  return hooks;
}

// A remote robot's messages go to its client, impaired there as its controller's own host does.
void Assembly::Receive(NodeId to, const Message& m) {
  if (!remote(to)) return hosts_.at(to)->Receive(m);
  const InboxResult result = remote_inbox_ ? remote_inbox_(to, m) : InboxResult::kLost;
  if (result == InboxResult::kIgnored) return;
  if (result == InboxResult::kDelivered) return Tell(MessageDelivered{to, m});
  Lost(to, m, "no client drives " + NameOf(to));
}

// The message's row, then a line in the addressee's log saying why.
void Assembly::Lost(NodeId to, const Message& m, const std::string& why) {
  Tell(MessageLost{Now(), to, m, why});
  const std::string text = "message from " + NameOf(m.from) + " lost: " + why;
  Tell(LogLine{m.time_received, to, text});
}

void Assembly::FollowBody(NodeId id, net::BodyMobilityModel* mobility) {
  poses_->Add(mobility, PosePipeline::Of(id, models_.at(id)->body()));
}

std::string Assembly::NameOfBody(const physics::Body* body) const {
  for (NodeId id = 0; id < models_.size(); ++id)
    if (&models_[id]->body() == body) return NameOf(id);
  return "a body";
}

std::vector<RadioPose> Assembly::RadioPoses(const std::vector<NodeId>& moved) const {
  std::vector<RadioPose> poses;
  poses.reserve(moved.size());
  for (NodeId id : moved) poses.push_back(PosePipeline::Of(id, models_.at(id)->body()));
  return poses;
}

// A node switched off again stays off: ns-3 aborts when a radio that is off is switched off.
void Assembly::SwitchOff(NodeId id) {
  off_for_good_.at(id) = true;
  if (energy::NodeEnergy* energy = batteries_.Of(id)) energy->SetOn(false);
  if (nodes_.at(id)->switched_off()) return;
  nodes_.at(id)->SwitchOff();
  hosts_.at(id)->SwitchOff();
  Log(id, "switched off");
}

std::optional<Signal> Assembly::SignalBetween(NodeId from, NodeId to) const {
  if (!wireless_) return std::nullopt;
  const double power = wireless_->ReceivedPower(from, to);
  if (std::isinf(power)) return std::nullopt;  // the two share no radio
  return Signal{power, wireless_->DetectionThreshold(from, to)};
}

void Assembly::JoinTap(NodeId id, int fd, const std::string& tap_mac) {
  if (!wireless_) throw WorldError("a real IP stack joins the simulated radio: the scenario needs a network section");
  wireless_->JoinTap(id, fd, tap_mac);
}

std::optional<NodeId> Assembly::Lookup(const std::string& name) const { return run_nodes_.Find(name); }

double Assembly::Now() const { return ns3::Simulator::Now().GetSeconds(); }

void Assembly::Log(NodeId node, const std::string& text) { Tell(LogLine{Now(), node, text}); }

void Assembly::Transition(NodeId node, const std::string& from, const std::string& to, const std::string& why) {
  states_.at(node) = to;
  Tell(Transitioned{Now(), node, from, to, why});
}

void Assembly::Metric(NodeId node, const std::string& name, double value) {
  Tell(MetricReported{Now(), node, name, value});
}

void Assembly::ReadSensor(NodeId node, const std::string& instance, const std::string& kind,
                          const SensorReading& reading) {
  if (energy::NodeEnergy* energy = batteries_.Of(node)) {
    const auto& sensors = run_nodes_[node].model.sensors;
    const auto it = sensors.find(instance);
    if (it != sensors.end()) energy->SensorRead(it->second.energy_j);
  }
  // A sensor sampling on its own clock is logged by its samples, which the stepper publishes
  // (Stepper::Aftermath), not by what reads take of them.
  const sensors::SensorKind* sensor = sensors::FindKind(kind);
  if (sensor && sensor->SamplesOnItsOwn()) return;
  if (running_ && bus_.Heard<SensorRead>()) bus_.Publish(SensorRead{Now(), node, instance, kind, reading, Body(node)});
}

// Without the body's state: the step after the sample may be in flight (asking would wait for it),
// and the messages of sampled readings do not use it.
void Assembly::Sampled(NodeId node, const sensors::SensorSet::Sample& sample) {
  if (running_ && bus_.Heard<SensorRead>())
    bus_.Publish(SensorRead{sample.taken.t, node, *sample.instance, *sample.kind, sample.taken.reading, BodyState{}});
}

BodyState Assembly::Body(NodeId node) const {
  const physics::Body& body = models_.at(node)->body();
  return {body.pose(), body.velocity(), physics::WheelAngles(models_.at(node)->vehicle())};
}

std::vector<NodeId> Assembly::RadioNeighbours(NodeId node) const { return transport_->View(node).Neighbours(); }

}  // namespace sanet::sim
