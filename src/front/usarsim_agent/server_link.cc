#include "usarsim_agent/server_link.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <stdexcept>
#include <thread>

#include "core/version.h"
#include "wire/message_lines.h"
#include "wire/sockets.h"

namespace sanet::usarsim_agent {
namespace {

constexpr int kConnectWait = 10;   // s: the server may still be starting
constexpr double kReplyWait = 10;  // s for an answer to one request

// A host name or dotted address, as the dotted IPv4 address it resolves to.
std::string Ipv4AddressOf(const std::string& host) {
  addrinfo hints{};
  hints.ai_family = AF_INET;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* found = nullptr;
  if (const int error = ::getaddrinfo(host.c_str(), nullptr, &hints, &found); error != 0)
    throw std::runtime_error("cannot find the server's host '" + host + "': " + ::gai_strerror(error));
  const std::string text = wire::AddressText(found->ai_addr);
  ::freeaddrinfo(found);
  return text;
}

// One non-blocking connection attempt that gives up at `deadline` (an address that does not
// answer would otherwise hold connect() for minutes); -1 with the reason in `why`.
int ConnectBefore(const sockaddr_in& server, std::chrono::steady_clock::time_point deadline, std::string* why) {
  const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK, 0);
  int error = ::connect(fd, reinterpret_cast<const sockaddr*>(&server), sizeof server) == 0 ? 0 : errno;
  if (error == EINPROGRESS) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    pollfd p{fd, POLLOUT, 0};
    if (::poll(&p, 1, static_cast<int>(std::max<std::int64_t>(0, left.count()))) > 0) {
      socklen_t size = sizeof error;
      ::getsockopt(fd, SOL_SOCKET, SO_ERROR, &error, &size);
    } else {
      error = ETIMEDOUT;
    }
  }
  if (error == 0) return fd;
  *why = std::strerror(error);
  ::close(fd);
  return -1;
}

}  // namespace

ServerLink::ServerLink(const std::string& host, std::uint16_t port)
    : host_(Ipv4AddressOf(host)), address_(host + ":" + std::to_string(port)) {
  const sockaddr_in server = wire::Ipv4Endpoint(host_, port);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(kConnectWait);
  std::string why = "no answer";
  while (fd_ < 0 && std::chrono::steady_clock::now() < deadline) {
    fd_ = ConnectBefore(server, deadline, &why);
    if (fd_ < 0) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  if (fd_ < 0)
    throw std::runtime_error("cannot reach the server at " + address_ + " within " + std::to_string(kConnectWait) +
                             " s: " + why + " (is `sanet serve` running there, and its run not over yet?)");
  const int yes = 1;
  ::setsockopt(fd_, IPPROTO_TCP, TCP_NODELAY, &yes, sizeof yes);
  const wire::ProtocolMessage greeting = Await("NFO", "");
  clock_origin_ = greeting.Number("ClockOrigin");
}

ServerLink::~ServerLink() {
  if (fd_ >= 0) ::close(fd_);
}

void ServerLink::Send(const wire::ProtocolMessage& m) {
  const std::string line = wire::FormatLine(m);
  std::size_t sent = 0;
  while (fd_ >= 0 && sent < line.size()) {
    const ssize_t n = ::send(fd_, line.data() + sent, line.size() - sent, MSG_NOSIGNAL);
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
      continue;
    }
    if (n <= 0) return;
    sent += static_cast<std::size_t>(n);
  }
}

bool ServerLink::Read(std::vector<wire::ProtocolMessage>& lines) {
  lines = std::move(waiting_);
  waiting_.clear();
  char buffer[65536];
  while (fd_ >= 0) {
    const ssize_t n = ::recv(fd_, buffer, sizeof buffer, 0);
    if (n == 0 || (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK)) {
      ::close(fd_);
      fd_ = -1;
      break;
    }
    if (n < 0) break;
    reader_.Append(std::string_view(buffer, static_cast<std::size_t>(n)));
  }
  bool too_long = false;
  while (auto line = reader_.Next(&too_long)) {
    std::string error;
    if (auto m = wire::ParseLine(*line, &error)) lines.push_back(std::move(*m));
  }
  return fd_ >= 0 || !lines.empty();
}

// Waits up to `timeout` s for the first line that `answers`; the others wait for Read. Nothing
// when the time is up or the server has closed.
std::optional<wire::ProtocolMessage> ServerLink::WaitFor(
    const std::function<bool(const wire::ProtocolMessage&)>& answers, double timeout) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout);
  std::vector<wire::ProtocolMessage> kept;
  std::optional<wire::ProtocolMessage> answer;
  bool open = true;
  while (!answer && open && std::chrono::steady_clock::now() < deadline) {
    std::vector<wire::ProtocolMessage> lines;
    open = Read(lines);
    for (wire::ProtocolMessage& line : lines)
      if (!answer && answers(line))
        answer = std::move(line);
      else
        kept.push_back(std::move(line));
    if (answer || !open) break;
    pollfd p{fd_, POLLIN, 0};
    ::poll(&p, 1, std::max(1, static_cast<int>(timeout * 1000 / 20)));
  }
  kept.insert(kept.end(), std::make_move_iterator(waiting_.begin()), std::make_move_iterator(waiting_.end()));
  waiting_ = std::move(kept);
  return answer;
}

// Waits for the first line of `type`; other lines wait for Read. An ERR is the server's answer.
wire::ProtocolMessage ServerLink::Await(const std::string& type, const std::string& request) {
  const auto line =
      WaitFor([&](const wire::ProtocolMessage& m) { return m.type == type || m.type == "ERR"; }, kReplyWait);
  if (line && line->type == type) return *line;
  if (line) {
    const std::string* text = line->Get("Message");
    throw std::runtime_error("the server at " + address_ + " says: " + (text ? *text : "error"));
  }
  if (fd_ < 0) throw std::runtime_error("the server at " + address_ + " closed the connection");
  throw std::runtime_error("the server at " + address_ + " did not answer" + (request.empty() ? "" : " " + request) +
                           " within " + std::to_string(static_cast<int>(kReplyWait)) + " s");
}

std::optional<wire::ProtocolMessage> ServerLink::Ask(const wire::ProtocolMessage& request,
                                                     const std::string& reply_type, double timeout) {
  Send(request);
  return WaitFor(
      [&](const wire::ProtocolMessage& m) {
        if (m.type == reply_type) return true;
        const std::string* text = m.Get("Message");
        return m.type == "ERR" && text && text->find(request.type) != std::string::npos;
      },
      timeout);
}

ServerHello ServerLink::Handshake(int protocol, const std::string& fingerprint) {
  wire::ProtocolMessage hello{"SANET"};
  hello.Add("Protocol", std::to_string(protocol)).Add("Version", SanetVersion());
  if (!fingerprint.empty()) hello.Add("Fingerprint", fingerprint);
  Send(hello);
  wire::ProtocolMessage reply;
  try {
    reply = Await("SANET", "SANET");
  } catch (const std::runtime_error& e) {
    if (std::string(e.what()).find("unknown command SANET") == std::string::npos) throw;
    throw std::runtime_error("the server at " + address_ +
                             " does not speak sanet's extensions (sanet before protocol 2, or another USARSim server)");
  }
  const auto theirs = reply.Count("Protocol", 1000000);
  const std::string* version = reply.Get("Version");
  if (!theirs || *theirs != static_cast<std::uint64_t>(protocol))
    throw std::runtime_error("the server at " + address_ + " speaks sanet's protocol " +
                             (theirs ? std::to_string(*theirs) : "?") + " (sanet " + (version ? *version : "?") +
                             "), this agent " + std::to_string(protocol) + " (sanet " + SanetVersion() +
                             "); run the same sanet on both computers");
  ServerHello h;
  h.version = version ? *version : "";
  if (const std::string* f = reply.Get("Fingerprint")) h.fingerprint = *f;
  h.time_port = time_port_ = static_cast<std::uint16_t>(reply.Count("TimePort", 65535).value_or(0));
  return h;
}

std::string ServerLink::FetchScenario() {
  std::string yaml;
  for (std::uint64_t part = 0, parts = 1; part < parts; ++part) {
    wire::ProtocolMessage request{"GETSCENARIO"};
    Send(request.Add("Part", std::to_string(part)));
    const wire::ProtocolMessage reply = Await("SCENARIO", "GETSCENARIO");
    const auto n = reply.Count("Parts", 1 << 20);
    const std::string* hex = reply.Get("Yaml");
    const auto bytes = hex ? wire::FromHex(*hex) : std::nullopt;
    if (!n || !bytes) throw std::runtime_error("the server at " + address_ + " sent a malformed SCENARIO line");
    parts = *n;
    yaml.append(bytes->begin(), bytes->end());
  }
  return yaml;
}

wire::PluginIdentity ServerLink::FetchPlugin(const std::string& robot) {
  wire::ProtocolMessage request{"GETPLUGIN"};
  Send(request.Add("Robot", robot));
  const wire::ProtocolMessage reply = Await("PLUGIN", "GETPLUGIN");
  wire::PluginIdentity id;
  id.controller_api = static_cast<int>(reply.Count("ControllerApi", 1000000).value_or(0));
  if (const std::string* library = reply.Get("Library")) id.library = *library;
  if (const std::string* sha = reply.Get("Sha256")) id.sha256 = *sha;
  if (const std::string* python = reply.Get("Python")) id.python = *python;
  return id;
}

}  // namespace sanet::usarsim_agent
