#include "usarsim_agent/peer_socket.h"

#include <fcntl.h>
#include <ifaddrs.h>
#include <net/if.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace sanet::usarsim_agent {
namespace {

constexpr std::size_t kMostHeldEarly = 1024;  // datagrams kept until the agent has the team's key

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
      state.address = wire::AddressText(a->ifa_addr);
  }
  ::freeifaddrs(all);
  return state;
}

}  // namespace

PeerSocket::PeerSocket(const sim::RunSpec& spec, NodeId self, PeerSettings settings, std::function<double()> clock)
    : spec_(spec),
      self_(self),
      settings_(std::move(settings)),
      clock_(std::move(clock)),
      peers_(spec.nodes.size()),
      replays_(spec.nodes.size()) {
  for (const sections::PeerLink& p : settings_.peers)
    for (NodeId node = 0; node < spec_.nodes.size(); ++node)
      if (spec_.nodes[node].name == p.robot && !p.address.empty())
        peers_[node] = wire::Ipv4Endpoint(p.address, PortOf(node));
  Open();
}

PeerSocket::~PeerSocket() {
  if (fd_ >= 0) ::close(fd_);
}

// On the address and interface the robot's peer link gives (the command line over the
// scenario's loop.peers), else on the one-machine rule's address.
void PeerSocket::Open() {
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
  if (address.empty()) address = interface.empty() ? HostOf(self_) : state.address;
  fd_ = ::socket(AF_INET, SOCK_DGRAM, 0);
  if (!interface.empty() &&
      ::setsockopt(fd_, SOL_SOCKET, SO_BINDTODEVICE, interface.c_str(), static_cast<socklen_t>(interface.size())) != 0)
    throw std::runtime_error(
        "cannot bind the peer socket to interface " + interface + ": " + std::strerror(errno) +
        (errno == EPERM ? " (before Linux 5.7, binding to an interface needs root or CAP_NET_RAW)" : ""));
  const sockaddr_in mine = wire::Ipv4Endpoint(address, PortOf(self_));
  if (::bind(fd_, reinterpret_cast<const sockaddr*>(&mine), sizeof mine) != 0)
    throw std::runtime_error("cannot bind UDP " + address + ":" + std::to_string(PortOf(self_)) + ": " +
                             std::strerror(errno) +
                             (errno == EADDRINUSE ? " (another agent or team uses these ports: give this team "
                                                    "others with --udp-base or the scenario's loop.udp_port)"
                                                  : ""));
  ::fcntl(fd_, F_SETFL, O_NONBLOCK);
  peers_[self_] = mine;
  address_ = address;
  endpoint_ = address + ":" + std::to_string(PortOf(self_)) + (interface.empty() ? "" : " on " + interface);
  if (!state.up)
    std::fprintf(stderr,
                 "sanet agent %s: warning: interface %s is down: datagrams to and from the other robots "
                 "will not get through until it is up\n",
                 Name().c_str(), interface.c_str());
}

void PeerSocket::SetPeer(NodeId node, const std::string& address, std::uint16_t port) {
  if (node < peers_.size() && node != self_) peers_[node] = wire::Ipv4Endpoint(address, port);
}

// A datagram from a peer is checked and stamped with this agent's clock when it is read; one
// that comes before the agent has the team's key (a peer that started sooner) waits.
void PeerSocket::Read(const std::function<void(const Message&)>& deliver) {
  const bool ready = key_.has_value();
  if (ready) {
    for (const Bytes& d : early_) Take(d, deliver);
    early_.clear();
  }
  std::uint8_t buffer[65536];
  while (true) {
    const ssize_t n = ::recv(fd_, buffer, sizeof buffer, 0);
    if (n <= 0) break;
    Bytes datagram(buffer, buffer + n);
    if (ready)
      Take(datagram, deliver);
    else if (early_.size() < kMostHeldEarly)
      early_.push_back(std::move(datagram));
    else
      Reject("more than " + std::to_string(kMostHeldEarly) + " datagrams before the agent had the team's key");
  }
}

void PeerSocket::Take(const Bytes& datagram, const std::function<void(const Message&)>& deliver) {
  std::string why;
  const auto d = wire::OpenDatagram(datagram.data(), datagram.size(), *key_, &why);
  if (!d) return Reject(why);
  if (d->from >= spec_.nodes.size() || d->from == self_) return Reject("from no other node of the scenario");
  const bool unicast = d->kind == wire::AgentDatagram::kUnicast;
  if (unicast ? d->to != self_ : d->to != wire::AgentDatagram::kToAll) return Reject("not for this robot");
  if (!replays_[d->from].Take(d->sequence))
    return Reject("sequence number " + std::to_string(d->sequence) + " of " + spec_.nodes[d->from].name +
                  " seen before");
  Message m;
  m.from = d->from;
  m.to = unicast ? self_ : sanet::kBroadcast;
  m.delivery = unicast ? Delivery::kUnicast : Delivery::kBroadcast;
  m.time_sent = d->time_sent;
  m.time_received = clock_();
  m.hops = 1;
  m.payload = d->payload;
  ++datagrams_.received;
  deliver(m);
}

// The first rejection is said on stderr; all are counted.
void PeerSocket::Reject(const std::string& why) {
  if (datagrams_.rejected++ == 0)
    std::fprintf(stderr, "sanet agent %s: rejected a datagram: %s (further ones are only counted)\n", Name().c_str(),
                 why.c_str());
}

void PeerSocket::Send(NodeId to, wire::AgentDatagram::Kind kind, const Bytes& payload) {
  if (!key_) {  // no key yet: the peers would reject what this agent sends
    ++datagrams_.send_errors;
    return;
  }
  wire::AgentDatagram d;
  d.from = self_;
  d.to = kind == wire::AgentDatagram::kUnicast ? to : wire::AgentDatagram::kToAll;
  d.kind = kind;
  d.sequence = next_sequence_++;
  d.time_sent = clock_();
  d.payload = payload;
  const Bytes datagram = wire::SealDatagram(d, *key_);
  const sockaddr_in peer = peers_[to] ? *peers_[to] : wire::Ipv4Endpoint(HostOf(to), PortOf(to));
  const ssize_t n =
      ::sendto(fd_, datagram.data(), datagram.size(), 0, reinterpret_cast<const sockaddr*>(&peer), sizeof peer);
  ++(n < 0 ? datagrams_.send_errors : datagrams_.sent);
}

std::vector<std::optional<Ipv4>> PeerSocket::Addresses() const {
  std::vector<std::optional<Ipv4>> addresses(spec_.nodes.size());
  for (NodeId id = 0; id < spec_.nodes.size(); ++id)
    if (peers_[id])
      addresses[id] = peers_[id]->sin_addr.s_addr;
    else if (!settings_.udp_subnet.empty() && sim::RunsAsAgent(spec_.nodes[id]))
      addresses[id] = wire::Ipv4Endpoint(HostOf(id), 0).sin_addr.s_addr;
  return addresses;
}

std::string PeerSocket::HostOf(NodeId node) const {
  return settings_.udp_subnet.empty() ? settings_.udp_host : settings_.udp_subnet + "." + std::to_string(node + 1);
}

std::uint16_t PeerSocket::PortOf(NodeId node) const {
  return static_cast<std::uint16_t>(settings_.udp_base_port + (settings_.udp_subnet.empty() ? node : 0));
}

}  // namespace sanet::usarsim_agent
