#include "robot_server/sim_server.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <thread>

#include "core/json_text.h"
#include "core/statistics.h"
#include "robot_server/spawn_policy.h"
#include "wire/agent_datagram.h"
#include "wire/message_lines.h"
#include "wire/sensor_lines.h"
#include "wire/sockets.h"

namespace sanet::robot_server {
std::size_t DefaultMaxClients(const sim::RunSpec& spec) {
  const auto robots = std::count_if(spec.nodes.begin(), spec.nodes.end(),
                                    [](const sim::NodeSpec& n) { return robots::HasDrive(n.model); });
  return std::max<std::size_t>(64, 2 * static_cast<std::size_t>(robots));
}

namespace {

// The names of the robots only a client can run (those with a controller), by node id.
std::vector<std::string> AgentRobots(const sim::Driver& driver) {
  std::vector<std::string> names(driver.NodeCount());
  for (NodeId id = 0; id < names.size(); ++id)
    if (sim::RunsAsAgent(driver.Spec(id))) names[id] = driver.NameOf(id);
  return names;
}

// USARSim's STA gives a robot's battery as whole seconds left: to its cutoff at the power it draws
// now, for a robot with `energy` (docs/energy.md), none once it is off; an hour for an infinite
// supply, as before.
std::string BatterySeconds(const sim::Driver& driver, NodeId robot) {
  const std::optional<BatteryReading> battery = driver.Battery(robot);
  const auto& energy = driver.Spec(robot).energy;
  if (!battery || !energy) return "3600";
  if (driver.SwitchedOff(robot)) return "0";
  if (battery->power_w <= 0) return "3600";
  const double usable_j = std::max(0.0, battery->remaining_j - energy->cutoff * battery->capacity_j);
  return std::to_string(static_cast<long long>(usable_j / battery->power_w));
}

}  // namespace

SimServer::SimServer(sim::Driver& driver, ServerSettings settings)
    : driver_(driver), settings_(std::move(settings)), attendance_(AgentRobots(driver)) {
  driver_.SetRemoteInbox([this](NodeId to, const Message& m) { return Forward(to, m); });
  wire::LineServer::Events events;
  events.connected = [this](wire::ConnectionId id) { Greet(id); };
  events.line = [this](wire::ConnectionId id, const std::string& line) {
    Client& c = clients_.at(id);
    std::string error;
    if (auto m = wire::ParseLine(line, &error))
      Handle(c, *m);
    else
      Error(c, "malformed line: " + error);
  };
  events.gone = [this](wire::ConnectionId id, const std::string& why) { Gone(id, why); };
  events.line_too_long = [](std::size_t max_line) {
    return wire::FormatLine(wire::ProtocolMessage{"ERR"}.Add(
        "Message", "line longer than " + std::to_string(max_line) + " bytes: closing"));
  };
  events.refusal_line = [](const std::string& why) {
    return wire::FormatLine(wire::ProtocolMessage{"ERR"}.Add("Message", why));
  };
  events.silence_line = events.refusal_line;  // ERR {Message connection closed: silent for 3 s after connecting}
  wire::LineServerSettings lines;
  lines.bind = settings_.bind;
  lines.port = settings_.port;
  lines.max_clients = settings_.max_clients;
  lines.cap_option = "--max-clients";
  lines.max_line = settings_.max_line;
  lines.max_backlog = settings_.max_backlog;
  lines.stall_timeout = settings_.stall_timeout;
  lines.lines_per_turn = settings_.lines_per_turn;
  lines.bytes_per_turn = settings_.bytes_per_turn;
  lines.poll_budget = settings_.poll_budget;
  lines_ = std::make_unique<wire::LineServer>(lines, std::move(events));
}

SimServer::~SimServer() { driver_.SetRemoteInbox(nullptr); }

void SimServer::Start() {
  driver_.Every(settings_.poll_period, [this] { Poll(); });
  step_ended_ = driver_.bus().On<sim::StepEnded>(sim::RunStage::kObserve,
                                                 [this](const sim::StepEnded& e) { AfterStep(e.world); });
  driver_.AtEnd([this] { FinishAgents(); });
}

// The run is over (sanet extension): every client that speaks sanet's lines and drives a robot
// is told END, and its controller's Finish may log, measure and record transitions until it says
// FINISHED, it goes, or finish_wait s pass; the results are written after.
void SimServer::FinishAgents() {
  run_over_ = true;
  std::vector<wire::ConnectionId> told;
  for (auto& [id, c] : clients_)
    if (c.open && c.robot && c.sanet) {
      Send(c, wire::ProtocolMessage{"END"}.Add("Time", wire::FormatNumber(driver_.Now())));
      told.push_back(id);
    }
  const auto finishing = [&] {
    return std::any_of(told.begin(), told.end(), [&](wire::ConnectionId id) {
      const auto it = clients_.find(id);
      return it != clients_.end() && it->second.open && !it->second.finished;
    });
  };
  const double give_up = wire::MonotonicSeconds() + settings_.finish_wait;
  while (finishing() && wire::MonotonicSeconds() < give_up) {
    lines_->Write();
    lines_->Read();
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  for (wire::ConnectionId id : told)
    if (const auto it = clients_.find(id); it != clients_.end() && it->second.open && !it->second.finished)
      driver_.Log(*it->second.robot, "its client did not say FINISHED within " +
                                         wire::FormatNumber(settings_.finish_wait) +
                                         " s of the run's end: what its controller's Finish logged later is lost");
}

// RADIO {Sleep true|false} (sanet extension): the robot's radio sleeps or wakes, as
// Node::SetRadioSleep; a refusal is an ERR line and the node's log says why.
void SimServer::SetRadioSleep(Client& c, const wire::ProtocolMessage& m) {
  const std::string* sleep = m.Get("Sleep");
  if (!sleep || (*sleep != "true" && *sleep != "false")) return Error(c, "RADIO needs {Sleep true} or {Sleep false}");
  if (!NodeOf(c).SetRadioSleep(*sleep == "true"))
    Error(c, "the radio of " + driver_.NameOf(*c.robot) + " cannot sleep");
}

// The lag of every physics step behind the wall clock.
void SimServer::AfterStep(const sim::WorldSnapshot& snapshot) {
  lags_.push_back(std::max(0.0, (wire::MonotonicSeconds() - wall_start_) - snapshot.time()));
}

nlohmann::ordered_json SimServer::LagSummary() const {
  std::vector<double> sorted = lags_;
  std::sort(sorted.begin(), sorted.end());
  const auto at = [&](double q) {
    return sorted.empty() ? 0.0 : sorted[static_cast<std::size_t>(q * (sorted.size() - 1))];
  };
  const double step = driver_.spec().physics_step;
  const auto missed = std::count_if(lags_.begin(), lags_.end(), [&](double l) { return l > step; });
  return {{"steps", lags_.size()},      {"p50_s", at(0.5)},
          {"p99_s", at(0.99)},          {"max_s", sorted.empty() ? 0 : sorted.back()},
          {"missed_deadlines", missed}, {"deadline_s", step}};
}

void SimServer::Poll() {
  const double now = driver_.Now();
  // The first poll runs as the real-time scheduler starts: simulated time 0 is now.
  if (wall_start_ < 0) {
    wall_start_ = wire::MonotonicSeconds() - now;
    // The time service's port: the robot protocol's number when UDP has it free.
    time_service_ = std::make_unique<wire::TimeService>(settings_.bind, lines_->port(), wall_start_);
  }
  lines_->Read();
  AnswerNetworkQueries(now);
  for (auto& [id, c] : clients_)
    if (c.open && c.robot) SendSensors(c, now);
  lines_->Write();
  for (auto it = clients_.begin(); it != clients_.end();) it = it->second.open ? std::next(it) : clients_.erase(it);
}

void SimServer::Greet(wire::ConnectionId id) {
  Client& c = clients_.emplace(id, Client(id, lines_->Peer(id))).first->second;
  wire::ProtocolMessage hello{"NFO"};
  hello.Add("Gametype", "BotDeathMatch").Add("Level", driver_.spec().name).Add("TimeLimit", driver_.spec().duration);
  // sanet extension: the machine's monotonic clock (s) at simulated time 0, so that processes
  // on this machine share the simulation's time to the microsecond.
  hello.Add("ClockOrigin", wire::FormatPrecise(wall_start_));
  Send(c, hello);
}

namespace {

// What a client may still say between the run's END and its FINISHED: what its controller's
// Finish records, nothing that moves a robot or the network.
bool TakenAfterEnd(const std::string& type) {
  for (const char* taken : {"LOG", "METRIC", "TRANSITION", "STATS", "RECV", "FINISHED"})
    if (type == taken) return true;
  return false;
}

}  // namespace

void SimServer::Handle(Client& c, const wire::ProtocolMessage& m) {
  if (run_over_ && !TakenAfterEnd(m.type))
    return Error(c, "the run is over: only LOG, METRIC, TRANSITION, STATS, RECV and FINISHED are taken now");
  if (m.type == "INIT") return Init(c, m);
  if (m.type == "SANET") return Hello(c, m);
  if (m.type == "GETSCENARIO") return SendScenario(c, m);
  if (m.type == "GETPLUGIN") return SendPlugin(c, m);
  if (m.type == "GETSTARTPOSES") {
    wire::ProtocolMessage reply{"NFO"};
    std::string poses;
    int count = 0;
    for (NodeId id = 0; id < driver_.NodeCount(); ++id) {
      const sim::NodeSpec& node = driver_.Spec(id);
      if (!robots::HasDrive(node.model) || driver_.IsSpawned(id)) continue;
      const auto p = wire::UsarsimPose(node.pose);
      poses += (count++ ? " " : "") + driver_.NameOf(id) + " " + wire::FormatNumber(p[0]) + "," +
               wire::FormatNumber(p[1]) + ",0.0000 0.0000,0.0000," + wire::FormatNumber(p[2]);
    }
    reply.Add("StartPoses", std::to_string(count)).Add(poses.empty() ? "None" : poses, "");
    return Send(c, reply);
  }
  if (!c.robot) return Error(c, m.type + " before INIT");
  const NodeId id = *c.robot;
  const auto& spec = driver_.Spec(id).model;
  if (m.type == "DRIVE") return Drive(c, m);
  if (m.type == "SEND") return SendMessage(c, m);
  if (m.type == "LOG" || m.type == "TRANSITION" || m.type == "METRIC") return Report(c, m);
  if (m.type == "STATS") return TakeStats(c, m);
  if (m.type == "PEER") return TakePeer(c, m);
  if (m.type == "CLOCK") return TakeClock(c, m);
  if (m.type == "GETNET") return AskNetwork(c);
  if (m.type == "RADIO") return SetRadioSleep(c, m);
  if (m.type == "FINISHED") return void(c.finished = true);
  if (m.type == "INVALIDATEROUTE" || m.type == "REQUESTROUTE") return ChangeRoute(c, m);
  if (m.type == "RECV") {
    const std::string* from = m.Get("From");
    std::string error;
    const auto report = wire::ParseRecvLine(m, from ? driver_.Lookup(*from) : std::nullopt, id, &error);
    return report ? driver_.RecordDelivery(id, report->message) : Error(c, error);
  }
  if (m.type == "GETCONF") {
    wire::ProtocolMessage reply{"CONF"};
    reply.Add("Type", "GroundVehicle")
        .Add("Name", driver_.NameOf(id))
        .Add("SteeringType", spec.model().UsarsimSteering())
        .Add("MaxSpeed", spec.max_speed)
        .Add("MaxTurnRate", spec.max_turn_rate);
    return Send(c, reply);
  }
  if (m.type == "GETGEO") {
    wire::ProtocolMessage reply{"GEO"};
    reply.Add("Type", "GroundVehicle")
        .Add("Name", driver_.NameOf(id))
        .Add("WheelRadius", spec.model().WheelRadius(spec))
        .Add("WheelSeparation", spec.model().WheelSeparation(spec));
    return Send(c, reply);
  }
  Error(c, "unknown command " + m.type);
}

// INIT {Name r} claims a robot that is there (the scenario's, or one spawned before); with a
// {ClassName} and a name nobody has, it spawns a new robot, as in USARSim.
void SimServer::Init(Client& c, const wire::ProtocolMessage& m) {
  if (c.robot) return Error(c, "INIT refused: this connection already drives " + driver_.NameOf(*c.robot));
  const std::string* name = m.Get("Name");
  const std::string* usarsim_class = m.Get("ClassName");
  if (name)
    if (const auto id = driver_.Lookup(*name)) return Claim(c, *id, usarsim_class);
  if (!usarsim_class)
    return Error(c, name ? "INIT refused: no robot named '" + *name + "' in this scenario; INIT {ClassName c} {Name " +
                               *name + "} {Location x,y,z} adds one where the scenario allows it"
                         : "INIT refused: give {Name robot} to claim one of the scenario's robots, or {ClassName c} "
                           "{Location x,y,z} to add one");
  if (m.Get("Start"))
    return Error(c,
                 "INIT refused: {Start tag}: the start poses belong to the scenario's robots; claim one with INIT "
                 "{Name tag}, or give {Location x,y,z} for a new robot");
  Spawn(c, *usarsim_class, name ? *name : "", m);
}

void SimServer::Claim(Client& c, NodeId id, const std::string* usarsim_class) {
  const std::string name = driver_.NameOf(id);
  if (!robots::HasDrive(driver_.Spec(id).model))
    return Error(c, "INIT refused: the name '" + name + "' is taken by a mote of this scenario");
  if (const auto owner = driver_.OwnerOf(id); owner && *owner != Owner(c))
    return Error(c, "INIT refused: robot '" + name + "' is already driven by another client");
  const std::string spawned_as = driver_.SpawnedAs(id);
  if (usarsim_class && !spawned_as.empty() && !sections::SameClass(*usarsim_class, spawned_as))
    return Error(c, "INIT refused: robot '" + name + "' is a " + spawned_as + ", not a " + *usarsim_class);
  if (const auto refused = driver_.Claim(id, Owner(c))) return Error(c, "INIT refused: " + *refused);
  attendance_.Joined(id, driver_.Now());
  if (settings_.announce) std::printf("sanet: client %s drives %s\n", c.peer.c_str(), name.c_str());
  c.robot = id;
  lines_->Register(c.id);  // a client that drives a robot keeps its slot when the cap is full
  c.next_sensors = c.next_status = driver_.Now();
  // sanet extension: the run's key for the datagrams agents send each other (wire/agent_datagram.h).
  Send(c, wire::ProtocolMessage{"KEY"}.Add("Datagrams", datagram_key_.Hex()));
  driver_.Log(id, "client " + c.peer + " drives this robot");
}

// {Location} and {Rotation} are in USARSim's frame (y right, yaw clockwise); the robot stands
// on the ground, whatever z says.
void SimServer::Spawn(Client& c, const std::string& usarsim_class, const std::string& name,
                      const wire::ProtocolMessage& m) {
  if (!m.Get("Location"))
    return Error(
        c, "INIT refused: {ClassName " + usarsim_class + "} needs {Location x,y,z}: where the new robot stands (m)");
  const auto location = m.Numbers("Location");
  if (!location || location->size() != 3)
    return Error(c, "INIT refused: {Location " + *m.Get("Location") + "}: expected three numbers x,y,z");
  const auto rotation = m.Get("Rotation") ? m.Numbers("Rotation") : std::vector<double>{0, 0, 0};
  if (!rotation || rotation->size() != 3)
    return Error(c, "INIT refused: {Rotation " + *m.Get("Rotation") + "}: expected three numbers r,p,y (rad)");
  const SpawnRequest request{usarsim_class, name, {(*location)[0], -(*location)[1], -(*rotation)[2]}};
  const SpawnPlan plan = PlanSpawn(driver_, settings_.spawn, request);
  if (!plan.node) return Error(c, "INIT refused: " + plan.refusal);
  const NodeId id =
      driver_.Spawn(*plan.node, plan.usarsim_class, "spawned as " + plan.usarsim_class + " by client " + c.peer);
  Claim(c, id, nullptr);
}

// Through the robot's simulated node, as its controller would drive it: a switched-off robot
// does not move, whoever asks.
void SimServer::Drive(Client& c, const wire::ProtocolMessage& m) {
  Node& node = NodeOf(c);
  if (driver_.SwitchedOff(*c.robot)) {
    if (!c.told_off) Error(c, "robot " + node.Name() + " is switched off: DRIVE ignored");
    c.told_off = true;
    return;
  }
  const auto& spec = driver_.Spec(*c.robot).model;
  if (m.Get("Left") || m.Get("Right")) {
    const auto left = m.Number("Left"), right = m.Number("Right");
    if (!left || !right) return Error(c, "DRIVE needs numbers for both {Left} and {Right}");
    double l = *left, r = *right;
    if (const std::string* normalized = m.Get("Normalized");
        normalized && (*normalized == "True" || *normalized == "true")) {
      const double top = spec.max_speed / spec.model().WheelRadius(spec);  // rad/s at 100 %
      l = std::clamp(l, -100.0, 100.0) / 100 * top, r = std::clamp(r, -100.0, 100.0) / 100 * top;
    }
    if (std::string(spec.model().UsarsimSteering()) != "SkidSteered")
      return Error(c, "{Left} {Right} drive a diffdrive; use {LinearVelocity} ... for omni3");
    node.SetWheelSpeeds({l, r});
    return;
  }
  if (m.Get("LinearVelocity") || m.Get("RotationalVelocity") || m.Get("LateralVelocity")) {
    const auto v = m.Number("LinearVelocity"), lateral = m.Number("LateralVelocity"),
               w = m.Number("RotationalVelocity");
    if ((m.Get("LinearVelocity") && !v) || (m.Get("LateralVelocity") && !lateral) ||
        (m.Get("RotationalVelocity") && !w))
      return Error(c, "DRIVE velocities must be numbers");
    node.Drive({v.value_or(0), -lateral.value_or(0), -w.value_or(0)});  // USARSim: y right, yaw clockwise
    return;
  }
  Error(c, "DRIVE needs {Left l} {Right r}, or {LinearVelocity} {LateralVelocity} {RotationalVelocity}");
}

// Every sensor period, the robot's sensors as its owner reads them (once: noisy sensors draw
// from the node's random stream); every status period, its status.
void SimServer::SendSensors(Client& c, double now) {
  if (now + 1e-9 >= c.next_sensors) {
    c.next_sensors = now + settings_.sensor_period;
    for (const wire::ProtocolMessage& line :
         SenLines(*c.robot, driver_.TakeReadings(*c.robot, Owner(c)), c.sanet, c.fresh))
      Send(c, line);
  }
  if (now + 1e-9 >= c.next_status) {
    c.next_status = now + settings_.status_period;
    wire::ProtocolMessage status{"STA"};
    status.Add("Type", "GroundVehicle")
        .Add("Time", now)
        .Add("FrontSteer", 0.0)
        .Add("RearSteer", 0.0)
        .Add("LightToggle", "False")
        .Add("LightIntensity", "0")
        .Add("Battery", BatterySeconds(driver_, *c.robot))
        .Add("View", "-1");
    Send(c, status);
  }
}

// A sample of a sensor on its own clock goes once (sim/fresh_samples.h), in the line of the read
// that first finds it.
std::vector<wire::ProtocolMessage> SimServer::SenLines(NodeId robot, const sim::SensorReadings& r, bool sanet,
                                                       sim::FreshSamples& fresh) const {
  const wire::LineContext context{r.time, r.height, [this](NodeId node) { return driver_.NameOf(node); },
                                  [this](const std::string& name) { return driver_.Lookup(name); }};
  const robots::SensorConfigs& sensors = driver_.Spec(robot).model.sensors;
  std::vector<wire::ProtocolMessage> lines;
  for (const auto& [instance, reading] : r.by_instance) {
    const auto config = sensors.find(instance);
    const wire::SensorLines* kind = config == sensors.end() ? nullptr : wire::LinesOf(config->second.kind);
    if (!kind || (kind->Extension() && !sanet) || !fresh.TakeIfNew(instance, r)) continue;
    for (wire::ProtocolMessage& line : kind->Write(instance, reading, context)) lines.push_back(std::move(line));
  }
  return lines;
}

void SimServer::Send(Client& c, const wire::ProtocolMessage& m) {
  if (c.open) lines_->Send(c.id, wire::FormatLine(m));
}

// An ERR line carries no braces, whatever it quotes (a client's own text, a field's name):
// braces would end its {Message ...} field early for a client's parser. A field's name in braces
// becomes quoted ('Left'), a field with its value parenthesised ((ClassName c)), a lone brace '.
std::string WithoutBraces(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const std::size_t close = text[i] == '{' ? text.find_first_of("{}", i + 1) : std::string::npos;
    if (close != std::string::npos && text[close] == '}') {
      const std::string inside = text.substr(i + 1, close - i - 1);
      const bool one_word = inside.find(' ') == std::string::npos;
      out += one_word ? "'" + inside + "'" : "(" + inside + ")";
      i = close;
    } else {
      out += text[i] == '{' || text[i] == '}' ? '\'' : text[i];
    }
  }
  return out;
}

void SimServer::Error(Client& c, const std::string& why) {
  wire::ProtocolMessage error{"ERR"};
  error.Add("Message", WithoutBraces(why));
  Send(c, error);
}

void SimServer::Drop(Client& c, const std::string& why) { lines_->Drop(c.id, why); }

// The line server ended the connection (or the client did): its robot stops and is free.
void SimServer::Gone(wire::ConnectionId id, const std::string& why) {
  Client& c = clients_.at(id);
  c.open = false;
  if (!c.robot) return;
  if (run_over_) return driver_.Release(*c.robot, Owner(c));  // it finished after END: driven to the end
  NodeOf(c).Drive({});                                        // a robot without its client stops
  driver_.Release(*c.robot, Owner(c));
  attendance_.Left(*c.robot, driver_.Now(), why);
  driver_.Log(*c.robot, "client " + c.peer + " gone (" + why + "): robot stopped");
  if (settings_.announce)
    std::printf("sanet: client %s of %s gone (%s)\n", c.peer.c_str(), driver_.NameOf(*c.robot).c_str(), why.c_str());
}

// SEND: the robot's message leaves from its own ns-3 node, like any node's. Values are
// case-sensitive, as node names are.
void SimServer::SendMessage(Client& c, const wire::ProtocolMessage& m) {
  const std::string* delivery = m.Get("Delivery");
  const std::string* data = m.Get("Data");
  const auto kind = ParseDelivery(delivery ? *delivery : "unicast");
  if (!kind) return Error(c, "SEND {Delivery " + *delivery + "}: expected unicast, broadcast or flood");
  if (!data) return Error(c, "SEND needs {Data hex bytes}");
  const auto payload = wire::FromHex(*data);
  if (!payload) return Error(c, "SEND {Data ...}: expected hex bytes (pairs of 0-9, a-f), not '" + *data + "'");
  Node& node = NodeOf(c);
  if (driver_.SwitchedOff(*c.robot)) return Error(c, "robot " + node.Name() + " is switched off: SEND ignored");
  if (*kind == Delivery::kBroadcast) return node.Broadcast(*payload);
  if (*kind == Delivery::kFlood) return node.Flood(*payload);
  const std::string* to = m.Get("To");
  if (!to) return Error(c, "SEND to one node needs {To node}; or give {Delivery broadcast} or {Delivery flood}");
  const auto target = driver_.Lookup(*to);
  if (!target) return Error(c, "SEND {To " + *to + "}: no node named '" + *to + "' in this scenario");
  if (*target == node.Id()) return Error(c, "SEND {To " + *to + "}: that is this robot");
  node.Send(*target, *payload);
}

// LOG, TRANSITION and METRIC: the controller's reports, as its node would make them in process.
void SimServer::Report(Client& c, const wire::ProtocolMessage& m) {
  Node& node = NodeOf(c);
  const std::string* text = m.Get("Text");
  if (m.type == "LOG") return text && !text->empty() ? node.Log(*text) : Error(c, "LOG needs {Text ...}");
  if (m.type == "METRIC") {
    const std::string* name = m.Get("Name");
    const auto value = m.Number("Value");
    return name && value ? node.Metric(*name, *value) : Error(c, "METRIC needs {Name n} and a number {Value v}");
  }
  const std::string *from = m.Get("From"), *to = m.Get("To"), *why = m.Get("Why");
  if (!from || !to || from->empty() || to->empty())
    return Error(c, "TRANSITION needs {From state} {To state}, both named, and may give {Why ...}");
  node.Transition(*from, *to, why ? *why : "");
}

namespace {

// STATS keys and their names in the results; counts are whole numbers.
struct StatsKey {
  const char* key;
  const char* name;
  bool count;
};
constexpr StatsKey kStatsKeys[] = {{"Steps", "steps", true},
                                   {"Missed", "steps_missed", true},
                                   {"Rate", "achieved_rate_hz", false},
                                   {"Sent", "messages_sent", true},
                                   {"Received", "messages_received", true},
                                   {"DatagramsSent", "datagrams_sent", true},
                                   {"DatagramsReceived", "datagrams_received", true},
                                   {"DatagramsRejected", "datagrams_rejected", true},
                                   {"SendErrors", "send_errors", true},
                                   {"LatenessP50", "lateness_p50_s", false},
                                   {"LatenessP99", "lateness_p99_s", false},
                                   {"LatenessMax", "lateness_max_s", false},
                                   {"ClockOffset", "clock_offset_s", false},
                                   {"ClockError", "clock_error_s", false},
                                   {"ClockErrorMax", "clock_error_max_s", false}};

}  // namespace

// STATS (sanet extension): an agent's steps, messages and packets so far; the last one counts.
void SimServer::TakeStats(Client& c, const wire::ProtocolMessage& m) {
  nlohmann::ordered_json stats = nlohmann::ordered_json::object();
  for (const StatsKey& k : kStatsKeys) {
    constexpr std::uint64_t kMostCount = std::uint64_t{1} << 53;  // whole numbers a double holds exactly
    if (k.count) {
      const auto count = m.Count(k.key, kMostCount);
      if (!count) return Error(c, std::string("STATS needs a whole number from 0 to 2^53 '") + k.key + " ...'");
      stats[k.name] = *count;
    } else {
      const auto value = m.Number(k.key);
      if (!value) return Error(c, std::string("STATS needs a number '") + k.key + " ...'");
      stats[k.name] = *value;
    }
  }
  agent_stats_[driver_.NameOf(*c.robot)] = stats;
  if (!c.agent) lines_->ExpectChatter(c.id);  // an agent reads and writes in one loop: silence tells it stopped
  c.agent = true;
}

// agents.csv: one row per agent, its last STATS, in node order; clock.csv: their CLOCK lines.
void SimServer::WriteAgentTable(trace::ResultsFolder& folder) const {
  if (!clock_rows_.empty()) {
    trace::CsvSink& clocks = folder.Csv("clock.csv", "time_s,node,offset_s,error_bound_s,round_trip_s,drift_ppm");
    for (const std::string& row : clock_rows_) clocks.Row(row);
  }
  if (agent_stats_.empty()) return;
  std::string header = "node";
  for (const StatsKey& k : kStatsKeys) header += std::string(",") + k.name;
  trace::CsvSink& table = folder.Csv("agents.csv", header);
  for (NodeId id = 0; id < driver_.NodeCount(); ++id) {
    const auto it = agent_stats_.find(driver_.NameOf(id));
    if (it == agent_stats_.end()) continue;
    std::string row = trace::CsvField(driver_.NameOf(id));
    for (const StatsKey& k : kStatsKeys) row += "," + JsonText((*it)[k.name]);
    table.Row(row);
  }
}

SimServer::Client* SimServer::ClientOf(NodeId robot) {
  for (auto& [id, c] : clients_)
    if (c.open && c.robot == robot) return &c;
  return nullptr;
}

// A message reached a client's robot in the simulated network: it goes on to the client. Agents
// hear each other over their own UDP sockets, so the server passes on only what comes from
// nodes that live here.
sim::InboxResult SimServer::Forward(NodeId to, const Message& m) {
  if (driver_.drivers() == sim::RobotDrivers::kFrontEnds && sim::RunsAsAgent(driver_.Spec(m.from)))
    return sim::InboxResult::kIgnored;
  Client* c = ClientOf(to);
  if (c) Send(*c, wire::MsgLine(m, driver_.NameOf(m.from)));
  return c && c->open ? sim::InboxResult::kDelivered : sim::InboxResult::kLost;
}

}  // namespace sanet::robot_server
