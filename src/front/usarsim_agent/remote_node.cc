#include "usarsim_agent/remote_node.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <ifaddrs.h>
#include <net/if.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <thread>

#include "robots/kinematics.h"
#include "robots/node_model.h"
#include "sanet/codec.h"
#include "wire/message_lines.h"
#include "wire/sensor_lines.h"
#include "wire/sockets.h"
#include "wire/time_service.h"

namespace sanet::usarsim_agent {
RemoteNode::RemoteNode(const sim::RunSpec& spec, NodeId robot, AgentSettings settings, std::unique_ptr<ServerLink> link)
    : spec_(spec),
      id_(robot),
      settings_(std::move(settings)),
      link_(std::move(link)),
      random_(spec.seed, "node/" + spec.nodes.at(robot).name + "/controller") {
  // The clock first: everything the agent stamps is on it.
  if (settings_.shared_clock) {
    clock_origin_ = link_->clock_origin();
    if (!clock_origin_)
      throw std::runtime_error("--shared-clock: the server at " + link_->address() + " gave no ClockOrigin");
  } else {
    clock_sync_ = std::make_unique<ClockSync>(link_->host(), settings_.time_port, settings_.clock_skew);
  }
  peer_socket_ = std::make_unique<PeerSocket>(spec_, id_, settings_.peer, [this] { return ClockNow(); });
  LoopNetworkView::Hooks hooks{[this] { return Now(); }, [this] { return peer_socket_->Addresses(); },
                               [this](const std::string& text) { Log(text); },
                               [this](const std::string& name) { return Lookup(name); }};
  view_ = std::make_unique<LoopNetworkView>(spec_, id_, link_.get(), std::move(hooks));
  wire::ProtocolMessage init("INIT");
  init.Add("ClassName", Holonomic() ? "sanet.omni3" : "USARBot.P2DX").Add("Name", Name());
  Command(init);
  Command(wire::ProtocolMessage{"PEER"}
              .Add("Address", peer_socket_->address())
              .Add("Port", std::to_string(peer_socket_->port())));
}

RemoteNode::~RemoteNode() {
  wire::ProtocolMessage stop("DRIVE");
  Holonomic() ? stop.Add("LinearVelocity", 0.0) : stop.Add("Left", 0.0).Add("Right", 0.0);
  Command(stop);
}

void RemoteNode::Command(const wire::ProtocolMessage& m) { link_->Send(m); }

double RemoteNode::Now() const { return step_time_ ? *step_time_ : ClockNow(); }

double RemoteNode::ClockNow() const {
  if (clock_origin_) return wire::MonotonicSeconds() - *clock_origin_;
  return clock_sync_->ServerNow();
}

ClockFigures RemoteNode::clock_figures() const {
  if (clock_sync_) return clock_sync_->figures();
  ClockFigures shared;
  shared.offset = -*clock_origin_;
  return shared;
}

std::optional<NodeId> RemoteNode::Lookup(const std::string& name) const {
  for (NodeId i = 0; i < spec_.nodes.size(); ++i)
    if (spec_.nodes[i].name == name) return i;
  return std::nullopt;
}

bool RemoteNode::Poll(const std::function<void(const Message&)>& deliver) {
  std::vector<wire::ProtocolMessage> lines;
  const bool open = link_->Read(lines);
  for (const wire::ProtocolMessage& m : lines) Take(m, deliver);
  peer_socket_->Read(deliver);
  return open && !ended_;
}

// Lines from the server: sensors, status, messages from its nodes, errors.
void RemoteNode::Take(const wire::ProtocolMessage& m, const std::function<void(const Message&)>& deliver) {
  if (m.type == "ERR") {  // fatal while claiming the robot; afterwards the run goes on
    const std::string* text = m.Get("Message");
    const std::string why = "server: " + (text ? *text : std::string("error"));
    if (!HasPose()) throw std::runtime_error(why);
    std::fprintf(stderr, "sanet agent %s: %s\n", Name().c_str(), why.c_str());
  }
  if (m.type == "MSG") {
    const std::string* from = m.Get("From");
    std::string error;
    if (auto message = wire::ParseMsgLine(m, from ? Lookup(*from) : std::nullopt, id_, &error))
      deliver(*message);
    else
      throw std::runtime_error("server sent a bad MSG line: " + error);
  }
  if (m.type == "SEN") TakeSensor(m);
  if (m.type == "KEY")
    if (const std::string* hex = m.Get("Datagrams"))
      if (const auto key = wire::DatagramKey::FromHex(*hex)) peer_socket_->SetKey(*key);
  if (m.type == "PEER") TakePeer(m);
  if (m.type == "END") ended_ = true;
}

// PEER {Name n} {Address a} {Port p}: where another agent listens (it said so to the server).
void RemoteNode::TakePeer(const wire::ProtocolMessage& m) {
  const std::string *name = m.Get("Name"), *address = m.Get("Address");
  const auto node = name ? Lookup(*name) : std::nullopt;
  const auto port = m.Count("Port", 65535);
  if (!node || !address || !port || *node == id_) return;
  try {
    peer_socket_->SetPeer(*node, *address, static_cast<std::uint16_t>(*port));
  } catch (const std::runtime_error&) {
    std::fprintf(stderr, "sanet agent %s: the server gave %s a peer address that is none: %s\n", Name().c_str(),
                 name->c_str(), address->c_str());
  }
}

// A SEN line, read by the part of the kind it belongs to (wire/sensor_lines.h) into the reading of
// the instance it names; lines of sensors this robot does not have are ignored.
void RemoteNode::TakeSensor(const wire::ProtocolMessage& m) {
  const wire::LineContext context{0, 0, [this](NodeId node) { return NameOf(node); },
                                  [this](const std::string& name) { return Lookup(name); }};
  const robots::SensorConfigs& sensors = spec_.nodes[id_].model.sensors;
  for (const auto& [instance, config] : sensors) {
    const wire::SensorLines* kind = wire::LinesOf(config.kind);
    if (!kind || !kind->IsFrom(m, instance)) continue;
    if (std::optional<SensorReading> reading = kind->Read(m, config.settings, context))
      readings_[instance] = std::move(*reading);
    return;
  }
}

std::optional<SensorReading> RemoteNode::Sensor(const std::string& name) {
  const auto it = readings_.find(name);
  if (it == readings_.end()) return std::nullopt;
  return it->second;
}

// The radio is the simulator's: the server puts it to sleep (and says ERR if it cannot).
bool RemoteNode::SetRadioSleep(bool asleep) {
  Command(wire::ProtocolMessage{"RADIO"}.Add("Sleep", asleep ? "true" : "false"));
  return true;
}

std::optional<BearingReading> RemoteNode::Bearing(NodeId target) {
  const auto it = readings_.find("bearing");
  if (it == readings_.end()) return std::nullopt;
  for (const NodeBearing& b : std::get<BearingsReading>(it->second).in_range)
    if (b.node == target) return b.reading;
  return std::nullopt;
}

// Within the model's limits, as the simulated node: the server clamps nothing for wheel speeds.
bool RemoteNode::ApplyDrive(const Twist2D& v) {
  const auto& model = spec_.nodes[id_].model;
  wire::ProtocolMessage drive("DRIVE");
  const Twist2D c = robots::LimitDrive(model, v);
  const std::string steering = model.model().UsarsimSteering();
  if (steering == "SkidSteered") {
    const auto w = model.model().MakeKinematics(model)->WheelSpeeds(c);
    drive.Add("Left", w[0]).Add("Right", w[1]);
  } else if (steering == "OmniDrive") {
    drive.Add("LinearVelocity", c.vx).Add("LateralVelocity", -c.vy).Add("RotationalVelocity", -c.omega);
  } else {
    return false;
  }
  Command(drive);
  return true;
}

bool RemoteNode::ApplyWheelSpeeds(const std::vector<double>& w) {
  if (std::string(spec_.nodes[id_].model.model().UsarsimSteering()) != "SkidSteered" || w.size() != 2) return false;
  wire::ProtocolMessage drive("DRIVE");
  drive.Add("Left", w[0]).Add("Right", w[1]);
  Command(drive);
  return true;
}

bool RemoteNode::IsAgent(NodeId node) const { return sim::RunsAsAgent(spec_.nodes.at(node)); }

void RemoteNode::SendThroughServer(Delivery delivery, std::optional<NodeId> to, const Bytes& payload) {
  wire::ProtocolMessage send("SEND");
  send.Add("Delivery", DeliveryName(delivery));
  if (to) send.Add("To", NameOf(*to));
  send.Add("Data", wire::ToHex(payload));
  Command(send);
}

// Agents over UDP; nodes that live in the server through the robot's node there.
void RemoteNode::Send(NodeId to, const Bytes& payload) {
  if (to >= spec_.nodes.size() || to == id_) return;
  ++messages_sent_;
  if (IsAgent(to))
    peer_socket_->Send(to, wire::AgentDatagram::kUnicast, payload);
  else
    SendThroughServer(Delivery::kUnicast, to, payload);
}

void RemoteNode::Broadcast(const Bytes& payload) {
  ++messages_sent_;
  for (NodeId to = 0; to < spec_.nodes.size(); ++to)
    if (to != id_ && IsAgent(to)) peer_socket_->Send(to, wire::AgentDatagram::kBroadcast, payload);
  SendThroughServer(Delivery::kBroadcast, std::nullopt, payload);
}

void RemoteNode::Flood(const Bytes& payload) {
  ++messages_sent_;
  for (NodeId to = 0; to < spec_.nodes.size(); ++to)
    if (to != id_ && IsAgent(to)) peer_socket_->Send(to, wire::AgentDatagram::kBroadcast, payload);
  SendThroughServer(Delivery::kFlood, std::nullopt, payload);
}

namespace {

// Braces and line ends would end the protocol's field or line.
std::string FieldText(const std::string& text) {
  std::string clean = text;
  for (char& c : clean) c = c == '{' ? '(' : c == '}' ? ')' : (c == '\n' || c == '\r') ? ' ' : c;
  return clean;
}

}  // namespace

void RemoteNode::Log(const std::string& text) {
  wire::ProtocolMessage log("LOG");
  log.Add("Text", FieldText(text));
  Command(log);
}

void RemoteNode::Transition(const std::string& from, const std::string& to, const std::string& why) {
  wire::ProtocolMessage t("TRANSITION");
  t.Add("From", FieldText(from)).Add("To", FieldText(to));
  if (!why.empty()) t.Add("Why", FieldText(why));
  Command(t);
}

void RemoteNode::Metric(const std::string& name, double value) {
  wire::ProtocolMessage m("METRIC");
  m.Add("Name", FieldText(name)).Add("Value", wire::FormatPrecise(value));
  Command(m);
}

}  // namespace sanet::usarsim_agent
