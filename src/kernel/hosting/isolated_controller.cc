#include "hosting/isolated_controller.h"

#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstring>
#include <stdexcept>
#include <tuple>
#include <type_traits>

#include "core/exception_text.h"
#include "hosting/controller_host.h"
#include "hosting/node_call_codec.h"
#include "hosting/node_calls.h"
#include "sanet/codec.h"

namespace sanet::hosting {
namespace {

// What crosses the socket. The parent asks the child to run a controller call (kStart, kStep,
// kMessage, kFinish); while it runs, the child asks the parent for node calls (the call list of
// hosting/node_calls.h) and gets one answer for each; the call ends with kDone or kFailed (the text
// of what the controller threw).
#define SANET_CALL_NUMBER(name, ...) k##name,
enum Call : std::uint8_t {
  kMade = 1,
  kMakeFailed,
  kStart,
  kStep,
  kMessage,
  kFinish,
  kDone,
  kFailed,
  kAnswer,
  SANET_NODE_CALLS(SANET_CALL_NUMBER) SANET_NETWORK_CALLS(SANET_CALL_NUMBER)
};
#undef SANET_CALL_NUMBER

// A message goes as packets of at most kChunk bytes, each led by a byte saying whether more of it
// follows: a SOCK_SEQPACKET packet past the socket's send buffer (about 208 KiB) is refused, and a
// camera's picture with its depth is larger than that.
constexpr std::size_t kChunk = 64 * 1024;
constexpr std::size_t kMostBytes = std::size_t{256} << 20;  // a message, whole: past it, the peer is faulty

void SendPacket(int fd, const Bytes& bytes) {
  std::size_t offset = 0;
  do {
    const std::size_t size = std::min(kChunk, bytes.size() - offset);
    Bytes packet;
    packet.reserve(size + 1);
    packet.push_back(offset + size < bytes.size() ? 1 : 0);
    packet.insert(packet.end(), bytes.begin() + static_cast<std::ptrdiff_t>(offset),
                  bytes.begin() + static_cast<std::ptrdiff_t>(offset + size));
    ssize_t sent;
    do sent = ::send(fd, packet.data(), packet.size(), MSG_NOSIGNAL);
    while (sent < 0 && errno == EINTR);
    if (sent != static_cast<ssize_t>(packet.size()))
      throw std::runtime_error(std::string("the controller's process is gone: ") + std::strerror(errno));
    offset += size;
  } while (offset < bytes.size());
}

// The next message; nothing when the other side has closed.
std::optional<Bytes> ReceivePacket(int fd) {
  Bytes message, packet(kChunk + 1);
  for (;;) {
    ssize_t n;
    do n = ::recv(fd, packet.data(), packet.size(), 0);
    while (n < 0 && errno == EINTR);
    if (n <= 0 || message.size() + static_cast<std::size_t>(n) > kMostBytes) return std::nullopt;
    message.insert(message.end(), packet.begin() + 1, packet.begin() + n);
    if (packet[0] == 0) return message;
  }
}

// The child's question to the parent: a call and its arguments; the answer is the call's result.
template <typename Result, typename... Args>
Result Ask(int fd, Call call, const std::tuple<Args...>& args) {
  Writer question;
  question.U8(call);
  std::apply([&](const auto&... a) { (node_calls::Put(question, a), ...); }, args);
  SendPacket(fd, question.bytes());
  auto answer = ReceivePacket(fd);
  if (!answer) std::_Exit(0);  // the run is over
  Reader r(std::move(*answer));
  r.U8();  // kAnswer
  if constexpr (!std::is_void_v<Result>) return node_calls::Get<Result>(r);
}

#define SANET_PROXY_CALL(name, override_name, Result, params, args, constness) \
  Result override_name params constness override { return Ask<Result>(fd_, k##name, std::forward_as_tuple args); }

// The child's side: a node whose every call is a question to the parent.
class ProxyNetwork : public NetworkView {
 public:
  explicit ProxyNetwork(int fd) : fd_(fd) {}
  SANET_NETWORK_CALLS(SANET_PROXY_CALL)

 private:
  int fd_;
};

class ProxyNode : public Node {
 public:
  ProxyNode(int fd, Reader& identity) : fd_(fd), network_(fd) {
    id_ = identity.U32();
    name_ = identity.Text();
    count_ = identity.U32();
    holonomic_ = identity.Bool();
  }
  NodeId Id() const override { return id_; }
  const std::string& Name() const override { return name_; }
  std::size_t NodeCount() const override { return count_; }
  bool Holonomic() const override { return holonomic_; }
  NetworkView& Network() override { return network_; }
  SANET_NODE_CALLS(SANET_PROXY_CALL)

 private:
  int fd_;
  NodeId id_ = 0;
  std::string name_;
  std::size_t count_ = 0;
  bool holonomic_ = false;
  ProxyNetwork network_;
};
#undef SANET_PROXY_CALL

// The parent's answer to a question: `call` with the arguments read from `r`, its result
// written to `w`.
template <typename F>
struct CallOf : CallOf<decltype(&F::operator())> {};
template <typename F, typename Result, typename... Args>
struct CallOf<Result (F::*)(Args...) const> {
  static void Answer(const F& call, Reader& r, Writer& w) {
    auto args = node_calls::GetAll<std::decay_t<Args>...>(r);
    if constexpr (std::is_void_v<Result>)
      std::apply(call, args);
    else
      node_calls::Put(w, std::apply(call, args));
  }
};
template <typename F>
void AnswerWith(const F& call, Reader& r, Writer& w) {
  CallOf<F>::Answer(call, r, w);
}

#define SANET_NODE_ANSWER(name, override_name, Result, params, args, constness) \
  case k##name:                                                                 \
    return AnswerWith([&node] params { return node.name args; }, r, w);
#define SANET_NETWORK_ANSWER(name, override_name, Result, params, args, constness) \
  case k##name:                                                                    \
    return AnswerWith([&node] params { return node.Network().name args; }, r, w);

void Answer(Node& node, Call call, Reader& r, Writer& w) {
  switch (call) {
    SANET_NODE_CALLS(SANET_NODE_ANSWER)
    SANET_NETWORK_CALLS(SANET_NETWORK_ANSWER)
    default:
      throw std::runtime_error("its process asked for an unknown node call " + std::to_string(call));
  }
}
#undef SANET_NODE_ANSWER
#undef SANET_NETWORK_ANSWER

// The child: makes the controller, then runs each call the parent asks for.
[[noreturn]] void HostInChild(int fd, const ControllerSpec& spec, Registry& registry) {
  std::unique_ptr<Controller> controller;
  try {
    controller = MakeController(spec, registry);
    SendPacket(fd, Writer().U8(kMade).bytes());
  } catch (...) {
    SendPacket(fd, Writer().U8(kMakeFailed).Text(CurrentExceptionText()).bytes());
    std::_Exit(0);
  }
  std::unique_ptr<ProxyNode> node;
  while (auto request = ReceivePacket(fd)) {
    Reader r(std::move(*request));
    const auto call = static_cast<Call>(r.U8());
    if (!node) node = std::make_unique<ProxyNode>(fd, r);  // the first call names the node
    try {
      if (call == kStart) controller->Start(*node);
      if (call == kStep) controller->ControlStep(*node);
      if (call == kMessage) controller->OnMessage(*node, node_calls::Get<Message>(r));
      if (call == kFinish) controller->Finish(*node);
      SendPacket(fd, Writer().U8(kDone).bytes());
    } catch (...) {
      SendPacket(fd, Writer().U8(kFailed).Text(CurrentExceptionText()).bytes());
    }
  }
  std::_Exit(0);
}

// The parent's side: a controller whose calls run in the child.
class IsolatedController : public Controller {
 public:
  IsolatedController(int fd, pid_t child, std::string name) : fd_(fd), child_(child), name_(std::move(name)) {}
  ~IsolatedController() override {
    ::close(fd_);
    ::kill(child_, SIGKILL);
    ::waitpid(child_, nullptr, 0);
  }
  void Start(Node& node) override { Run(node, Request(node, kStart)); }
  void ControlStep(Node& node) override { Run(node, Request(node, kStep)); }
  void Finish(Node& node) override { Run(node, Request(node, kFinish)); }
  void OnMessage(Node& node, const Message& m) override {
    Writer request = Request(node, kMessage);
    node_calls::Put(request, m);
    Run(node, request);
  }

 private:
  // The call, and with the first one the node's identity, which the child's node needs.
  Writer Request(Node& node, Call call) {
    Writer request;
    request.U8(call);
    if (introduced_) return request;
    introduced_ = true;
    request.U32(node.Id()).Text(node.Name()).U32(static_cast<std::uint32_t>(node.NodeCount())).Bool(node.Holonomic());
    return request;
  }

  // Sends the call, then answers the child's node calls until the call is done.
  void Run(Node& node, const Writer& request) {
    SendPacketOrCrash(request.bytes());
    while (true) {
      auto packet = ReceivePacket(fd_);
      if (!packet) throw std::runtime_error(Crash());
      Reader r(std::move(*packet));
      const auto call = static_cast<Call>(r.U8());
      if (call == kDone) return;
      if (call == kFailed) throw std::runtime_error(r.Text());
      Writer answer;
      answer.U8(kAnswer);  // never an empty packet: that would read as the end of the stream
      Answer(node, call, r, answer);
      SendPacketOrCrash(answer.bytes());
    }
  }

  void SendPacketOrCrash(const Bytes& bytes) {
    try {
      SendPacket(fd_, bytes);
    } catch (const std::runtime_error&) {
      throw std::runtime_error(Crash());
    }
  }

  // Why the child is gone, once it is. It is killed first, in case it is not gone but stuck (a
  // message too large to take, a send the parent will never read): a child that has exited
  // keeps its status.
  std::string Crash() {
    int status = 0;
    ::kill(child_, SIGKILL);
    ::waitpid(child_, &status, 0);
    if (WIFSIGNALED(status))
      return "its process (" + name_ + ", run apart with --isolate-controllers) crashed: signal " +
             std::to_string(WTERMSIG(status)) + " (" + ::strsignal(WTERMSIG(status)) + ")";
    return "its process (" + name_ + ", run apart with --isolate-controllers) exited with status " +
           std::to_string(WEXITSTATUS(status));
  }

  int fd_;
  pid_t child_;
  std::string name_;
  bool introduced_ = false;
};

}  // namespace

std::unique_ptr<Controller> MakeIsolatedController(const ControllerSpec& spec, Registry& registry) {
  int fds[2];
  if (::socketpair(AF_UNIX, SOCK_SEQPACKET | SOCK_CLOEXEC, 0, fds) != 0)
    throw std::runtime_error(std::string("cannot open a socket to a controller's process: ") + std::strerror(errno));
  const pid_t parent = ::getpid();
  const pid_t child = ::fork();
  if (child < 0) throw std::runtime_error(std::string("cannot start a controller's process: ") + std::strerror(errno));
  if (child == 0) {
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);  // it dies with the run
    if (::getppid() != parent) std::_Exit(0);
    ::close(fds[0]);
    HostInChild(fds[1], spec, registry);
  }
  ::close(fds[1]);
  auto controller = std::make_unique<IsolatedController>(fds[0], child, spec.name);
  const auto made = ReceivePacket(fds[0]);
  if (!made) throw RegistryError("controller '" + spec.name + "' could not be made: its process ended");
  Reader r(*made);
  if (r.U8() == kMakeFailed) throw RegistryError(r.Text());
  return controller;
}

}  // namespace sanet::hosting
