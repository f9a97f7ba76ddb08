#include "wss/wss_server.h"

#include <algorithm>
#include <cctype>

namespace sanet::wss {
namespace {

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

WssServer::WssServer(sim::Driver& driver, WssSettings settings) : driver_(driver), settings_(std::move(settings)) {
  wire::LineServer::Events events;
  events.connected = [this](wire::ConnectionId id) {
    Robot& robot = robots_[id] = Robot{};
    robot.id = id;
    robot.host = lines_->PeerHost(id);
  };
  events.line = [this](wire::ConnectionId id, const std::string& line) {
    std::string error;
    if (auto m = wire::ParseLine(line, &error)) Handle(robots_.at(id), *m);  // WSS has no word for a malformed line
  };
  events.gone = [this](wire::ConnectionId id, const std::string&) { Gone(id); };
  events.refusal_line = [](const std::string& why) {
    return wire::FormatLine(wire::ProtocolMessage("ERROR").Add("Reason", "Too.Many.Connections: " + why));
  };
  events.silence_line = [](const std::string& why) {
    return wire::FormatLine(wire::ProtocolMessage("ERROR").Add("Reason", "Handshake.Timeout: " + why));
  };
  wire::LineServerSettings lines;
  lines.bind = settings_.bind;
  lines.port = settings_.port;
  lines.max_clients = settings_.max_clients;
  lines.cap_option = "--wss-max-clients";
  lines.max_line = settings_.max_line;
  lines_ = std::make_unique<wire::LineServer>(lines, std::move(events));
}

WssServer::~WssServer() { relays_.clear(); }

void WssServer::Start() {
  driver_.Every(settings_.poll_period, [this] { Poll(); });
}

nlohmann::ordered_json WssServer::Summary() const {
  std::uint64_t cut = relays_cut_, connections = connections_, bytes = bytes_;
  for (const auto& [key, relay] : relays_)
    cut += relay->cut(), connections += relay->connections(), bytes += relay->bytes();
  return {{"port", lines_->port()},
          {"relays", relays_opened_},
          {"connections", connections},
          {"connections_cut", cut},
          {"bytes", bytes}};
}

void WssServer::Poll() {
  lines_->Read();
  UpdateRelays();
  lines_->Write();
  for (auto it = robots_.begin(); it != robots_.end();) it = it->second.open ? std::next(it) : robots_.erase(it);
}

void WssServer::Handle(Robot& r, const wire::ProtocolMessage& m) {
  if (r.name.empty()) return m.type == "INIT" ? Init(r, m) : Error(r, "Must.Use.INIT.Method.First");
  if (m.type == "GETSS") return GetSignal(r, m);
  if (m.type == "DNS") return Dns(r, m);
  if (m.type == "REVERSEDNS") return ReverseDns(r, m);
  Error(r, "Method.Unknown.Or.Can.INIT.only.once");
}

void WssServer::Init(Robot& r, const wire::ProtocolMessage& m) {
  const std::string* name = m.Get("Robot");
  const std::string* ports = m.Get("Port");
  if (!name || name->empty()) return Error(r, "Robot.Name.Must.Not.Be.Empty");
  const auto list = ports ? Ports(*ports) : std::nullopt;
  if (!list) return Error(r, "Ports.List.Must.Be.Integer");
  if (Registered(*name)) return Error(r, "Robot.Alread.Exists");  // sic, as USARSim's WSS spells it
  const auto node = driver_.Lookup(*name);
  if (!node) return Error(r, "Robot.Not.In.Simulation");  // sanet: its position comes from the world
  r.name = *name;
  r.node = *node;
  r.ports = *list;
  lines_->Register(r.id);  // a registered robot keeps its slot when the cap is full
  Send(r, wire::ProtocolMessage("INITREPLY").Add("Status", "OK"));
}

void WssServer::GetSignal(Robot& r, const wire::ProtocolMessage& m) {
  const std::string* other = m.Get("Robot");
  wire::ProtocolMessage reply("SS");
  reply.Add("Robot", other ? *other : "");
  // Any node of the world answers, registered or not, as USARSim's WSS answers for any robot in
  // the game.
  const std::optional<NodeId> o = other ? driver_.Lookup(*other) : std::nullopt;
  if (o == r.node) return Send(r, reply.Add("Strength", "INF").Add("Error", "SS.To.Self"));
  if (!o) return Send(r, reply.Add("Strength", "NaN").Add("Error", "Robot.Does.Not.Exist"));
  const auto signal = driver_.SignalBetween(*o, r.node);
  Send(r, signal ? reply.Add("Strength", wire::FormatNumber(signal->received_dbm))
                 : reply.Add("Strength", "NaN").Add("Error", "No.Simulated.Radio"));
}

void WssServer::Dns(Robot& r, const wire::ProtocolMessage& m) {
  const std::string* other = m.Get("Robot");
  wire::ProtocolMessage reply("DNSREPLY");
  reply.Add("Robot", other ? *other : "");
  Robot* o = other ? Registered(*other) : nullptr;
  // A robot of the world that has not registered has no ports to relay to: WSS's NoSuchRobot,
  // with sanet's reason beside it.
  if (!o && other && driver_.Lookup(*other))
    return Send(r, reply.Add("Port", "-1").Add("Error", "NoSuchRobot").Add("Why", "Not.Registered.With.WSS"));
  if (!o || o == &r) return Send(r, reply.Add("Port", "-1").Add("Error", "NoSuchRobot"));
  if (!driver_.SignalBetween(r.node, o->node))
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
void WssServer::ReverseDns(Robot& r, const wire::ProtocolMessage& m) {
  const std::string* port = m.Get("Port");
  wire::ProtocolMessage reply("REVERSEDNSREPLY");
  reply.Add("Port", port ? *port : "");
  const auto list = port ? Ports(*port) : std::nullopt;
  if (list && list->size() == 1)
    for (const auto& [key, relay] : relays_)
      if (std::get<1>(key) == r.name && relay->UsesLocalPort(list->front()))
        return Send(r, reply.Add("Robot", std::get<0>(key)));
  Send(r, reply.Add("Error", "UnknownOrIllegalPort"));
}

WssServer::Robot* WssServer::Registered(const std::string& name) {
  for (auto& [id, r] : robots_)
    if (r.open && r.name == name) return &r;
  return nullptr;
}

// Both ways over the threshold: each robot's frames are detected by the other.
bool WssServer::LinkUp(NodeId a, NodeId b) const {
  const auto there = driver_.SignalBetween(a, b), back = driver_.SignalBetween(b, a);
  return there && back && there->received_dbm >= there->threshold_dbm && back->received_dbm >= back->threshold_dbm;
}

void WssServer::UpdateRelays() {
  for (auto& [key, relay] : relays_) {
    const auto from = driver_.Lookup(std::get<0>(key)), to = driver_.Lookup(std::get<1>(key));
    relay->SetLinkUp(from && to && LinkUp(*from, *to));
    relay->Pump();
  }
}

// Closing the control connection deregisters the robot: its relays, both ways, go with it.
void WssServer::Gone(wire::ConnectionId id) {
  Robot& r = robots_.at(id);
  r.open = false;
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

void WssServer::Send(Robot& r, const wire::ProtocolMessage& m) {
  if (r.open) lines_->Send(r.id, wire::FormatLine(m));
}

void WssServer::Error(Robot& r, const std::string& reason) {
  Send(r, wire::ProtocolMessage("ERROR").Add("Reason", reason));
}

}  // namespace sanet::wss
