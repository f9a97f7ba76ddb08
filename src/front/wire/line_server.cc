#include "wire/line_server.h"

#include <sys/resource.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <utility>

#include "wire/sockets.h"
#include "wire/tcp_window.h"
#include "wire/time_service.h"

namespace sanet::wire {
namespace {

// A client whose advertised window is this close to the widest it has advertised has read what
// reached it, give or take the last lines (a laser scan line is about 1.5 KB).
constexpr std::uint32_t kWindowSlack = 4 * 1024;
constexpr int kSendBuffer = 16 * 1024;  // bytes the server's kernel holds for one client
constexpr double kClosingLinger = 1.0;  // s a connection the server ends has to read its last line and hang up

std::string ShortSeconds(double s) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", s);
  return text;
}

}  // namespace

struct LineServer::Connection {
  Connection(int socket, std::size_t max_line, double now)
      : fd(socket),
        peer(PeerOf(socket, &host)),
        reader(max_line),
        last_caught_up(now),
        last_heard(now),
        connected_at(now) {}
  int fd;
  std::string host;
  std::string peer;
  LineReader reader;
  std::string out;
  double last_caught_up;            // wall clock (s) when it last had nothing of ours left unread
  double last_heard;                // wall clock (s) of its last line (of its accepting until it speaks)
  double connected_at;              // wall clock (s) when it was accepted
  bool spoke = false;               // it has sent a line: the handshake time no longer closes it
  bool registered = false;          // its owner says it has registered (Register): never evicted
  std::uint32_t widest_window = 0;  // the largest receive window it has advertised (bytes)
  std::uint32_t last_window = 0;    // the window at the last poll
  bool chatter = false;             // silence ends it (ExpectChatter)
};

void RaiseDescriptorLimit(std::size_t connections) {
  const rlim_t needed = 2 * static_cast<rlim_t>(connections) + 64;  // clients, refused ones, results, ns-3
  rlimit limit{};
  ::getrlimit(RLIMIT_NOFILE, &limit);
  if (limit.rlim_cur >= needed) return;
  if (limit.rlim_max != RLIM_INFINITY && limit.rlim_max < needed)
    throw std::runtime_error("a cap of " + std::to_string(connections) + " connections needs " +
                             std::to_string(needed) + " file descriptors; this process may open at most " +
                             std::to_string(limit.rlim_max) + " (ulimit -Hn)");
  limit.rlim_cur = needed;
  ::setrlimit(RLIMIT_NOFILE, &limit);
}

LineServer::LineServer(LineServerSettings settings, Events events)
    : settings_(std::move(settings)), events_(std::move(events)) {
  if (settings_.max_clients == 0) throw std::runtime_error("the connection cap must be at least 1");
  listener_ = ListenTcp(settings_.bind, settings_.port, static_cast<int>(settings_.max_clients), &port_);
}

LineServer::~LineServer() {
  for (auto& [id, c] : connections_)
    if (c.fd >= 0) ::close(c.fd);
  for (const Closing& r : closing_) ::close(r.fd);
  if (listener_ >= 0) ::close(listener_);
}

void LineServer::Read() {
  Accept();
  const double deadline = MonotonicSeconds() + settings_.poll_budget;
  std::size_t idle = 0;  // connections in a row that had nothing more
  for (std::size_t k = 0; !connections_.empty() && idle < connections_.size(); ++k) {
    if (k > 0 && MonotonicSeconds() > deadline) break;
    auto it = connections_.lower_bound(next_turn_);
    if (it == connections_.end()) it = connections_.begin();
    next_turn_ = it->first + 1;
    const bool more = it->second.fd >= 0 && TakeLines(it->first, it->second);
    idle = more ? 0 : idle + 1;
  }
}

void LineServer::Write() {
  const double now = MonotonicSeconds();
  for (auto& [id, c] : connections_) {
    if (c.fd >= 0) Flush(id, c);
    if (c.fd >= 0) CheckReading(id, c, now);
    if (c.fd >= 0) CheckHandshake(id, c, now);
  }
  for (auto it = connections_.begin(); it != connections_.end();)
    it = it->second.fd < 0 ? connections_.erase(it) : std::next(it);
  CloseLingering();
}

void LineServer::Send(ConnectionId id, const std::string& line) {
  const auto it = connections_.find(id);
  if (it == connections_.end() || it->second.fd < 0) return;
  it->second.out += line;
  if (it->second.out.size() > settings_.max_backlog)
    Drop(id, "not reading (more than " + std::to_string(settings_.max_backlog) + " bytes waiting)");
}

void LineServer::Drop(ConnectionId id, const std::string& why) {
  const auto it = connections_.find(id);
  if (it == connections_.end() || it->second.fd < 0) return;
  Connection& c = it->second;
  if (!c.out.empty()) ::send(c.fd, c.out.data(), c.out.size(), MSG_NOSIGNAL | MSG_DONTWAIT);
  Linger(c.fd);
  c.fd = -1;
  --open_;
  if (events_.gone) events_.gone(id, why);
}

const std::string& LineServer::Peer(ConnectionId id) const { return connections_.at(id).peer; }
const std::string& LineServer::PeerHost(ConnectionId id) const { return connections_.at(id).host; }
void LineServer::ExpectChatter(ConnectionId id) { connections_.at(id).chatter = true; }

void LineServer::Register(ConnectionId id) {
  const auto it = connections_.find(id);
  if (it != connections_.end()) it->second.registered = true;
}

void LineServer::Accept() {
  std::vector<ConnectionId> evictable;  // listed once per poll, when the cap is first reached
  bool listed = false;
  // Bounded, so that a storm of connections cannot hold the poll; the rest wait in the backlog.
  for (std::size_t accepted = 0; accepted < settings_.max_clients; ++accepted) {
    const int fd = AcceptClient(listener_);
    if (fd < 0) return;
    if (open_ >= settings_.max_clients) {
      if (!listed) evictable = Evictable(MonotonicSeconds()), listed = true;
      MakeRoom(evictable);
    }
    if (open_ >= settings_.max_clients)
      Refuse(fd);
    else
      Admit(fd);
  }
}

void LineServer::Admit(int fd) {
  // A small kernel buffer: what a client leaves unread piles up where the server can see it.
  ::setsockopt(fd, SOL_SOCKET, SO_SNDBUF, &kSendBuffer, sizeof kSendBuffer);
  const ConnectionId id = next_id_++;
  connections_.emplace(id, Connection(fd, settings_.max_line, MonotonicSeconds()));
  ++open_;
  if (events_.connected) events_.connected(id);
}

// The connections a newcomer may take the slot of: not registered and past their handshake time,
// the longest silent last. Newcomers admitted in the same poll are inside theirs, so the list
// holds for the whole poll.
std::vector<ConnectionId> LineServer::Evictable(double now) const {
  std::vector<std::pair<double, ConnectionId>> silent_since;
  for (const auto& [id, c] : connections_)
    if (c.fd >= 0 && !c.registered && now - c.connected_at > settings_.handshake_timeout)
      silent_since.emplace_back(c.last_heard, id);
  std::sort(silent_since.begin(), silent_since.end(), std::greater<>());
  std::vector<ConnectionId> ids;
  for (const auto& [heard, id] : silent_since) ids.push_back(id);
  return ids;
}

// Drops the longest silent of `evictable` (telling it why) until a slot is free or none is left.
void LineServer::MakeRoom(std::vector<ConnectionId>& evictable) {
  const std::string timeout = ShortSeconds(settings_.handshake_timeout);
  const std::string why = "closed to make room: no " + settings_.registration + " within " + timeout +
                          " s of connecting and the server is full";
  while (open_ >= settings_.max_clients && !evictable.empty()) {
    const ConnectionId id = evictable.back();
    evictable.pop_back();
    Send(id, Notice(events_.refusal_line, why + CapText()));
    Drop(id, why);
  }
}

void LineServer::Refuse(int fd) {
  const std::string n = std::to_string(settings_.max_clients);
  const std::string line =
      Notice(events_.refusal_line, "connection refused: the server already has " + n + " connections" + CapText());
  ::send(fd, line.data(), line.size(), MSG_NOSIGNAL | MSG_DONTWAIT);
  Linger(fd);
}

// " (its cap, --max-clients 64)": the option that sets it, for the client's operator.
std::string LineServer::CapText() const {
  const std::string n = std::to_string(settings_.max_clients);
  return settings_.cap_option.empty() ? " (its cap)" : " (its cap, " + settings_.cap_option + " " + n + ")";
}

// The owner's line for `text`, or the text alone.
std::string LineServer::Notice(const std::function<std::string(const std::string&)>& format,
                               const std::string& text) const {
  return format ? format(text) : text + "\r\n";
}

// The server stops writing and waits (briefly) for the client to hang up before it closes: closing
// on bytes the client has sent and the server has not read would reset the connection, and the
// client could lose the line that says why.
void LineServer::Linger(int fd) {
  ::shutdown(fd, SHUT_WR);
  if (closing_.size() >= settings_.max_clients) {
    ::close(fd);
    return;
  }
  closing_.push_back({fd, MonotonicSeconds() + kClosingLinger});
}

// What the client still sends is read and thrown away, one turn's bytes per poll at most: one that
// keeps sending is closed at its deadline all the same.
void LineServer::CloseLingering() {
  const double now = MonotonicSeconds();
  read_buffer_.resize(settings_.bytes_per_turn);
  for (Closing& r : closing_) {
    const ssize_t n = ::recv(r.fd, read_buffer_.data(), read_buffer_.size(), 0);
    const bool hung_up = n == 0 || (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK);
    if (hung_up || now > r.close_by) ::close(r.fd), r.fd = -1;
  }
  closing_.erase(std::remove_if(closing_.begin(), closing_.end(), [](const Closing& r) { return r.fd < 0; }),
                 closing_.end());
}

// One turn: at most `bytes_per_turn` bytes read and `lines_per_turn` lines handled. A client that
// floods waits for its own next turn, and its bytes wait in its socket (TCP slows it down), so
// every other client's lines are taken within a few polls however many flood.
bool LineServer::TakeLines(ConnectionId id, Connection& c) {
  std::string gone;  // why the connection ended, once the lines it brought are handled
  bool full_read = false;
  if (c.reader.Pending() <= settings_.max_line) {  // never more than a line and a turn's bytes held
    read_buffer_.resize(settings_.bytes_per_turn);
    const ssize_t n = ::recv(c.fd, read_buffer_.data(), read_buffer_.size(), 0);
    if (n == 0) gone = "disconnected";
    if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK) gone = std::strerror(errno);
    if (n > 0) c.reader.Append(std::string_view(read_buffer_.data(), static_cast<std::size_t>(n)));
    full_read = n == static_cast<ssize_t>(read_buffer_.size());
  }
  bool too_long = false;
  std::size_t taken = 0;
  for (; taken < settings_.lines_per_turn; ++taken) {
    const auto line = c.reader.Next(&too_long);
    if (!line) break;
    if (line->find_first_not_of(" \t") == std::string::npos) continue;
    events_.line(id, *line);
    if (c.fd < 0) return false;
  }
  if (taken > 0) {  // once a turn, not for every line
    c.last_heard = MonotonicSeconds();
    c.spoke = true;
  }
  if (too_long) {
    if (events_.line_too_long) Send(id, events_.line_too_long(settings_.max_line));
    Drop(id, "line too long");
    return false;
  }
  if (!gone.empty()) {
    if (c.reader.Pending() > 0 && taken == settings_.lines_per_turn) return true;  // its last lines first
    Drop(id, gone);
    return false;
  }
  return full_read || taken == settings_.lines_per_turn;
}

void LineServer::Flush(ConnectionId id, Connection& c) {
  while (c.fd >= 0 && !c.out.empty()) {
    const ssize_t n = ::send(c.fd, c.out.data(), c.out.size(), MSG_NOSIGNAL);
    if (n < 0) {
      if (errno != EAGAIN && errno != EWOULDBLOCK) Drop(id, std::strerror(errno));
      break;
    }
    c.out.erase(0, static_cast<std::size_t>(n));
  }
}

// A client keeps up when nothing waits for it here and its receive window is (nearly) as wide as
// it has ever been or has just widened: it has read what reached it, or some of it. One that has
// not kept up for `stall_timeout` is dropped. TCP gives no earlier sign: until its window
// narrows, a client that stopped reading looks like one that reads (the window narrows as soon as
// long lines such as laser scans arrive unread, only after tens of kilobytes of short ones).
void LineServer::CheckReading(ConnectionId id, Connection& c, double now) {
  const auto window = PeerReceiveWindow(c.fd);
  bool reads = true;  // without the window's word, a client that takes every byte reads
  if (window) {
    reads = *window + kWindowSlack >= c.widest_window || *window > c.last_window;
    c.widest_window = std::max(c.widest_window, *window);
    c.last_window = *window;
  }
  if (c.out.empty() && reads) c.last_caught_up = now;
  if (now - c.last_caught_up > settings_.stall_timeout)
    Drop(id, "not reading for " + ShortSeconds(settings_.stall_timeout) + " s");
  else if (c.chatter && now - c.last_heard > settings_.stall_timeout)
    Drop(id, "an agent silent for " + ShortSeconds(settings_.stall_timeout) + " s");
}

// A connection that has said nothing within the handshake time holds a slot for nothing (a
// client of either protocol speaks first after the greeting): it is closed, whatever the cap, as
// nginx's client_header_timeout and sshd's LoginGraceTime close theirs.
void LineServer::CheckHandshake(ConnectionId id, Connection& c, double now) {
  if (c.spoke || now - c.connected_at <= settings_.handshake_timeout) return;
  const std::string why = "silent for " + ShortSeconds(settings_.handshake_timeout) + " s after connecting";
  Send(id, Notice(events_.silence_line, "connection closed: " + why));
  Drop(id, why);
}

}  // namespace sanet::wire
