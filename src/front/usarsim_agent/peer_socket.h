// A robot's agent's link to the other robots' agents: one UDP socket, on the address (and
// interface) its peer link gives, over which the controllers' messages go as authenticated
// datagrams (wire/agent_datagram.h: HMAC-SHA256 with the team's key, a replay window per sender).
// The same whatever drives the robot: a server (remote_node.h) or a ROS 2 robot's topics.
#pragma once

#include <netinet/in.h>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "sanet/message.h"
#include "sections/loop_section.h"
#include "sim/run_spec.h"
#include "usarsim_agent/kernel_tables.h"
#include "wire/agent_datagram.h"
#include "wire/sockets.h"

namespace sanet::usarsim_agent {

// Where the agents listen for each other.
struct PeerSettings {
  std::string udp_host = "127.0.0.1";   // where every node's UDP socket lives (one machine)
  std::uint16_t udp_base_port = 47000;  // node i listens on base + i
  std::string udp_subnet;               // instead: node i listens on <subnet>.(i+1), port udp_base_port (namespaces)
  // This robot's link to the other agents, over the scenario's loop.peers: the address its peer
  // socket takes, and the interface it is bound to (robot-to-robot datagrams leave through it only).
  std::string peer_address, peer_interface;
  std::vector<sections::PeerLink> peers;  // the scenario's loop.peers: where each robot's agent listens
};

class PeerSocket {
 public:
  // Opens and binds the socket of `self`; `clock` stamps what is sent and received. Throws
  // std::runtime_error saying what could not be done (an interface without an address, a bind).
  PeerSocket(const sim::RunSpec& spec, NodeId self, PeerSettings settings, std::function<double()> clock);
  ~PeerSocket();
  PeerSocket(const PeerSocket&) = delete;
  PeerSocket& operator=(const PeerSocket&) = delete;

  // The team's key; datagrams that came before it wait (up to a bound), sending waits for it.
  void SetKey(const wire::DatagramKey& key) { key_ = key; }
  bool HasKey() const { return key_.has_value(); }
  // Where `node`'s agent listens, learnt at run time. Throws std::runtime_error for no address.
  void SetPeer(NodeId node, const std::string& address, std::uint16_t port);
  // Delivers the messages of the datagrams that arrived, checked, in the order they came.
  void Read(const std::function<void(const Message&)>& deliver);
  // One datagram to `to`'s agent: a unicast message, or its copy of a broadcast.
  void Send(NodeId to, wire::AgentDatagram::Kind kind, const Bytes& payload);

  // The robot's own packets between agents (UDP datagrams): sent, refused by the sender's
  // stack (sendto failed) or not sent for want of the team's key, received whole from a known
  // node with a valid MAC, and rejected (malformed, forged, replayed, or not for this robot).
  struct Datagrams {
    std::uint64_t sent = 0, send_errors = 0, received = 0, rejected = 0;
  };
  const Datagrams& datagrams() const { return datagrams_; }
  const std::string& address() const { return address_; }
  std::uint16_t port() const { return PortOf(self_); }
  // "address:port", and " on IF" when bound to an interface.
  const std::string& endpoint() const { return endpoint_; }
  // Where each node's agent listens, as far as this one knows (for the kernel's network view).
  std::vector<std::optional<Ipv4>> Addresses() const;

 private:
  void Open();
  void Take(const Bytes& datagram, const std::function<void(const Message&)>& deliver);
  void Reject(const std::string& why);
  std::string HostOf(NodeId node) const;
  std::uint16_t PortOf(NodeId node) const;
  const std::string& Name() const { return spec_.nodes[self_].name; }

  const sim::RunSpec& spec_;
  NodeId self_;
  PeerSettings settings_;
  std::function<double()> clock_;
  int fd_ = -1;
  std::vector<std::optional<sockaddr_in>> peers_;  // where each agent listens, when known
  std::vector<Bytes> early_;                       // datagrams that came before this agent had the key
  std::string address_, endpoint_;
  std::optional<wire::DatagramKey> key_;
  std::uint64_t next_sequence_ = 1;          // of this agent's datagrams
  std::vector<wire::ReplayWindow> replays_;  // per sender
  Datagrams datagrams_;
};

}  // namespace sanet::usarsim_agent
