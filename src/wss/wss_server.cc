#include "wss/wss_server.h"

#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>

#include "wire/sockets.h"

namespace sanet::hil {
namespace {

constexpr std::size_t kMaxBacklog = 1 << 20;  // bytes waiting for a robot that does not read

// "5000,5001" or "5000 5001": whole port numbers, or nothing.
std::optional<std::vector<std::uint16_t>> Ports(const std::string& text) {
  std::vector<std::uint16_t> ports;
  std::string item;
  for (std::size_t i = 0; i <= text.size(); ++i) {
    if (i < text.size() && text[i] != ',' && text[i] != ' ') {
      if (!std::isdigit(static_cast<unsigned char>(text[i])) || item.size() > 5) return std::nullopt;
      item += text[i];
      continue;
    }
    if (item.empty()) continue;
    const long port = std::stol(item);
    if (port < 1 || port > 65535) return std::nullopt;
    ports.push_back(static_cast<std::uint16_t>(port));
    item.clear();
  }
  if (ports.empty()) return std::nullopt;
  return ports;
}

}  // namespace

WssServer::WssServer(sim::World& world, WssSettings settings) : world_(world), settings_(std::move(settings)) {
  listener_ = ListenTcp(settings_.bind, settings_.port, 64, &port_);
}

WssServer::~WssServer() {
  relays_.clear();
  for (auto& r : robots_)
    if (r->fd >= 0) ::close(r->fd);
  if (listener_ >= 0) ::close(listener_);
}

void WssServer::Start() {
  world_.Every(settings_.poll_period, [this] { Poll(); });
}

nlohmann::ordered_json WssServer::Summary() const {
  std::uint64_t cut = relays_cut_, connections = connections_, bytes = bytes_;
  for (const auto& [key, relay] : relays_)
    cut += relay->cut(), connections += relay->connections(), bytes += relay->bytes();
  return {{"port", port_},
          {"relays", relays_opened_},
          {"connections", connections},
          {"connections_cut", cut},
          {"bytes", bytes}};
}

void WssServer::Poll() {
  Accept();
  for (auto& r : robots_)
    if (r->fd >= 0) Read(*r);
  UpdateRelays();
  for (auto& r : robots_) {
    while (r->fd >= 0 && !r->out.empty()) {
      const ssize_t n = ::send(r->fd, r->out.data(), r->out.size(), MSG_NOSIGNAL);
      if (n < 0) {
        if (errno != EAGAIN && errno != EWOULDBLOCK) Drop(*r);
        break;
      }
      r->out.erase(0, n);
    }
  }
  robots_.erase(std::remove_if(robots_.begin(), robots_.end(), [](const auto& r) { return r->fd < 0; }), robots_.end());
}

void WssServer::Accept() {
  while (true) {
    const int fd = AcceptClient(listener_);
    if (fd < 0) return;
    auto robot = std::make_unique<Robot>();
    robot->fd = fd;
    robot->reader = LineReader(settings_.max_line);
    PeerOf(fd, &robot->host);
    robots_.push_back(std::move(robot));
  }
}

void WssServer::Read(Robot& r) {
  char buffer[4096];
  bool gone = false;
  while (true) {
    const ssize_t n = ::recv(r.fd, buffer, sizeof buffer, 0);
    if (n == 0 || (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK)) gone = true;
    if (n <= 0) break;
    r.reader.Append(std::string_view(buffer, n));
  }
  bool too_long = false;
  while (auto line = r.reader.Next(&too_long)) {
    if (line->find_first_not_of(" \t") == std::string::npos) continue;
    std::string error;
    if (auto m = ParseLine(*line, &error)) Handle(r, *m);
  }
  if (gone || too_long) Drop(r);
}

void WssServer::Handle(Robot& r, const ProtocolMessage& m) {
  if (r.name.empty()) return m.type == "INIT" ? Init(r, m) : Error(r, "Must.Use.INIT.Method.First");
  if (m.type == "GETSS") return GetSignal(r, m);
  if (m.type == "DNS") return Dns(r, m);
  if (m.type == "REVERSEDNS") return ReverseDns(r, m);
  Error(r, "Method.Unknown.Or.Can.INIT.only.once");
}

void WssServer::Init(Robot& r, const ProtocolMessage& m) {
  const std::string* name = m.Get("Robot");
  const std::string* ports = m.Get("Port");
  if (!name || name->empty()) return Error(r, "Robot.Name.Must.Not.Be.Empty");
  const auto list = ports ? Ports(*ports) : std::nullopt;
  if (!list) return Error(r, "Ports.List.Must.Be.Integer");
  if (Registered(*name)) return Error(r, "Robot.Alread.Exists");  // sic, as USARSim's WSS spells it
  const auto node = world_.Lookup(*name);
  if (!node) return Error(r, "Robot.Not.In.Simulation");  // sanet: its position comes from the world
  r.name = *name;
  r.node = *node;
  r.ports = *list;
  Send(r, ProtocolMessage("INITREPLY").Add("Status", "OK"));
}

void WssServer::GetSignal(Robot& r, const ProtocolMessage& m) {
  const std::string* other = m.Get("Robot");
  ProtocolMessage reply("SS");
  reply.Add("Robot", other ? *other : "");
  Robot* o = other ? Registered(*other) : nullptr;
  if (o == &r) return Send(r, reply.Add("Strength", "INF").Add("Error", "SS.To.Self"));
  if (!o) return Send(r, reply.Add("Strength", "NaN").Add("Error", "Robot.Does.Not.Exist"));
  const auto signal = world_.parts().SignalBetween(o->node, r.node);
  Send(r, signal ? reply.Add("Strength", FormatNumber(signal->received_dbm))
                 : reply.Add("Strength", "NaN").Add("Error", "No.Simulated.Radio"));
}

void WssServer::Dns(Robot& r, const ProtocolMessage& m) {
  const std::string* other = m.Get("Robot");
  ProtocolMessage reply("DNSREPLY");
  reply.Add("Robot", other ? *other : "");
  Robot* o = other ? Registered(*other) : nullptr;
  if (!o || o == &r) return Send(r, reply.Add("Port", "-1").Add("Error", "NoSuchRobot"));
  if (!world_.parts().SignalBetween(r.node, o->node))
    return Send(r, reply.Add("Port", "-1").Add("Error", "No.Simulated.Radio"));
  std::uint16_t port = o->ports.front();
  if (const std::string* asked = m.Get("Port")) {
    const auto list = Ports(*asked);
    if (!list || list->size() != 1 || std::find(o->ports.begin(), o->ports.end(), list->front()) == o->ports.end())
      return Send(r, reply.Add("Port", "-1").Add("Error", "RobotDoesNotListenOnThisPort"));
    port = list->front();
  }
  const RelayKey key{r.name, o->name, port};
  auto it = relays_.find(key);
  if (it == relays_.end()) {
    try {
      it = relays_.emplace(key, std::make_unique<WssRelay>(settings_.bind, o->host, port)).first;
      ++relays_opened_;
    } catch (const std::runtime_error&) {
      return Error(r, "Could.Not.Allocate.Port");
    }
    it->second->SetLinkUp(LinkUp(r.node, o->node));
  }
  Send(r, reply.Add("Port", std::to_string(it->second->port())));
}

// The robot whose relayed connection reaches this one from port `p` of the server's host.
void WssServer::ReverseDns(Robot& r, const ProtocolMessage& m) {
  const std::string* port = m.Get("Port");
  ProtocolMessage reply("REVERSEDNSREPLY");
  reply.Add("Port", port ? *port : "");
  const auto list = port ? Ports(*port) : std::nullopt;
  if (list && list->size() == 1)
    for (const auto& [key, relay] : relays_)
      if (std::get<1>(key) == r.name && relay->UsesLocalPort(list->front()))
        return Send(r, reply.Add("Robot", std::get<0>(key)));
  Send(r, reply.Add("Error", "UnknownOrIllegalPort"));
}

WssServer::Robot* WssServer::Registered(const std::string& name) {
  for (auto& r : robots_)
    if (r->fd >= 0 && r->name == name) return r.get();
  return nullptr;
}

// Both ways over the threshold: each robot's frames are detected by the other.
bool WssServer::LinkUp(NodeId a, NodeId b) const {
  const auto there = world_.parts().SignalBetween(a, b), back = world_.parts().SignalBetween(b, a);
  return there && back && there->received_dbm >= there->threshold_dbm && back->received_dbm >= back->threshold_dbm;
}

void WssServer::UpdateRelays() {
  for (auto& [key, relay] : relays_) {
    const auto from = world_.Lookup(std::get<0>(key)), to = world_.Lookup(std::get<1>(key));
    relay->SetLinkUp(from && to && LinkUp(*from, *to));
    relay->Pump();
  }
}

// Closing the control connection deregisters the robot: its relays, both ways, go with it.
void WssServer::Drop(Robot& r) {
  if (r.fd < 0) return;
  ::close(r.fd);
  r.fd = -1;
  for (auto it = relays_.begin(); it != relays_.end();) {
    if (!r.name.empty() && (std::get<0>(it->first) == r.name || std::get<1>(it->first) == r.name)) {
      relays_cut_ += it->second->cut();
      connections_ += it->second->connections();
      bytes_ += it->second->bytes();
      it = relays_.erase(it);
    } else {
      ++it;
    }
  }
}

void WssServer::Send(Robot& r, const ProtocolMessage& m) {
  r.out += FormatLine(m);
  if (r.out.size() > kMaxBacklog) Drop(r);
}

void WssServer::Error(Robot& r, const std::string& reason) { Send(r, ProtocolMessage("ERROR").Add("Reason", reason)); }

}  // namespace sanet::hil
