// The node a controller sees when it runs as its own process: sensors and actuators over the
// robot protocol (a TCP client of `sanet serve`), messages to other agents over real UDP
// sockets (one port per node of the scenario), messages to and from the nodes that live in the
// server (motes) over the protocol connection, through the robot's own node in the server's
// ns-3 network; its network view is that node's over the simulated radio, the host kernel's over
// real networks (loop_network_view.h). The controller cannot tell it from the simulated node.
#pragma once

#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/random_stream.h"
#include "sanet/node.h"
#include "sections/loop_section.h"
#include "sim/run_spec.h"
#include "usarsim_agent/clock_sync.h"
#include "usarsim_agent/loop_network_view.h"
#include "usarsim_agent/peer_socket.h"
#include "usarsim_agent/server_link.h"
#include "wire/protocol.h"

namespace sanet::usarsim_agent {

struct AgentSettings {
  PeerSettings peer;            // where the agents listen for each other
  bool shared_clock = false;    // the server runs on this machine: take its clock origin
  std::uint16_t time_port = 0;  // otherwise: the server's time service, for the clock estimate
  double clock_skew = 0;        // tests: added to this computer's clock, which the estimate must find
  bool quiet = false;           // no progress lines on stdout
};

class RemoteNode : public Node {
 public:
  // Takes the server's clock (shared, or estimated), opens the robot's peer socket, claims `robot`
  // over `link` and says where it listens. Throws std::runtime_error.
  RemoteNode(const sim::RunSpec& spec, NodeId robot, AgentSettings settings, std::unique_ptr<ServerLink> link);
  ~RemoteNode() override;

  // Reads what arrived on TCP and UDP; messages go to `deliver` as they arrived (the controller's
  // host applies the scenario's impairments). False once the server is gone.
  bool Poll(const std::function<void(const Message&)>& deliver);
  bool HasPose() const { return readings_.count("ground_truth") > 0; }
  // Inside a control step, Now() is the step's time on the shared clock's grid, not the moment
  // the process happened to wake (as in a simulated run); nullopt outside steps.
  void SetStepTime(std::optional<double> t) { step_time_ = t; }
  // The run's clock as this process reads it, steps or not.
  double ClockNow() const;
  // How well that clock agrees with the server's (all zero but the offset with a shared clock).
  ClockFigures clock_figures() const;
  std::uint64_t messages_sent() const { return messages_sent_; }
  using Datagrams = PeerSocket::Datagrams;
  const Datagrams& datagrams() const { return peer_socket_->datagrams(); }
  // Where this robot listens for the other agents: "address:port", and " on IF" when bound to one.
  const std::string& peer_endpoint() const { return peer_socket_->endpoint(); }
  // A robot whose controller runs as an agent: reached over UDP, not through the server.
  bool IsAgent(NodeId node) const;
  // Reports to the server (a sanet extension line), e.g. the agent's STATS.
  void Report(const wire::ProtocolMessage& m) { Command(m); }
  // The server said END: the run is over, the controller may finish (then FINISHED).
  bool ended() const { return ended_; }

  double Now() const override;
  NodeId Id() const override { return id_; }
  const std::string& Name() const override { return spec_.nodes[id_].name; }
  std::optional<NodeId> Lookup(const std::string& name) const override;
  std::string NameOf(NodeId id) const override { return id < spec_.nodes.size() ? spec_.nodes[id].name : ""; }
  std::size_t NodeCount() const override { return spec_.nodes.size(); }
  // From the server's last sensor lines.
  std::optional<SensorReading> Sensor(const std::string& name) override;
  // From the server's last bearing line (nodes within the sensor's range then).
  std::optional<BearingReading> Bearing(NodeId target) override;
  bool SetRadioSleep(bool asleep) override;
  bool Holonomic() const override { return robots::Holonomic(spec_.nodes[id_].model); }
  void Send(NodeId to, const Bytes& payload) override;
  void Broadcast(const Bytes& payload) override;
  void Flood(const Bytes& payload) override;
  NetworkView& Network() override { return *view_; }
  double Random() override { return random_.Uniform(); }
  void Log(const std::string& text) override;
  void Transition(const std::string& from, const std::string& to, const std::string& why) override;
  void Metric(const std::string& name, double value) override;

 protected:
  bool ApplyDrive(const Twist2D& velocity) override;
  bool ApplyWheelSpeeds(const std::vector<double>& rad_per_s) override;

 private:
  void Command(const wire::ProtocolMessage& m);
  void Take(const wire::ProtocolMessage& m, const std::function<void(const Message&)>& deliver);
  void TakeSensor(const wire::ProtocolMessage& m);
  void SendThroughServer(Delivery delivery, std::optional<NodeId> to, const Bytes& payload);
  void TakePeer(const wire::ProtocolMessage& m);

  const sim::RunSpec& spec_;
  NodeId id_;
  AgentSettings settings_;
  std::unique_ptr<ServerLink> link_;
  std::optional<double> clock_origin_;     // a shared clock: the server's monotonic clock at time 0
  std::unique_ptr<ClockSync> clock_sync_;  // otherwise
  std::unique_ptr<PeerSocket> peer_socket_;
  std::unique_ptr<LoopNetworkView> view_;
  RandomStream random_;
  std::map<std::string, SensorReading> readings_;  // by instance: the server's last line of each
  std::optional<double> step_time_;
  std::uint64_t messages_sent_ = 0;
  bool ended_ = false;
};

}  // namespace sanet::usarsim_agent
