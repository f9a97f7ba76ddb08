// What TCP tells a sender about a peer that stops reading: the receive window the peer last
// advertised shrinks as unread bytes fill its buffer. The server's only sign, short of the
// client's own words, that a client has stopped taking its lines.
#pragma once

#include <cstdint>
#include <optional>

namespace sanet::wire {

// The receive window (bytes) the peer of a connected TCP socket last advertised; nothing when
// the kernel does not say (Linux before 5.4).
std::optional<std::uint32_t> PeerReceiveWindow(int fd);

}  // namespace sanet::wire
