// A Wireless Simulation Server endpoint, compatible with the control protocol of USARSim's WSS:
// robots' programs register (INIT {Robot R} {Port p,...}), ask for signal strength (GETSS), ask
// for a relay port to reach another robot (DNS) and who is behind a relayed connection
// (REVERSEDNS). Signal strength and whether a relayed connection lives come from the simulated
// radio: ns-3's propagation loss at the robots' simulated positions and the radio's detection
// threshold, not from a distance formula. It runs in `sanet serve`, polled on the simulation
// clock; docs/protocol.md describes every message.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <tuple>
#include <vector>

#include "sim/driver.h"
#include "wire/line_server.h"
#include "wire/protocol.h"
#include "wss/wss_relay.h"

namespace sanet::wss {

struct WssSettings {
  std::string bind = "127.0.0.1";
  std::uint16_t port = 50000;  // USARSim's WSS default; 0: any free port
  double poll_period = 0.005;  // s between polls of the sockets and the links
  std::size_t max_line = 4096;
  std::size_t max_clients = 64;  // control connections at once (--wss-max-clients)
};

class WssServer {
 public:
  WssServer(sim::Driver& driver, WssSettings settings);  // listens; throws std::runtime_error
  ~WssServer();
  std::uint16_t port() const { return lines_->port(); }
  void Start();  // polls on the simulation clock
  // Relays opened and cut and bytes carried, for summary.json.
  nlohmann::ordered_json Summary() const;

 private:
  // A control connection (LineServer keeps its socket and buffers) and the robot it registered.
  struct Robot {
    wire::ConnectionId id = 0;
    std::string host;  // where its control connection comes from: its ports are there
    bool open = true;
    std::string name;  // empty until INIT
    NodeId node = 0;
    std::vector<std::uint16_t> ports;
  };
  using RelayKey = std::tuple<std::string, std::string, std::uint16_t>;  // from, to, port of `to`

  void Poll();
  void Gone(wire::ConnectionId id);
  void Handle(Robot& r, const wire::ProtocolMessage& m);
  void Init(Robot& r, const wire::ProtocolMessage& m);
  void GetSignal(Robot& r, const wire::ProtocolMessage& m);
  void Dns(Robot& r, const wire::ProtocolMessage& m);
  void ReverseDns(Robot& r, const wire::ProtocolMessage& m);
  Robot* Registered(const std::string& name);
  bool LinkUp(NodeId a, NodeId b) const;
  void UpdateRelays();
  void Send(Robot& r, const wire::ProtocolMessage& m);
  void Error(Robot& r, const std::string& reason);

  sim::Driver& driver_;
  WssSettings settings_;
  std::map<wire::ConnectionId, Robot> robots_;
  std::unique_ptr<wire::LineServer> lines_;
  std::map<RelayKey, std::unique_ptr<WssRelay>> relays_;
  std::uint64_t relays_cut_ = 0, connections_ = 0, bytes_ = 0;  // of relays already gone
  std::uint64_t relays_opened_ = 0;
};

}  // namespace sanet::wss
