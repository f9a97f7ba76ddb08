#include "wss/wss_relay.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "wire/sockets.h"

namespace sanet::wss {
namespace {

constexpr std::size_t kMaxPending = 256 * 1024;  // per direction: stop reading beyond it

void NonBlocking(int fd) { ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK); }

}  // namespace

WssRelay::WssRelay(const std::string& bind, std::string target_host, std::uint16_t target_port)
    : bind_(bind), target_host_(std::move(target_host)), target_port_(target_port) {
  Listen();
  if (listener_ < 0) throw std::runtime_error("cannot open a relay port on " + bind_);
}

WssRelay::~WssRelay() { SetLinkUp(false); }

// On the relay's own port once it has one, so that a robot that asked keeps its answer.
void WssRelay::Listen() {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0) return;
  const int yes = 1;
  ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  sockaddr_in a = wire::Ipv4Endpoint(bind_, port_);
  if (::bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0 || ::listen(fd, 8) != 0) {
    ::close(fd);
    return;
  }
  NonBlocking(fd);
  socklen_t size = sizeof a;
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&a), &size);
  port_ = ntohs(a.sin_port);
  listener_ = fd;
}

void WssRelay::SetLinkUp(bool up) {
  if (up && listener_ < 0) Listen();
  if (up || listener_ < 0) return;
  ::close(listener_);
  listener_ = -1;
  for (Pipe& p : pipes_) {
    if (p.accepted >= 0) ++cut_;
    Close(p);
  }
  pipes_.clear();
}

void WssRelay::Accept() {
  while (listener_ >= 0) {
    const int accepted = ::accept(listener_, nullptr, nullptr);
    if (accepted < 0) return;
    NonBlocking(accepted);
    Pipe pipe;
    pipe.accepted = accepted;
    pipe.outgoing = ::socket(AF_INET, SOCK_STREAM, 0);
    NonBlocking(pipe.outgoing);
    const sockaddr_in target = wire::Ipv4Endpoint(target_host_, target_port_);
    if (::connect(pipe.outgoing, reinterpret_cast<const sockaddr*>(&target), sizeof target) != 0 &&
        errno != EINPROGRESS) {
      Close(pipe);
      continue;
    }
    sockaddr_in local{};
    socklen_t size = sizeof local;
    ::getsockname(pipe.outgoing, reinterpret_cast<sockaddr*>(&local), &size);
    pipe.local_port = ntohs(local.sin_port);
    ++connections_;
    pipes_.push_back(std::move(pipe));
  }
}

// Reads what `from` has (unless `pending` is full) and writes what is pending to `to`. False
// when `from` has ended or either side failed.
bool WssRelay::Copy(int from, int to, std::string& pending) {
  char buffer[16384];
  bool alive = true;
  while (pending.size() < kMaxPending) {
    const ssize_t n = ::recv(from, buffer, sizeof buffer, 0);
    if (n == 0 || (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK)) alive = false;
    if (n <= 0) break;
    pending.append(buffer, n);
  }
  while (!pending.empty()) {
    const ssize_t n = ::send(to, pending.data(), pending.size(), MSG_NOSIGNAL);
    if (n < 0) {
      if (errno != EAGAIN && errno != EWOULDBLOCK && errno != ENOTCONN) alive = false;
      break;
    }
    bytes_ += n;
    pending.erase(0, n);
  }
  return alive;
}

void WssRelay::Pump() {
  Accept();
  for (Pipe& p : pipes_) {
    const bool forward = Copy(p.accepted, p.outgoing, p.to_target);
    const bool back = Copy(p.outgoing, p.accepted, p.to_source);
    if (!forward || !back) p.closing = true;
    if (p.closing && p.to_target.empty() && p.to_source.empty()) Close(p);
  }
  pipes_.erase(std::remove_if(pipes_.begin(), pipes_.end(), [](const Pipe& p) { return p.accepted < 0; }),
               pipes_.end());
}

void WssRelay::Close(Pipe& p) {
  if (p.accepted >= 0) ::close(p.accepted);
  if (p.outgoing >= 0) ::close(p.outgoing);
  p.accepted = p.outgoing = -1;
}

bool WssRelay::UsesLocalPort(std::uint16_t port) const {
  return std::any_of(pipes_.begin(), pipes_.end(), [&](const Pipe& p) { return p.local_port == port; });
}

}  // namespace sanet::wss
