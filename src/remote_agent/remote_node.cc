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
#include "sanet/codec.h"
#include "wire/message_lines.h"
#include "wire/sockets.h"
#include "wire/time_service.h"

namespace sanet::hil {
namespace {

constexpr std::uint8_t kUnicast = AgentDatagram::kUnicast, kBroadcast = AgentDatagram::kBroadcast;
constexpr std::size_t kMostHeldEarly = 1024;  // datagrams kept until the agent has its clock and key

// A network interface as the peer socket needs it: its first IPv4 address ("" if none), and
// whether it is up and running.
struct InterfaceState {
  std::string address;
  bool up = false;
};

InterfaceState LookUpInterface(const std::string& interface) {
  ifaddrs* all = nullptr;
  if (::getifaddrs(&all) != 0) throw std::runtime_error(std::string("cannot list interfaces: ") + std::strerror(errno));
  InterfaceState state;
  for (const ifaddrs* a = all; a; a = a->ifa_next) {
    if (interface != a->ifa_name) continue;
    state.up = state.up || ((a->ifa_flags & IFF_UP) && (a->ifa_flags & IFF_RUNNING));
    if (state.address.empty() && a->ifa_addr && a->ifa_addr->sa_family == AF_INET)
      state.address = AddressText(a->ifa_addr);
  }
  ::freeifaddrs(all);
  return state;
}

// USARSim frame (y right, yaw clockwise) back to sanet's.
Pose2D FromUsarsim(double x, double y, double yaw) { return {x, -y, -yaw}; }

}  // namespace

RemoteNode::RemoteNode(const sim::RunSpec& spec, NodeId robot, AgentSettings settings, std::unique_ptr<ServerLink> link)
    : spec_(spec),
      id_(robot),
      settings_(std::move(settings)),
      link_(std::move(link)),
      random_(spec.seed, "node/" + spec.nodes.at(robot).name + "/controller"),
      peers_(spec.nodes.size()),
      replays_(spec.nodes.size()) {
  // The clock first: everything the agent stamps is on it.
  if (settings_.shared_clock) {
    clock_origin_ = link_->clock_origin();
    if (!clock_origin_)
      throw std::runtime_error("--shared-clock: the server at " + link_->address() + " gave no ClockOrigin");
  } else {
    clock_sync_ = std::make_unique<ClockSync>(link_->host(), settings_.time_port, settings_.clock_skew);
  }
  for (const sections::PeerLink& p : settings_.peers)
    if (const auto node = Lookup(p.robot); node && !p.address.empty())
      peers_[*node] = Ipv4Endpoint(p.address, PortOf(*node));
  OpenPeerSocket();
  LoopNetworkView::Hooks hooks{[this] { return Now(); }, [this] { return PeerAddresses(); },
                               [this](const std::string& text) { Log(text); },
                               [this](const std::string& name) { return Lookup(name); }};
  view_ = std::make_unique<LoopNetworkView>(spec_, id_, *link_, std::move(hooks));
  ProtocolMessage init("INIT");
  init.Add("ClassName", Holonomic() ? "sanet.omni3" : "USARBot.P2DX").Add("Name", Name());
  Command(init);
  Command(ProtocolMessage{"PEER"}.Add("Address", peer_address_).Add("Port", std::to_string(PortOf(id_))));
}

RemoteNode::~RemoteNode() {
  ProtocolMessage stop("DRIVE");
  Holonomic() ? stop.Add("LinearVelocity", 0.0) : stop.Add("Left", 0.0).Add("Right", 0.0);
  Command(stop);
  if (udp_ >= 0) ::close(udp_);
}

// The robot's peer socket: on the address and interface its peer link gives (the command line
// over the scenario's loop.peers), else on the one-machine rule's address.
void RemoteNode::OpenPeerSocket() {
  const auto link = std::find_if(settings_.peers.begin(), settings_.peers.end(),
                                 [&](const sections::PeerLink& p) { return p.robot == Name(); });
  const bool linked = link != settings_.peers.end();
  const std::string interface = !settings_.peer_interface.empty() ? settings_.peer_interface
                                : linked                          ? link->interface
                                                                  : "";
  std::string address = !settings_.peer_address.empty() ? settings_.peer_address : linked ? link->address : "";
  const InterfaceState state = interface.empty() ? InterfaceState{"", true} : LookUpInterface(interface);
  if (address.empty() && !interface.empty() && state.address.empty())
    throw std::runtime_error("interface " + interface + " has no IPv4 address (or does not exist)");
  if (address.empty()) address = interface.empty() ? HostOf(id_) : state.address;
  udp_ = ::socket(AF_INET, SOCK_DGRAM, 0);
  if (!interface.empty() &&
      ::setsockopt(udp_, SOL_SOCKET, SO_BINDTODEVICE, interface.c_str(), static_cast<socklen_t>(interface.size())) != 0)
    throw std::runtime_error(
        "cannot bind the peer socket to interface " + interface + ": " + std::strerror(errno) +
        (errno == EPERM ? " (before Linux 5.7, binding to an interface needs root or CAP_NET_RAW)" : ""));
  const sockaddr_in mine = Ipv4Endpoint(address, PortOf(id_));
  if (::bind(udp_, reinterpret_cast<const sockaddr*>(&mine), sizeof mine) != 0)
    throw std::runtime_error("cannot bind UDP " + address + ":" + std::to_string(PortOf(id_)) + ": " +
                             std::strerror(errno));
  ::fcntl(udp_, F_SETFL, O_NONBLOCK);
  peers_[id_] = mine;
  peer_address_ = address;
  peer_endpoint_ = address + ":" + std::to_string(PortOf(id_)) + (interface.empty() ? "" : " on " + interface);
  if (!state.up)
    std::fprintf(stderr,
                 "sanet agent %s: warning: interface %s is down: datagrams to and from the other robots "
                 "will not get through until it is up\n",
                 Name().c_str(), interface.c_str());
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
  ReadUdp(deliver);
  return open;
}

// A datagram from a peer is checked and stamped with this agent's clock when it is read; one
// that comes before the agent has the run's key (a peer that started sooner) waits.
void RemoteNode::ReadUdp(const std::function<void(const Message&)>& deliver) {
  const bool ready = key_.has_value();
  if (ready) {
    for (const Bytes& d : early_) TakeDatagram(d, deliver);
    early_.clear();
  }
  std::uint8_t buffer[65536];
  while (true) {
    const ssize_t n = ::recv(udp_, buffer, sizeof buffer, 0);
    if (n <= 0) break;
    Bytes datagram(buffer, buffer + n);
    if (ready)
      TakeDatagram(datagram, deliver);
    else if (early_.size() < kMostHeldEarly)
      early_.push_back(std::move(datagram));
    else
      Reject("more than " + std::to_string(kMostHeldEarly) + " datagrams before the agent had the run's key");
  }
}

void RemoteNode::TakeDatagram(const Bytes& datagram, const std::function<void(const Message&)>& deliver) {
  std::string why;
  const auto d = OpenDatagram(datagram.data(), datagram.size(), *key_, &why);
  if (!d) return Reject(why);
  if (d->from >= spec_.nodes.size() || d->from == id_) return Reject("from no other node of the scenario");
  if (d->kind == kUnicast ? d->to != id_ : d->to != AgentDatagram::kToAll) return Reject("not for this robot");
  if (!replays_[d->from].Take(d->sequence))
    return Reject("sequence number " + std::to_string(d->sequence) + " of " + NameOf(d->from) + " seen before");
  Message m;
  m.from = d->from;
  m.to = d->kind == kUnicast ? id_ : sanet::kBroadcast;
  m.delivery = d->kind == kUnicast ? Delivery::kUnicast : Delivery::kBroadcast;
  m.time_sent = d->time_sent;
  m.time_received = ClockNow();
  m.hops = 1;
  m.payload = d->payload;
  ++datagrams_.received;
  deliver(m);
}

// The first rejection is said on stderr; all are counted (STATS, agents.csv).
void RemoteNode::Reject(const std::string& why) {
  if (datagrams_.rejected++ == 0)
    std::fprintf(stderr, "sanet agent %s: rejected a datagram: %s (further ones are only counted)\n", Name().c_str(),
                 why.c_str());
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
    if (const std::string* hex = m.Get("Datagrams")) key_ = DatagramKey::FromHex(*hex);
  if (m.type == "PEER") TakePeer(m);
}

// PEER {Name n} {Address a} {Port p}: where another agent listens (it said so to the server).
void RemoteNode::TakePeer(const ProtocolMessage& m) {
  const std::string *name = m.Get("Name"), *address = m.Get("Address");
  const auto node = name ? Lookup(*name) : std::nullopt;
  const auto port = m.Count("Port", 65535);
  if (!node || !address || !port || *node == id_) return;
  try {
    peers_[*node] = Ipv4Endpoint(*address, static_cast<std::uint16_t>(*port));
  } catch (const std::runtime_error&) {
    std::fprintf(stderr, "sanet agent %s: the server gave %s a peer address that is none: %s\n", Name().c_str(),
                 name->c_str(), address->c_str());
  }
}

// Where each node's agent listens for the others, as far as this agent knows: the network
// view's map from the kernel's addresses to nodes.
std::vector<std::optional<Ipv4>> RemoteNode::PeerAddresses() const {
  std::vector<std::optional<Ipv4>> addresses(spec_.nodes.size());
  for (NodeId id = 0; id < spec_.nodes.size(); ++id)
    if (peers_[id])
      addresses[id] = peers_[id]->sin_addr.s_addr;
    else if (!settings_.udp_subnet.empty() && IsAgent(id))
      addresses[id] = Ipv4Endpoint(HostOf(id), 0).sin_addr.s_addr;
  return addresses;
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

bool RemoteNode::ApplyDrive(const Twist2D& v) {
  const auto& model = spec_.nodes[id_].model;
  ProtocolMessage drive("DRIVE");
  if (model.kind == robots::ModelKind::kDiffDrive) {
    // The server clamps nothing for wheel speeds: apply the model's limits here, as the
    // simulated node does.
    Twist2D c = v;
    c.vx = std::clamp(c.vx, -model.max_speed, model.max_speed);
    c.omega = std::clamp(c.omega, -model.max_turn_rate, model.max_turn_rate);
    const auto w =
        robots::DiffDriveKinematics(model.diffdrive.axle_length, model.diffdrive.wheel_radius).WheelSpeeds(c);
    drive.Add("Left", w[0]).Add("Right", w[1]);
  } else if (model.kind == robots::ModelKind::kOmni3) {
    drive.Add("LinearVelocity", v.vx).Add("LateralVelocity", -v.vy).Add("RotationalVelocity", -v.omega);
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

void RemoteNode::SendUdp(NodeId to, std::uint8_t kind, const Bytes& payload) {
  if (!key_) {  // a server that gave no key: the peers would reject what this agent sends
    ++datagrams_.send_errors;
    return;
  }
  AgentDatagram d;
  d.from = id_;
  d.to = kind == kUnicast ? to : AgentDatagram::kToAll;
  d.kind = static_cast<AgentDatagram::Kind>(kind);
  d.sequence = next_sequence_++;
  d.time_sent = ClockNow();
  d.payload = payload;
  const Bytes datagram = SealDatagram(d, *key_);
  const sockaddr_in peer = peers_[to] ? *peers_[to] : Ipv4Endpoint(HostOf(to), PortOf(to));
  const ssize_t n =
      ::sendto(udp_, datagram.data(), datagram.size(), 0, reinterpret_cast<const sockaddr*>(&peer), sizeof peer);
  ++(n < 0 ? datagrams_.send_errors : datagrams_.sent);
}

std::string RemoteNode::HostOf(NodeId node) const {
  return settings_.udp_subnet.empty() ? settings_.udp_host : settings_.udp_subnet + "." + std::to_string(node + 1);
}

std::uint16_t RemoteNode::PortOf(NodeId node) const {
  return static_cast<std::uint16_t>(settings_.udp_base_port + (settings_.udp_subnet.empty() ? node : 0));
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
    SendUdp(to, kUnicast, payload);
  else
    SendThroughServer(Delivery::kUnicast, to, payload);
}

void RemoteNode::Broadcast(const Bytes& payload) {
  ++messages_sent_;
  for (NodeId to = 0; to < spec_.nodes.size(); ++to)
    if (to != id_ && IsAgent(to)) SendUdp(to, kBroadcast, payload);
  SendThroughServer(Delivery::kBroadcast, std::nullopt, payload);
}

void RemoteNode::Flood(const Bytes& payload) {
  ++messages_sent_;
  for (NodeId to = 0; to < spec_.nodes.size(); ++to)
    if (to != id_ && IsAgent(to)) SendUdp(to, kBroadcast, payload);
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
