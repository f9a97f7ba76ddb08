// A TCP server of text lines that no client can stall or exhaust, for every line protocol sanet
// serves (the USARSim robot server, the WSS endpoint). Sockets are non-blocking; clients take
// turns of bounded lines and bytes within a time budget per poll; input and output are bounded (a
// line too long, or output a client leaves unread past the backlog, ends it); a client whose TCP
// window shows that it stopped reading is dropped after `stall_timeout`; and a connection the
// server ends lingers until the client hangs up, so that a last ERR is not lost to a reset.
//
// Slots are for clients that speak. Connections are capped (`max_clients`, with a listen backlog
// to match), and a connection that has sent no complete line within `handshake_timeout` (3 s by
// default) of being accepted is closed, whatever the cap. The owner says when a connection has
// completed its protocol's registration (Register: an INIT that took a robot). When the cap is
// full, a newcomer takes the slot of the unregistered connection silent the longest among those
// past their handshake time, which is told why and dropped (its `gone` runs); the newcomer is
// refused (told why and closed) only when every slot holds a registered connection or one still
// inside its handshake time. Registered connections are never evicted, and one that has spoken is
// never closed by the handshake time, however slowly it goes on (an agent fetching the scenario
// before its INIT). What the lines mean is the owner's business (LineServer::Events).
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "wire/protocol.h"

namespace sanet::wire {

struct LineServerSettings {
  std::string bind = "127.0.0.1";
  std::uint16_t port = 0;              // 0: any free port
  std::size_t max_clients = 64;        // connections at once (at least 1)
  std::string cap_option;              // the option that sets the cap, named in the refusal
  std::string registration = "INIT";   // what registers a connection, named to one evicted
  double handshake_timeout = 3.0;      // s a new connection has to send its first line (or it is closed)
  std::size_t max_line = 4096;         // bytes; a longer line ends the connection
  std::size_t max_backlog = 1 << 20;   // bytes waiting for a client that does not read: then it is dropped
  double stall_timeout = 2.0;          // s a client may leave its lines unread before it is dropped
  std::size_t lines_per_turn = 32;     // lines taken from one client before the next has its turn
  std::size_t bytes_per_turn = 16384;  // bytes read from one client per turn
  double poll_budget = 0.0015;         // s of line handling per poll; the rest waits for the next poll
};

using ConnectionId = std::uint64_t;

class LineServer {
 public:
  struct Events {
    std::function<void(ConnectionId)> connected;                          // greet it, if the protocol does
    std::function<void(ConnectionId, const std::string& line)> line;      // a line that is not blank
    std::function<void(ConnectionId, const std::string& why)> gone;       // dropped or hung up: forget it
    std::function<std::string(std::size_t max_line)> line_too_long;       // the last line it is sent
    std::function<std::string(const std::string& refusal)> refusal_line;  // formats the cap's refusal (and eviction)
    std::function<std::string(const std::string& why)> silence_line;      // formats the handshake time's close
  };

  // Listens; throws std::runtime_error naming the address and the reason.
  LineServer(LineServerSettings settings, Events events);
  ~LineServer();
  LineServer(const LineServer&) = delete;
  LineServer& operator=(const LineServer&) = delete;
  std::uint16_t port() const { return port_; }

  // A poll in two halves, so that the owner can write between them (sensor lines): accepts
  // (bounded) and takes lines in turns; then writes what waits, drops clients that stopped
  // reading, forgets the closed and closes lingering connections.
  void Read();
  void Write();

  // Queues a line (with its line end) for a connection; a connection that is gone ignores it.
  void Send(ConnectionId id, const std::string& line);
  // Ends a connection: what is queued goes first (as far as its socket takes it), then the
  // server stops writing and closes once the client hangs up or a second has passed.
  void Drop(ConnectionId id, const std::string& why);
  // "host:port" of the client, and its host alone.
  const std::string& Peer(ConnectionId id) const;
  const std::string& PeerHost(ConnectionId id) const;
  // A client that must speak (an agent reads and writes in one loop): silence for stall_timeout
  // ends it, whatever TCP shows.
  void ExpectChatter(ConnectionId id);
  // The connection has completed its protocol's registration (e.g. an INIT that took a robot): it
  // keeps its slot when the cap is full. A connection that is gone ignores it.
  void Register(ConnectionId id);
  std::size_t size() const { return open_; }  // connections holding a slot
  const LineServerSettings& settings() const { return settings_; }

 private:
  struct Connection;
  struct Closing {
    int fd;
    double close_by;  // wall clock (s)
  };
  void Accept();
  void Admit(int fd);
  void Refuse(int fd);
  std::vector<ConnectionId> Evictable(double now) const;
  void MakeRoom(std::vector<ConnectionId>& evictable);
  void Linger(int fd);
  void CloseLingering();
  bool TakeLines(ConnectionId id, Connection& c);  // one turn; true if it has more
  void Flush(ConnectionId id, Connection& c);
  void CheckReading(ConnectionId id, Connection& c, double now);
  void CheckHandshake(ConnectionId id, Connection& c, double now);
  std::string CapText() const;
  std::string Notice(const std::function<std::string(const std::string&)>& format, const std::string& text) const;

  LineServerSettings settings_;
  Events events_;
  int listener_ = -1;
  std::uint16_t port_ = 0;
  std::map<ConnectionId, Connection> connections_;  // with the dropped ones until the next Write
  std::size_t open_ = 0;                            // connections not dropped: the slots taken
  ConnectionId next_id_ = 1;
  ConnectionId next_turn_ = 0;  // the connection whose turn comes first in the next poll
  std::vector<Closing> closing_;
  std::vector<char> read_buffer_;  // one turn's bytes
};

// Each connection (and each refused one while it lingers) holds a file descriptor: raises the
// soft limit to what `connections` at once need; throws std::runtime_error when the hard limit
// is lower.
void RaiseDescriptorLimit(std::size_t connections);

}  // namespace sanet::wire
