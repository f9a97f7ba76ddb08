// The server's side of sanet's extensions for agents on other computers (docs/protocol.md,
// "sanet's extensions"): the version handshake, the scenario and plugin they fetch and compare,
// their peers' addresses, and their clock estimates.
#include <arpa/inet.h>

#include <algorithm>
#include <cstdio>

#include "core/version.h"
#include "robot_server/sim_server.h"
#include "wire/message_lines.h"
#include "wire/plugin_identity.h"

namespace sanet::robot_server {
namespace {

constexpr std::size_t kScenarioPart = 32768;  // bytes of YAML per SCENARIO line (twice that in hex)
constexpr double kLeastClockPeriod = 0.5;     // s between two CLOCK rows of one robot

bool IsIpv4(const std::string& text) {
  in_addr address{};
  return ::inet_pton(AF_INET, text.c_str(), &address) == 1;
}

}  // namespace

// Told why, then closed (after the ERR has gone out).
void SimServer::Refuse(Client& c, const std::string& why) {
  if (settings_.announce) std::printf("sanet: client %s %s\n", c.peer.c_str(), why.c_str());
  Error(c, why);
  Drop(c, why);  // what is queued, the ERR with it, goes out first
}

// SANET {Protocol n} {Version v} [{Fingerprint f}]: an agent says which sanet it is (and which
// scenario it holds); the server answers with its own, or refuses naming both.
void SimServer::Hello(Client& c, const wire::ProtocolMessage& m) {
  const auto protocol = m.Count("Protocol", 1000000);
  const std::string* version = m.Get("Version");
  const std::string theirs = "protocol " + (protocol ? std::to_string(*protocol) : std::string("?")) + " (sanet " +
                             (version ? *version : std::string("?")) + ")";
  const std::string mine = "protocol " + std::to_string(wire::kSanetProtocol) + " (sanet " + SanetVersion() + ")";
  if (!protocol || *protocol != static_cast<std::uint64_t>(wire::kSanetProtocol))
    return Refuse(c, "refused: this agent speaks sanet's " + theirs + ", the server " + mine +
                         "; run the same sanet on both computers");
  const std::string* fingerprint = m.Get("Fingerprint");
  if (fingerprint && *fingerprint != settings_.scenario_fingerprint)
    return Refuse(c, "refused: this agent's scenario has fingerprint " + *fingerprint + ", the server's " +
                         settings_.scenario_fingerprint +
                         "; give the agent the server's scenario, or leave out --scenario to fetch it");
  c.sanet = true;
  wire::ProtocolMessage reply{"SANET"};
  reply.Add("Protocol", std::to_string(wire::kSanetProtocol)).Add("Version", SanetVersion());
  reply.Add("Fingerprint", settings_.scenario_fingerprint);
  reply.Add("TimePort", std::to_string(time_service_ ? time_service_->port() : 0));
  Send(c, reply);
}

// GETSCENARIO {Part i}: the effective scenario in parts, so that no line outgrows what a client
// must buffer: SCENARIO {Part i} {Parts n} {Fingerprint f} {Yaml hex}.
void SimServer::SendScenario(Client& c, const wire::ProtocolMessage& m) {
  const std::string& yaml = settings_.scenario_yaml;
  const std::size_t parts = std::max<std::size_t>(1, (yaml.size() + kScenarioPart - 1) / kScenarioPart);
  const auto part = m.Get("Part") ? m.Count("Part", parts - 1) : std::optional<std::uint64_t>(0);
  if (!part) return Error(c, "GETSCENARIO {Part i}: i from 0 to " + std::to_string(parts - 1));
  const std::string text = yaml.substr(*part * kScenarioPart, kScenarioPart);
  wire::ProtocolMessage reply{"SCENARIO"};
  reply.Add("Part", std::to_string(*part)).Add("Parts", std::to_string(parts));
  reply.Add("Fingerprint", settings_.scenario_fingerprint).Add("Yaml", wire::ToHex(Bytes(text.begin(), text.end())));
  Send(c, reply);
}

// GETPLUGIN {Robot r}: which controller code the robot runs here.
void SimServer::SendPlugin(Client& c, const wire::ProtocolMessage& m) {
  const std::string* robot = m.Get("Robot");
  const auto id = robot ? driver_.Lookup(*robot) : std::nullopt;
  if (!id || !driver_.Spec(*id).controller)
    return Error(c, "GETPLUGIN {Robot r}: r must be a node with a controller in this scenario");
  wire::PluginIdentity plugin;
  try {
    plugin = wire::IdentifyPlugin(*driver_.Spec(*id).controller);
  } catch (const std::runtime_error& e) {
    return Error(c, e.what());
  }
  wire::ProtocolMessage reply{"PLUGIN"};
  reply.Add("Robot", *robot).Add("ControllerApi", std::to_string(plugin.controller_api));
  if (!plugin.library.empty()) reply.Add("Library", plugin.library).Add("Sha256", plugin.sha256);
  if (!plugin.python.empty()) reply.Add("Python", plugin.python);
  Send(c, reply);
}

// PEER {Address a} {Port p}: where this robot's agent listens for the other agents. Every agent
// that said SANET hears it (PEER {Name n} {Address a} {Port p}), and the newcomer hears the rest.
void SimServer::TakePeer(Client& c, const wire::ProtocolMessage& m) {
  const std::string* address = m.Get("Address");
  const auto port = m.Count("Port", 65535);
  if (!address || !IsIpv4(*address) || !port || *port == 0)
    return Error(c, "PEER needs {Address a.b.c.d} and {Port p} (1 to 65535)");
  peers_.resize(driver_.NodeCount());
  peers_[*c.robot] = Peer{*address, static_cast<std::uint16_t>(*port)};
  const auto line = [&](NodeId id) {
    return wire::ProtocolMessage{"PEER"}
        .Add("Name", driver_.NameOf(id))
        .Add("Address", peers_[id]->address)
        .Add("Port", std::to_string(peers_[id]->port));
  };
  for (auto& [id, other] : clients_) {
    if (!other.open || !other.sanet || !other.robot || &other == &c) continue;
    Send(other, line(*c.robot));
    if (*other.robot < peers_.size() && peers_[*other.robot]) Send(c, line(*other.robot));
  }
}

// CLOCK {Offset o} {Error e} {RoundTrip r} {Drift d}: an agent's clock estimate after a burst.
void SimServer::TakeClock(Client& c, const wire::ProtocolMessage& m) {
  const auto offset = m.Number("Offset"), error = m.Number("Error"), trip = m.Number("RoundTrip");
  const auto drift = m.Number("Drift");
  if (!offset || !error || !trip || !drift)
    return Error(c, "CLOCK needs {Offset s} {Error s} {RoundTrip s} {Drift s/s}");
  // An agent reports once a second; more often is no agent's doing, and would only grow the table.
  last_clock_row_.resize(driver_.NodeCount(), -1e300);
  if (driver_.Now() - last_clock_row_[*c.robot] < kLeastClockPeriod) return;
  last_clock_row_[*c.robot] = driver_.Now();
  clock_rows_.push_back(wire::FormatPrecise(driver_.Now()) + "," + trace::CsvField(driver_.NameOf(*c.robot)) + "," +
                        wire::FormatPrecise(*offset) + "," + wire::FormatPrecise(*error) + "," +
                        wire::FormatPrecise(*trip) + "," + wire::FormatPrecise(*drift * 1e6));
}

nlohmann::ordered_json SimServer::ClockSummary() const {
  nlohmann::ordered_json j;
  j["origin_monotonic_s"] = wall_start_;  // this machine's CLOCK_MONOTONIC at simulated time 0
  j["time_service_port"] = time_service_ ? time_service_->port() : 0;
  j["exchanges_served"] = time_service_ ? time_service_->served() : 0;
  return j;
}

}  // namespace sanet::robot_server
