// Small helpers for the servers' non-blocking TCP sockets.
#pragma once

#include <netinet/in.h>

#include <cstdint>
#include <string>

namespace sanet::wire {

// A non-blocking TCP socket listening on `bind`:`port` (0: any free port); sets `bound` to the
// port it got. Throws std::runtime_error naming the address and the reason.
int ListenTcp(const std::string& bind, std::uint16_t port, int backlog, std::uint16_t* bound);

// An IPv4 address and port; throws std::runtime_error when `host` is not a dotted IPv4 address.
sockaddr_in Ipv4Endpoint(const std::string& host, std::uint16_t port);

// The next connection waiting on `listener`, non-blocking and without Nagle's delay (lines go
// out as they are written); -1 when none waits.
int AcceptClient(int listener);

// The dotted text of an IPv4 address.
std::string AddressText(const sockaddr* address);

// "host:port" of a connected socket's peer; its host alone in `host` if given.
std::string PeerOf(int fd, std::string* host = nullptr);

}  // namespace sanet::wire
