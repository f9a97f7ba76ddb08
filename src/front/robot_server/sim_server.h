// The simulation server of communication-in-the-loop runs: a TCP server speaking the
// USARSim-compatible protocol (protocol.h) on top of a World that runs against the wall clock.
// A client claims one of the scenario's robots with INIT, drives it with DRIVE and receives its
// sensors as SEN lines and its status as STA lines; with the sanet extensions it sends messages
// from its robot's ns-3 node (SEND) and receives those that reach it (MSG), and reports its
// controller's transitions and metrics. Everything a client does goes through its robot's
// simulated node, as an in-process controller's calls do, so the run's rules (switch-off) hold.
// It is polled on the simulation clock and watches the world as an observer; no client can
// block it: sockets are non-blocking, every client's lines are taken in turns of bounded size
// within a time budget per poll, buffers are bounded, and connections are capped.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "robot_server/attendance.h"
#include "sections/spawn_section.h"
#include "sim/driver.h"
#include "sim/fresh_samples.h"
#include "trace/results_folder.h"
#include "wire/agent_datagram.h"
#include "wire/line_server.h"
#include "wire/protocol.h"
#include "wire/sockets.h"
#include "wire/time_service.h"

namespace sanet::robot_server {

struct ServerSettings {
  std::string bind = "127.0.0.1";      // loopback unless told otherwise
  std::uint16_t port = 3000;           // 0: any free port
  double sensor_period = 0.1;          // s between SEN lines per sensor
  double status_period = 0.2;          // s between STA lines
  double poll_period = 0.005;          // s between socket polls
  double net_period = 0.02;            // s of simulated time between two NET answers to one client
  std::size_t max_line = 4096;         // bytes; a longer line closes the connection
  std::size_t max_backlog = 1 << 20;   // bytes waiting for a client that does not read: then it is dropped
  double stall_timeout = 2.0;          // s a client may leave its lines unread before it is dropped
  std::size_t max_clients = 64;        // connections at once; more are told ERR and closed
  std::size_t lines_per_turn = 32;     // lines taken from one client before the next has its turn
  std::size_t bytes_per_turn = 16384;  // bytes read from one client per turn
  double finish_wait = 5.0;            // s the controllers of agents may take to finish (END .. FINISHED)
  double poll_budget = 0.0015;         // s of line handling per poll; the rest waits for the next poll
  // What agents fetch and compare (sanet extensions): the effective scenario and its fingerprint.
  std::string scenario_yaml, scenario_fingerprint;
  // The scenario's spawn section: robots clients may add with INIT (none without one).
  std::optional<sections::SpawnSpec> spawn;
  bool announce = false;  // say on stdout which client drives which robot, and who is refused
};

// `text` for an ERR line: a field in braces written 'Name' (one word) or (Name value), lone
// braces as '.
std::string WithoutBraces(const std::string& text);

// The default connection cap: twice the robots, and never fewer than 64.
std::size_t DefaultMaxClients(const sim::RunSpec& spec);

class SimServer {
 public:
  SimServer(sim::Driver& driver, ServerSettings settings);  // listens; throws std::runtime_error
  ~SimServer();
  std::uint16_t port() const { return lines_->port(); }
  void Start();                                        // schedules polling and lag measurement on the simulation clock
  void AfterStep(const sim::WorldSnapshot& snapshot);  // heard on the run's bus
  // Lag of every physics step behind the wall clock: p50, p99, max, missed deadlines.
  nlohmann::ordered_json LagSummary() const;
  // What each agent last reported of its steps and messages (STATS lines), by robot.
  const nlohmann::ordered_json& AgentStats() const { return agent_stats_; }
  // The same as a table, agents.csv (nothing without agents), and the agents' clock estimates
  // through the run, clock.csv.
  void WriteAgentTable(trace::ResultsFolder& folder) const;
  // Which robots with a controller (agents' robots) clients drove, and when.
  const Attendance& attendance() const { return attendance_; }
  Attendance& attendance() { return attendance_; }
  // The time service's port and the clock's origin, for summary.json.
  nlohmann::ordered_json ClockSummary() const;

 private:
  Subscription step_ended_;  // AfterStep, on the run's bus
  // What the server knows of a connection (LineServer keeps its socket and buffers).
  struct Client {
    Client(wire::ConnectionId connection, std::string address) : id(connection), peer(std::move(address)) {}
    wire::ConnectionId id;
    std::string peer;  // host:port
    bool open = true;  // until the line server says it is gone
    std::optional<NodeId> robot;
    double next_sensors = 0, next_status = 0;
    bool told_off = false;    // told once that its robot is switched off
    bool agent = false;       // it has sent STATS: a sanet agent, which speaks five times a second
    bool sanet = false;       // it has said SANET: it understands sanet's extension lines
    bool net_asked = false;   // it has sent GETNET, not answered yet
    bool finished = false;    // it has said FINISHED after the run's END
    double next_net = 0;      // the rate limit's: no NET answer before this time
    sim::FreshSamples fresh;  // the samples of sensors on their own clocks already sent
  };
  void Poll();
  void FinishAgents();
  void SetRadioSleep(Client& c, const wire::ProtocolMessage& m);
  void Greet(wire::ConnectionId id);
  void Gone(wire::ConnectionId id, const std::string& why);
  void Handle(Client& c, const wire::ProtocolMessage& m);
  void Init(Client& c, const wire::ProtocolMessage& m);
  void Claim(Client& c, NodeId robot, const std::string* usarsim_class);
  void Spawn(Client& c, const std::string& usarsim_class, const std::string& name, const wire::ProtocolMessage& m);
  void Drive(Client& c, const wire::ProtocolMessage& m);
  void SendMessage(Client& c, const wire::ProtocolMessage& m);
  void Report(Client& c, const wire::ProtocolMessage& m);
  void TakeStats(Client& c, const wire::ProtocolMessage& m);
  // sanet's extensions for agents (robot_server/server_extensions.cc).
  void Hello(Client& c, const wire::ProtocolMessage& m);
  void SendScenario(Client& c, const wire::ProtocolMessage& m);
  void SendPlugin(Client& c, const wire::ProtocolMessage& m);
  void TakePeer(Client& c, const wire::ProtocolMessage& m);
  void TakeClock(Client& c, const wire::ProtocolMessage& m);
  // The routing view in the loop (robot_server/network_lines.cc).
  void AskNetwork(Client& c);
  void AnswerNetworkQueries(double now);
  wire::ProtocolMessage NetworkLine(NodeId robot, double now) const;
  void ChangeRoute(Client& c, const wire::ProtocolMessage& m);
  void Refuse(Client& c, const std::string& why);
  sim::InboxResult Forward(NodeId to, const Message& message);
  Client* ClientOf(NodeId robot);
  Node& NodeOf(const Client& c) { return driver_.NodeOf(*c.robot, Owner(c)); }
  std::string Owner(const Client& c) const { return "client " + c.peer; }
  void SendSensors(Client& c, double now);
  // `sanet`: the client said SANET: it understands sanet's extension lines (SensorLines::Extension).
  // The SEN lines of a robot's readings, each instance's by its kind (wire/sensor_lines.h).
  std::vector<wire::ProtocolMessage> SenLines(NodeId robot, const sim::SensorReadings& readings, bool sanet,
                                              sim::FreshSamples& fresh) const;
  void Send(Client& c, const wire::ProtocolMessage& m);
  void Error(Client& c, const std::string& why);
  void Drop(Client& c, const std::string& why);

  sim::Driver& driver_;
  ServerSettings settings_;
  std::map<wire::ConnectionId, Client> clients_;
  bool run_over_ = false;  // END was sent: clients that go now finished, they did not drop out
  std::unique_ptr<wire::LineServer> lines_;
  Attendance attendance_;
  const wire::DatagramKey datagram_key_ = wire::DatagramKey::Random();  // new for every run
  std::vector<double> lags_;                                            // s, per physics step
  nlohmann::ordered_json agent_stats_ = nlohmann::ordered_json::object();
  std::unique_ptr<wire::TimeService> time_service_;  // from the first poll, when the clock's origin is known
  struct Peer {
    std::string address;
    std::uint16_t port;
  };
  std::vector<std::optional<Peer>> peers_;  // per node: where its agent listens for other agents
  std::vector<std::string> clock_rows_;     // clock.csv
  std::vector<double> last_clock_row_;      // per node: when its last CLOCK was recorded
  double wall_start_ = -1;
};

}  // namespace sanet::robot_server
