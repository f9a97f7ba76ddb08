#include "usarsim_agent/kernel_tables.h"

#include <linux/neighbour.h>
#include <linux/netlink.h>
#include <linux/rtnetlink.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <functional>
#include <map>
#include <stdexcept>

namespace sanet::usarsim_agent {
namespace {

// One rtnetlink conversation: a request, then its answers until the kernel says it is done.
class Netlink {
 public:
  Netlink() : fd_(::socket(AF_NETLINK, SOCK_RAW | SOCK_CLOEXEC, NETLINK_ROUTE)) {
    if (fd_ < 0) throw std::runtime_error(std::string("cannot open rtnetlink: ") + std::strerror(errno));
    timeval wait{1, 0};  // the kernel answers at once; never hang the controller's step on it
    ::setsockopt(fd_, SOL_SOCKET, SO_RCVTIMEO, &wait, sizeof wait);
  }
  ~Netlink() { ::close(fd_); }
  Netlink(const Netlink&) = delete;
  Netlink& operator=(const Netlink&) = delete;

  // Sends `request` and gives every answer to `take`; false if the kernel answered with an error.
  bool Exchange(const nlmsghdr& request, const std::function<void(const nlmsghdr&)>& take) {
    if (::send(fd_, &request, request.nlmsg_len, 0) < 0)
      throw std::runtime_error(std::string("cannot ask rtnetlink: ") + std::strerror(errno));
    alignas(nlmsghdr) char buffer[32768];
    while (true) {
      const ssize_t n = ::recv(fd_, buffer, sizeof buffer, 0);
      if (n <= 0) return false;  // timed out or closed: nothing more to read
      int left = static_cast<int>(n);
      for (auto* h = reinterpret_cast<const nlmsghdr*>(buffer); NLMSG_OK(h, left); h = NLMSG_NEXT(h, left)) {
        if (h->nlmsg_type == NLMSG_DONE) return true;
        if (h->nlmsg_type == NLMSG_ERROR) return reinterpret_cast<const nlmsgerr*>(NLMSG_DATA(h))->error == 0;
        take(*h);
        if (!(h->nlmsg_flags & NLM_F_MULTI)) return true;
      }
    }
  }

 private:
  int fd_;
};

template <typename Header>
std::map<int, const rtattr*> Attributes(const nlmsghdr& h, int first_offset) {
  std::map<int, const rtattr*> found;
  int left = static_cast<int>(h.nlmsg_len) - NLMSG_LENGTH(sizeof(Header));
  const auto* a = reinterpret_cast<const rtattr*>(reinterpret_cast<const char*>(NLMSG_DATA(&h)) + first_offset);
  for (; RTA_OK(a, left); a = RTA_NEXT(a, left)) found[a->rta_type] = a;
  return found;
}

Ipv4 AddressIn(const rtattr* a) {
  Ipv4 address = 0;
  std::memcpy(&address, RTA_DATA(a), std::min<std::size_t>(sizeof address, RTA_PAYLOAD(a)));
  return address;
}

// How many nodes hold each address: one makes it that node's, more make it none's.
std::map<Ipv4, int> Holders(const std::vector<std::optional<Ipv4>>& addresses) {
  std::map<Ipv4, int> holders;
  for (const auto& a : addresses)
    if (a) ++holders[*a];
  return holders;
}

}  // namespace

std::optional<KernelRoute> KernelRouteTo(Ipv4 destination) {
  struct {
    nlmsghdr header;
    rtmsg route;
    char attributes[64];
  } request{};
  request.header.nlmsg_len = NLMSG_LENGTH(sizeof(rtmsg));
  request.header.nlmsg_type = RTM_GETROUTE;
  request.header.nlmsg_flags = NLM_F_REQUEST;
  request.route.rtm_family = AF_INET;
  request.route.rtm_dst_len = 32;
  auto* dst = reinterpret_cast<rtattr*>(reinterpret_cast<char*>(&request) + NLMSG_ALIGN(request.header.nlmsg_len));
  dst->rta_type = RTA_DST;
  dst->rta_len = RTA_LENGTH(sizeof destination);
  std::memcpy(RTA_DATA(dst), &destination, sizeof destination);
  request.header.nlmsg_len = NLMSG_ALIGN(request.header.nlmsg_len) + RTA_ALIGN(dst->rta_len);
  std::optional<KernelRoute> route;
  Netlink link;
  const bool answered = link.Exchange(request.header, [&](const nlmsghdr& h) {
    if (h.nlmsg_type != RTM_NEWROUTE) return;
    const auto found = Attributes<rtmsg>(h, NLMSG_ALIGN(sizeof(rtmsg)));
    route = KernelRoute{destination, std::nullopt};
    if (const auto g = found.find(RTA_GATEWAY); g != found.end()) route->gateway = AddressIn(g->second);
  });
  return answered ? route : std::nullopt;
}

std::vector<KernelNeighbour> KernelNeighbours() {
  struct {
    nlmsghdr header;
    ndmsg neighbour;
  } request{};
  request.header.nlmsg_len = NLMSG_LENGTH(sizeof(ndmsg));
  request.header.nlmsg_type = RTM_GETNEIGH;
  request.header.nlmsg_flags = NLM_F_REQUEST | NLM_F_DUMP;
  request.neighbour.ndm_family = AF_INET;
  constexpr int kKnown = NUD_REACHABLE | NUD_STALE | NUD_DELAY | NUD_PROBE | NUD_PERMANENT;
  std::vector<KernelNeighbour> neighbours;
  Netlink link;
  link.Exchange(request.header, [&](const nlmsghdr& h) {
    if (h.nlmsg_type != RTM_NEWNEIGH) return;
    const auto* n = reinterpret_cast<const ndmsg*>(NLMSG_DATA(&h));
    if (n->ndm_family != AF_INET || !(n->ndm_state & kKnown)) return;
    const auto found = Attributes<ndmsg>(h, NLMSG_ALIGN(sizeof(ndmsg)));
    if (const auto d = found.find(NDA_DST); d != found.end()) neighbours.push_back({AddressIn(d->second)});
  });
  return neighbours;
}

KernelTables MapToNodes(NodeId self, const std::vector<std::optional<Ipv4>>& addresses,
                        const std::vector<KernelRoute>& routes, const std::vector<KernelNeighbour>& neighbours) {
  std::map<Ipv4, int> holders = Holders(addresses);
  const auto node_at = [&](Ipv4 address) -> std::optional<NodeId> {
    if (holders[address] != 1) return std::nullopt;  // no node's, or several nodes'
    for (NodeId id = 0; id < addresses.size(); ++id)
      if (addresses[id] == address) return id;
    return std::nullopt;
  };
  KernelTables tables;
  for (const KernelRoute& r : routes) {
    const auto destination = node_at(r.destination);
    const auto next = r.gateway ? node_at(*r.gateway) : destination;
    if (!destination || !next || *destination == self || *next == self) continue;
    tables.routes.push_back({*destination, *next, r.gateway ? 2 : 1, true, 0});
  }
  for (const KernelNeighbour& n : neighbours)
    if (const auto node = node_at(n.address);
        node && *node != self &&
        std::find(tables.neighbours.begin(), tables.neighbours.end(), *node) == tables.neighbours.end())
      tables.neighbours.push_back(*node);
  std::sort(tables.neighbours.begin(), tables.neighbours.end());
  return tables;
}

KernelTables ReadKernelTables(NodeId self, const std::vector<std::optional<Ipv4>>& addresses) {
  std::map<Ipv4, int> holders = Holders(addresses);
  std::vector<KernelRoute> routes;
  for (NodeId id = 0; id < addresses.size(); ++id)
    if (id != self && addresses[id] && holders[*addresses[id]] == 1)
      if (const auto r = KernelRouteTo(*addresses[id])) routes.push_back(*r);
  return MapToNodes(self, addresses, routes, KernelNeighbours());
}

}  // namespace sanet::usarsim_agent
