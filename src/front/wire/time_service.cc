#include "wire/time_service.h"

#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <stdexcept>

#include "sanet/codec.h"
#include "wire/sockets.h"

namespace sanet::wire {
namespace {

constexpr std::uint32_t kRequestMagic = 0x31515473;  // "sTQ1" as little-endian bytes
constexpr std::uint32_t kReplyMagic = 0x31525473;    // "sTR1"

int BindUdp(const std::string& bind, std::uint16_t port) {
  const sockaddr_in address = Ipv4Endpoint(bind, port);
  const int fd = ::socket(AF_INET, SOCK_DGRAM, 0);
  if (fd < 0) throw std::runtime_error(std::string("cannot open a UDP socket: ") + std::strerror(errno));
  if (::bind(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) == 0) return fd;
  const std::string why = std::strerror(errno);
  ::close(fd);
  throw std::runtime_error("cannot bind the time service to UDP " + bind + ":" + std::to_string(port) + ": " + why);
}

}  // namespace

Bytes TimeRequest(double sent) { return Writer().U32(kRequestMagic).F64(sent).bytes(); }

std::optional<double> ReadTimeRequest(const std::uint8_t* data, std::size_t size) {
  if (size != 12) return std::nullopt;
  Reader r(Bytes(data, data + size));
  if (r.U32() != kRequestMagic) return std::nullopt;
  return r.F64();
}

Bytes TimeReply(double sent, double server_received, double server_sent) {
  return Writer().U32(kReplyMagic).F64(sent).F64(server_received).F64(server_sent).bytes();
}

std::optional<ClockExchange> ReadTimeReply(const std::uint8_t* data, std::size_t size, double sent, double received) {
  if (size != 28) return std::nullopt;
  Reader r(Bytes(data, data + size));
  if (r.U32() != kReplyMagic || r.F64() != sent) return std::nullopt;  // not the answer to this request
  ClockExchange e;
  e.sent = sent;
  e.server_received = r.F64();
  e.server_sent = r.F64();
  e.received = received;
  return e;
}

double MonotonicSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

TimeService::TimeService(const std::string& bind, std::uint16_t port, double origin) : origin_(origin) {
  try {
    fd_ = BindUdp(bind, port);
  } catch (const std::runtime_error&) {
    if (port == 0) throw;
    fd_ = BindUdp(bind, 0);  // the robot protocol's port number is taken for UDP: any other
  }
  sockaddr_in address{};
  socklen_t size = sizeof address;
  ::getsockname(fd_, reinterpret_cast<sockaddr*>(&address), &size);
  port_ = ntohs(address.sin_port);
  thread_ = std::thread([this] { Serve(); });
}

TimeService::~TimeService() {
  stop_ = true;
  thread_.join();
  ::close(fd_);
}

// Blocks in poll (waking every 0.1 s to see whether to stop) and answers each request at once.
void TimeService::Serve() {
  std::uint8_t buffer[64];
  while (!stop_) {
    pollfd p{fd_, POLLIN, 0};
    if (::poll(&p, 1, 100) <= 0) continue;
    sockaddr_in from{};
    socklen_t size = sizeof from;
    const ssize_t n = ::recvfrom(fd_, buffer, sizeof buffer, MSG_DONTWAIT, reinterpret_cast<sockaddr*>(&from), &size);
    const double received = MonotonicSeconds() - origin_;
    if (n <= 0) continue;
    const auto sent = ReadTimeRequest(buffer, static_cast<std::size_t>(n));
    if (!sent) continue;  // not a request: nothing to say to whoever sent it
    ++served_;            // before the reply: whoever has it may count on it
    const Bytes reply = TimeReply(*sent, received, MonotonicSeconds() - origin_);
    ::sendto(fd_, reply.data(), reply.size(), 0, reinterpret_cast<const sockaddr*>(&from), size);
  }
}

}  // namespace sanet::wire
