// An agent's connection to the server: the robot protocol's TCP connection, and the sanet
// extensions an agent uses before it drives its robot: the version handshake, the scenario and
// the controller plugin's identity fetched from the server (docs/protocol.md, "sanet's
// extensions").
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "wire/plugin_identity.h"
#include "wire/protocol.h"

namespace sanet::usarsim_agent {

// The server's answer to the handshake.
struct ServerHello {
  std::string version;      // sanet's
  std::string fingerprint;  // of the scenario it serves
  std::uint16_t time_port = 0;
};

class ServerLink {
 public:
  // Connects (retrying for ten seconds: the server may still be starting) and reads its greeting.
  // Throws std::runtime_error naming the server.
  ServerLink(const std::string& host, std::uint16_t port);
  ~ServerLink();
  ServerLink(const ServerLink&) = delete;
  ServerLink& operator=(const ServerLink&) = delete;

  const std::string& host() const { return host_; }
  const std::string& address() const { return address_; }  // "host:port", for messages
  // The server's monotonic clock at simulated time 0 (its greeting says it), for --shared-clock.
  std::optional<double> clock_origin() const { return clock_origin_; }
  // The server's time service (UDP), from the handshake.
  std::uint16_t time_port() const { return time_port_; }

  // Says which sanet this is (and the fingerprint of the scenario this agent holds, if any).
  // Throws when the server refuses, speaks another protocol version, or no sanet extensions at all.
  ServerHello Handshake(int protocol, const std::string& fingerprint);
  std::string FetchScenario();  // the effective scenario, YAML
  wire::PluginIdentity FetchPlugin(const std::string& robot);

  void Send(const wire::ProtocolMessage& m);
  // Sends `request` and waits up to `timeout` s for its answer, a line of `reply_type` or an ERR
  // that names the request; lines that come meanwhile wait for Read. Nothing on a timeout.
  std::optional<wire::ProtocolMessage> Ask(const wire::ProtocolMessage& request, const std::string& reply_type,
                                           double timeout);
  // The lines that have arrived, without waiting; false once the server has closed.
  bool Read(std::vector<wire::ProtocolMessage>& lines);

 private:
  wire::ProtocolMessage Await(const std::string& type, const std::string& request);
  std::optional<wire::ProtocolMessage> WaitFor(const std::function<bool(const wire::ProtocolMessage&)>& answers,
                                               double timeout);
  std::string host_, address_;
  int fd_ = -1;
  wire::LineReader reader_{1 << 20};
  std::vector<wire::ProtocolMessage> waiting_;  // lines read while awaiting another
  std::optional<double> clock_origin_;
  std::uint16_t time_port_ = 0;
};

}  // namespace sanet::usarsim_agent
