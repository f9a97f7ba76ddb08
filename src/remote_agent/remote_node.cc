#include "remote_agent/remote_node.h"

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
#include "wire/sockets.h"
#include "wire/time_service.h"

namespace sanet::hil {
namespace {

// USARSim frame (y right, yaw clockwise) back to sanet's.
Pose2D FromUsarsim(double x, double y, double yaw) { return {x, -y, -yaw}; }

}  // namespace

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
  ProtocolMessage init("INIT");
  init.Add("ClassName", Holonomic() ? "sanet.omni3" : "USARBot.P2DX").Add("Name", Name());
  Command(init);
  Command(ProtocolMessage{"PEER"}
              .Add("Address", peer_socket_->address())
              .Add("Port", std::to_string(peer_socket_->port())));
}

RemoteNode::~RemoteNode() {
  ProtocolMessage stop("DRIVE");
  Holonomic() ? stop.Add("LinearVelocity", 0.0) : stop.Add("Left", 0.0).Add("Right", 0.0);
  Command(stop);
}

void RemoteNode::Command(const ProtocolMessage& m) { link_->Send(m); }

double RemoteNode::Now() const { return step_time_ ? *step_time_ : ClockNow(); }

double RemoteNode::ClockNow() const {
  if (clock_origin_) return MonotonicSeconds() - *clock_origin_;
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
  std::vector<ProtocolMessage> lines;
  const bool open = link_->Read(lines);
  for (const ProtocolMessage& m : lines) Take(m, deliver);
  peer_socket_->Read(deliver);
  return open;
}

// Lines from the server: sensors, status, messages from its nodes, errors.
void RemoteNode::Take(const ProtocolMessage& m, const std::function<void(const Message&)>& deliver) {
  if (m.type == "ERR") {  // fatal while claiming the robot; afterwards the run goes on
    const std::string* text = m.Get("Message");
    const std::string why = "server: " + (text ? *text : std::string("error"));
    if (!HasPose()) throw std::runtime_error(why);
    std::fprintf(stderr, "sanet agent %s: %s\n", Name().c_str(), why.c_str());
  }
  if (m.type == "MSG") {
    const std::string* from = m.Get("From");
    std::string error;
    if (auto message = ParseMsgLine(m, from ? Lookup(*from) : std::nullopt, id_, &error))
      deliver(*message);
    else
      throw std::runtime_error("server sent a bad MSG line: " + error);
  }
  if (m.type == "SEN") TakeSensor(m);
  if (m.type == "KEY")
    if (const std::string* hex = m.Get("Datagrams"))
      if (const auto key = DatagramKey::FromHex(*hex)) peer_socket_->SetKey(*key);
  if (m.type == "PEER") TakePeer(m);
}

// PEER {Name n} {Address a} {Port p}: where another agent listens (it said so to the server).
void RemoteNode::TakePeer(const ProtocolMessage& m) {
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

void RemoteNode::TakeSensor(const ProtocolMessage& m) {
  const std::string* type = m.Get("Type");
  if (!type) return;
  if (*type == "GroundTruth") {
    const auto at = m.Numbers("Location"), o = m.Numbers("Orientation");
    if (at && o && at->size() >= 2 && o->size() >= 3) truth_ = FromUsarsim((*at)[0], (*at)[1], (*o)[2]);
  } else if (*type == "Odometry") {
    const auto p = m.Numbers("Pose");
    if (p && p->size() >= 3) odometry_ = FromUsarsim((*p)[0], (*p)[1], (*p)[2]);
  } else if (*type == "RangeScanner") {
    const auto ranges = m.Numbers("Range");
    const auto fov = m.Number("FOV");
    const auto& laser = spec_.nodes[id_].model.sensors.laser;
    if (!ranges || !fov || ranges->empty()) return;
    RangeScan scan;
    scan.ranges = *ranges;
    scan.max_range = laser ? laser->max_range : 0;
    for (std::size_t i = 0; i < ranges->size(); ++i)  // right to left
      scan.angles.push_back(ranges->size() == 1 ? 0 : -*fov / 2 + *fov * i / (ranges->size() - 1));
    laser_ = scan;
  } else if (*type == "IR") {
    const auto& ir = spec_.nodes[id_].model.sensors.ir;
    if (!ir) return;
    RangeScan scan;
    scan.angles = ir->angles;
    scan.max_range = ir->max_range;
    for (const auto& [key, value] : m.fields)  // {Name IR0 Range 0.8}
      if (key == "Name") {
        const auto at = value.rfind(' ');
        scan.ranges.push_back(at == std::string::npos ? 0 : std::atof(value.c_str() + at + 1));
      }
    if (scan.ranges.size() == scan.angles.size()) ir_ = scan;
  } else if (*type == "Bearing") {
    TakeBearings(m);
  }
}

// {Name R Distance d Bearing b} per node in range; b in USARSim's frame (clockwise).
void RemoteNode::TakeBearings(const ProtocolMessage& m) {
  bearings_.clear();
  for (const auto& [key, value] : m.fields) {
    if (key != "Name") continue;
    char name[128];
    double distance = 0, angle = 0;
    if (std::sscanf(value.c_str(), "%127s Distance %lf Bearing %lf", name, &distance, &angle) != 3) continue;
    if (const auto node = Lookup(name)) bearings_[*node] = BearingReading{distance, -angle};
  }
}

std::optional<BearingReading> RemoteNode::Bearing(NodeId target) {
  const auto it = bearings_.find(target);
  if (it == bearings_.end()) return std::nullopt;
  return it->second;
}

// Within the model's limits, as the simulated node: the server clamps nothing for wheel speeds.
bool RemoteNode::ApplyDrive(const Twist2D& v) {
  const auto& model = spec_.nodes[id_].model;
  ProtocolMessage drive("DRIVE");
  const Twist2D c = robots::LimitDrive(model, v);
  if (model.kind == robots::ModelKind::kDiffDrive) {
    const auto w =
        robots::DiffDriveKinematics(model.diffdrive.axle_length, model.diffdrive.wheel_radius).WheelSpeeds(c);
    drive.Add("Left", w[0]).Add("Right", w[1]);
  } else if (model.kind == robots::ModelKind::kOmni3) {
    drive.Add("LinearVelocity", c.vx).Add("LateralVelocity", -c.vy).Add("RotationalVelocity", -c.omega);
  } else {
    return false;
  }
  Command(drive);
  return true;
}

bool RemoteNode::ApplyWheelSpeeds(const std::vector<double>& w) {
  if (spec_.nodes[id_].model.kind != robots::ModelKind::kDiffDrive || w.size() != 2) return false;
  ProtocolMessage drive("DRIVE");
  drive.Add("Left", w[0]).Add("Right", w[1]);
  Command(drive);
  return true;
}

bool RemoteNode::IsAgent(NodeId node) const { return sim::RunsAsAgent(spec_.nodes.at(node)); }

void RemoteNode::SendThroughServer(Delivery delivery, std::optional<NodeId> to, const Bytes& payload) {
  ProtocolMessage send("SEND");
  send.Add("Delivery", DeliveryName(delivery));
  if (to) send.Add("To", NameOf(*to));
  send.Add("Data", ToHex(payload));
  Command(send);
}

// Agents over UDP; nodes that live in the server through the robot's node there.
void RemoteNode::Send(NodeId to, const Bytes& payload) {
  if (to >= spec_.nodes.size() || to == id_) return;
  ++messages_sent_;
  if (IsAgent(to))
    peer_socket_->Send(to, AgentDatagram::kUnicast, payload);
  else
    SendThroughServer(Delivery::kUnicast, to, payload);
}

void RemoteNode::Broadcast(const Bytes& payload) {
  ++messages_sent_;
  for (NodeId to = 0; to < spec_.nodes.size(); ++to)
    if (to != id_ && IsAgent(to)) peer_socket_->Send(to, AgentDatagram::kBroadcast, payload);
  SendThroughServer(Delivery::kBroadcast, std::nullopt, payload);
}

void RemoteNode::Flood(const Bytes& payload) {
  ++messages_sent_;
  for (NodeId to = 0; to < spec_.nodes.size(); ++to)
    if (to != id_ && IsAgent(to)) peer_socket_->Send(to, AgentDatagram::kBroadcast, payload);
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
  ProtocolMessage log("LOG");
  log.Add("Text", FieldText(text));
  Command(log);
}

void RemoteNode::Transition(const std::string& from, const std::string& to, const std::string& why) {
  ProtocolMessage t("TRANSITION");
  t.Add("From", FieldText(from)).Add("To", FieldText(to));
  if (!why.empty()) t.Add("Why", FieldText(why));
  Command(t);
}

void RemoteNode::Metric(const std::string& name, double value) {
  ProtocolMessage m("METRIC");
  m.Add("Name", FieldText(name)).Add("Value", FormatPrecise(value));
  Command(m);
}

}  // namespace sanet::hil
