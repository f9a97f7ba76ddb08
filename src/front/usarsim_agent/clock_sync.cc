#include "usarsim_agent/clock_sync.h"

#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "wire/sockets.h"
#include "wire/time_service.h"

namespace sanet::usarsim_agent {
namespace {

constexpr int kReplyWaitMs = 200;  // an exchange not answered by then is lost
constexpr int kFirstTries = 25;    // bursts before giving up at the start (about 5 s)

}  // namespace

ClockSync::ClockSync(const std::string& host, std::uint16_t port, double skew)
    : server_(host + ":" + std::to_string(port)), skew_(skew) {
  const sockaddr_in server = wire::Ipv4Endpoint(host, port);
  fd_ = ::socket(AF_INET, SOCK_DGRAM, 0);
  // Connected: the kernel passes on only datagrams from the server's address and port.
  if (fd_ < 0 || ::connect(fd_, reinterpret_cast<const sockaddr*>(&server), sizeof server) != 0)
    throw std::runtime_error("cannot open a UDP socket to the server's time service " + server_ + ": " +
                             std::strerror(errno));
  std::optional<wire::ClockSample> first;
  for (int attempt = 0; attempt < kFirstTries && !first; ++attempt) first = Burst(kFirstBurst);
  if (!first) {
    ::close(fd_);
    throw std::runtime_error("the server's time service at UDP " + server_ +
                             " does not answer (a firewall closing that UDP port?)");
  }
  Take(*first);
  thread_ = std::thread([this] { Refresh(); });
}

ClockSync::~ClockSync() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
  ::close(fd_);
}

double ClockSync::Local() const { return wire::MonotonicSeconds() + skew_; }

double ClockSync::ServerNow() const {
  std::lock_guard<std::mutex> lock(mutex_);
  const double local = Local();
  last_read_ = std::max(last_read_, local + estimate_.Offset(local));  // a new estimate never turns time back
  return last_read_;
}

ClockFigures ClockSync::figures() const {
  std::lock_guard<std::mutex> lock(mutex_);
  ClockFigures f = figures_;
  const double local = Local();
  f.offset = estimate_.Offset(local);
  f.error_bound = estimate_.ErrorBound(local);
  return f;
}

// Exchanges one after another; each waits for its own reply (a late reply to an earlier
// request carries another t1 and is passed over).
std::optional<wire::ClockSample> ClockSync::Burst(int exchanges) {
  std::vector<wire::ClockExchange> answered;
  std::uint64_t unanswered = 0;
  for (int i = 0; i < exchanges; ++i) {
    const double sent = Local();
    const Bytes request = wire::TimeRequest(sent);
    if (::send(fd_, request.data(), request.size(), 0) < 0) {
      ++unanswered;
      continue;
    }
    std::optional<wire::ClockExchange> e;
    while (!e) {
      pollfd p{fd_, POLLIN, 0};
      const int waited_ms = static_cast<int>((Local() - sent) * 1000);
      if (waited_ms >= kReplyWaitMs || ::poll(&p, 1, kReplyWaitMs - waited_ms) <= 0) break;
      std::uint8_t buffer[64];
      const ssize_t n = ::recv(fd_, buffer, sizeof buffer, MSG_DONTWAIT);
      const double received = Local();
      if (n > 0) e = wire::ReadTimeReply(buffer, static_cast<std::size_t>(n), sent, received);
      if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK) break;  // e.g. refused: nothing listens there
    }
    if (e)
      answered.push_back(*e);
    else
      ++unanswered;
  }
  std::lock_guard<std::mutex> lock(mutex_);
  figures_.exchanges += answered.size();
  figures_.unanswered += unanswered;
  return wire::Best(answered);
}

void ClockSync::Take(const wire::ClockSample& best) {
  std::lock_guard<std::mutex> lock(mutex_);
  estimate_.Add(best);
  ++figures_.bursts;
  figures_.round_trip = best.round_trip;
  figures_.drift = estimate_.Drift();
  // The bound grows until the next burst: the largest is the one just before it.
  const double before_next = estimate_.ErrorBound(best.at + kRefreshPeriod);
  figures_.error_bound_max = std::max(figures_.error_bound_max, before_next);
}

void ClockSync::Refresh() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!wake_.wait_for(lock, std::chrono::duration<double>(kRefreshPeriod), [this] { return stop_; })) {
    lock.unlock();
    if (const auto best = Burst(kBurst)) Take(*best);
    lock.lock();
  }
}

}  // namespace sanet::usarsim_agent
