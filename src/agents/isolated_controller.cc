#include "agents/isolated_controller.h"

#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstring>
#include <stdexcept>

#include "agents/controller_host.h"
#include "core/exception_text.h"
#include "sanet/codec.h"

namespace sanet::agents {
namespace {

// What crosses the socket. The parent asks the child to run a controller call (kStart, kStep,
// kMessage); while it runs, the child asks the parent for node calls (the rest) and gets one
// answer for each; the call ends with kDone or kFailed (the text of what the controller threw).
enum Call : std::uint8_t {
  kMade = 1,
  kMakeFailed,
  kStart,
  kStep,
  kMessage,
  kDone,
  kFailed,
  kAnswer,
  kNow,
  kLookup,
  kNameOf,
  kIr,
  kLaser,
  kOdometry,
  kGroundTruth,
  kBearing,
  kDrive,
  kSetWheelSpeeds,
  kSend,
  kBroadcast,
  kFlood,
  kRandom,
  kLog,
  kTransition,
  kMetric,
  kProtocol,
  kRoutingTable,
  kNeighbours,
  kInvalidateRoute,
  kRequestRoute
};

constexpr std::size_t kMostBytes = 1 << 20;  // one packet either way

void SendPacket(int fd, const Bytes& bytes) {
  if (::send(fd, bytes.data(), bytes.size(), MSG_NOSIGNAL) != static_cast<ssize_t>(bytes.size()))
    throw std::runtime_error(std::string("the controller's process is gone: ") + std::strerror(errno));
}

// The next packet; nothing when the other side has closed.
std::optional<Bytes> ReceivePacket(int fd) {
  Bytes bytes(kMostBytes);
  ssize_t n;
  do n = ::recv(fd, bytes.data(), bytes.size(), 0);
  while (n < 0 && errno == EINTR);
  if (n <= 0) return std::nullopt;
  bytes.resize(static_cast<std::size_t>(n));
  return bytes;
}

void WriteDoubles(Writer& w, const std::vector<double>& v) {
  w.U32(static_cast<std::uint32_t>(v.size()));
  for (double x : v) w.F64(x);
}
std::vector<double> ReadDoubles(Reader& r) {
  std::vector<double> v(r.U32());
  for (double& x : v) x = r.F64();
  return v;
}
void WriteBytes(Writer& w, const Bytes& b) {
  w.U32(static_cast<std::uint32_t>(b.size()));
  for (std::uint8_t x : b) w.U8(x);
}
Bytes ReadBytes(Reader& r) {
  Bytes b(r.U32());
  for (std::uint8_t& x : b) x = r.U8();
  return b;
}
void WriteScan(Writer& w, const std::optional<RangeScan>& s) {
  w.Bool(s.has_value());
  if (!s) return;
  WriteDoubles(w, s->angles);
  WriteDoubles(w, s->ranges);
  w.F64(s->max_range);
}
std::optional<RangeScan> ReadScan(Reader& r) {
  if (!r.Bool()) return std::nullopt;
  RangeScan s;
  s.angles = ReadDoubles(r);
  s.ranges = ReadDoubles(r);
  s.max_range = r.F64();
  return s;
}
void WritePose(Writer& w, const std::optional<Pose2D>& p) {
  w.Bool(p.has_value());
  if (p) w.F64(p->x).F64(p->y).F64(p->theta);
}
std::optional<Pose2D> ReadPose(Reader& r) {
  if (!r.Bool()) return std::nullopt;
  Pose2D p;
  p.x = r.F64(), p.y = r.F64(), p.theta = r.F64();
  return p;
}
void WriteMessage(Writer& w, const Message& m) {
  w.U8(static_cast<std::uint8_t>(m.delivery)).U32(m.from).U32(m.to).F64(m.time_sent).F64(m.time_received);
  w.Bool(m.hops.has_value()).I32(m.hops.value_or(0));
  WriteBytes(w, m.payload);
}
Message ReadMessage(Reader& r) {
  Message m;
  m.delivery = static_cast<Delivery>(r.U8());
  m.from = r.U32(), m.to = r.U32(), m.time_sent = r.F64(), m.time_received = r.F64();
  const bool hops = r.Bool();
  const int count = r.I32();
  if (hops) m.hops = count;
  m.payload = ReadBytes(r);
  return m;
}

// The child's side: a node whose every call is a question to the parent.
class ProxyNetwork : public NetworkView {
 public:
  explicit ProxyNetwork(std::function<Reader(const Writer&)> ask) : ask_(std::move(ask)) {}
  std::string Protocol() const override { return ask_(Writer().U8(kProtocol)).Text(); }
  std::vector<RouteEntry> RoutingTable() const override {
    Reader r = ask_(Writer().U8(kRoutingTable));
    std::vector<RouteEntry> table(r.U32());
    for (RouteEntry& e : table) {
      e.destination = r.U32(), e.next_hop = r.U32(), e.hops = r.I32(), e.valid = r.Bool();
      e.expires_in = r.F64();
    }
    return table;
  }
  std::vector<NodeId> Neighbours() const override {
    Reader r = ask_(Writer().U8(kNeighbours));
    std::vector<NodeId> ids(r.U32());
    for (NodeId& id : ids) id = r.U32();
    return ids;
  }
  bool InvalidateRoute(NodeId d) override { return ask_(Writer().U8(kInvalidateRoute).U32(d)).Bool(); }
  void RequestRoute(NodeId d) override { ask_(Writer().U8(kRequestRoute).U32(d)); }

 private:
  std::function<Reader(const Writer&)> ask_;
};

class ProxyNode : public Node {
 public:
  ProxyNode(int fd, Reader& identity) : fd_(fd), network_([this](const Writer& w) { return Ask(w); }) {
    id_ = identity.U32();
    name_ = identity.Text();
    count_ = identity.U32();
    holonomic_ = identity.Bool();
  }
  double Now() const override { return Ask(Writer().U8(kNow)).F64(); }
  NodeId Id() const override { return id_; }
  const std::string& Name() const override { return name_; }
  std::optional<NodeId> Lookup(const std::string& name) const override {
    Reader r = Ask(Writer().U8(kLookup).Text(name));
    const bool found = r.Bool();
    const NodeId id = r.U32();
    return found ? std::optional<NodeId>(id) : std::nullopt;
  }
  std::string NameOf(NodeId id) const override { return Ask(Writer().U8(kNameOf).U32(id)).Text(); }
  std::size_t NodeCount() const override { return count_; }
  std::optional<RangeScan> Ir() override { return ReadScanOf(kIr); }
  std::optional<RangeScan> Laser() override { return ReadScanOf(kLaser); }
  std::optional<Pose2D> Odometry() override { return ReadPoseOf(kOdometry); }
  std::optional<Pose2D> GroundTruth() override { return ReadPoseOf(kGroundTruth); }
  std::optional<BearingReading> Bearing(NodeId target) override {
    Reader r = Ask(Writer().U8(kBearing).U32(target));
    if (!r.Bool()) return std::nullopt;
    BearingReading b;
    b.distance = r.F64(), b.bearing = r.F64();
    return b;
  }
  bool Drive(const Twist2D& v) override { return Ask(Writer().U8(kDrive).F64(v.vx).F64(v.vy).F64(v.omega)).Bool(); }
  bool SetWheelSpeeds(const std::vector<double>& w) override {
    Writer question;
    question.U8(kSetWheelSpeeds);
    WriteDoubles(question, w);
    return Ask(question).Bool();
  }
  bool Holonomic() const override { return holonomic_; }
  void Send(NodeId to, const Bytes& payload) override {
    Writer question;
    question.U8(kSend).U32(to);
    WriteBytes(question, payload);
    Ask(question);
  }
  void Broadcast(const Bytes& payload) override { AskWithBytes(kBroadcast, payload); }
  void Flood(const Bytes& payload) override { AskWithBytes(kFlood, payload); }
  NetworkView& Network() override { return network_; }
  double Random() override { return Ask(Writer().U8(kRandom)).F64(); }
  void Log(const std::string& text) override { Ask(Writer().U8(kLog).Text(text)); }
  void Transition(const std::string& from, const std::string& to, const std::string& why) override {
    Ask(Writer().U8(kTransition).Text(from).Text(to).Text(why));
  }
  void Metric(const std::string& name, double value) override { Ask(Writer().U8(kMetric).Text(name).F64(value)); }

 private:
  Reader Ask(const Writer& question) const {
    SendPacket(fd_, question.bytes());
    auto answer = ReceivePacket(fd_);
    if (!answer) std::_Exit(0);  // the run is over
    Reader r(std::move(*answer));
    r.U8();  // kAnswer
    return r;
  }
  void AskWithBytes(Call call, const Bytes& payload) {
    Writer question;
    question.U8(call);
    WriteBytes(question, payload);
    Ask(question);
  }
  std::optional<RangeScan> ReadScanOf(Call call) {
    Reader r = Ask(Writer().U8(call));
    return ReadScan(r);
  }
  std::optional<Pose2D> ReadPoseOf(Call call) {
    Reader r = Ask(Writer().U8(call));
    return ReadPose(r);
  }

  int fd_;
  NodeId id_ = 0;
  std::string name_;
  std::size_t count_ = 0;
  bool holonomic_ = false;
  mutable ProxyNetwork network_;
};

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
      if (call == kMessage) controller->OnMessage(*node, ReadMessage(r));
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
  void OnMessage(Node& node, const Message& m) override {
    Writer request = Request(node, kMessage);
    WriteMessage(request, m);
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
      SendPacketOrCrash(Answer(node, call, r, answer).bytes());
    }
  }

  void SendPacketOrCrash(const Bytes& bytes) {
    try {
      SendPacket(fd_, bytes);
    } catch (const std::runtime_error&) {
      throw std::runtime_error(Crash());
    }
  }

  // Why the child is gone, once it is.
  std::string Crash() {
    int status = 0;
    ::waitpid(child_, &status, 0);
    if (WIFSIGNALED(status))
      return "its process (" + name_ + ", run apart with --isolate-controllers) crashed: signal " +
             std::to_string(WTERMSIG(status)) + " (" + ::strsignal(WTERMSIG(status)) + ")";
    return "its process (" + name_ + ", run apart with --isolate-controllers) exited with status " +
           std::to_string(WEXITSTATUS(status));
  }

  static Writer& Answer(Node& node, Call call, Reader& r, Writer& w) {
    switch (call) {
      case kNow:
        return w.F64(node.Now());
      case kLookup: {
        const auto id = node.Lookup(r.Text());
        return w.Bool(id.has_value()).U32(id.value_or(0));
      }
      case kNameOf:
        return w.Text(node.NameOf(r.U32()));
      case kIr:
        WriteScan(w, node.Ir());
        return w;
      case kLaser:
        WriteScan(w, node.Laser());
        return w;
      case kOdometry:
        WritePose(w, node.Odometry());
        return w;
      case kGroundTruth:
        WritePose(w, node.GroundTruth());
        return w;
      case kBearing: {
        const auto b = node.Bearing(r.U32());
        return w.Bool(b.has_value()).F64(b ? b->distance : 0).F64(b ? b->bearing : 0);
      }
      case kDrive: {
        Twist2D v;
        v.vx = r.F64(), v.vy = r.F64(), v.omega = r.F64();
        return w.Bool(node.Drive(v));
      }
      case kSetWheelSpeeds:
        return w.Bool(node.SetWheelSpeeds(ReadDoubles(r)));
      case kSend: {
        const NodeId to = r.U32();
        node.Send(to, ReadBytes(r));
        return w;
      }
      case kBroadcast:
        node.Broadcast(ReadBytes(r));
        return w;
      case kFlood:
        node.Flood(ReadBytes(r));
        return w;
      case kRandom:
        return w.F64(node.Random());
      case kLog:
        node.Log(r.Text());
        return w;
      case kTransition: {
        const std::string from = r.Text(), to = r.Text(), why = r.Text();
        node.Transition(from, to, why);
        return w;
      }
      case kMetric: {
        const std::string name = r.Text();
        node.Metric(name, r.F64());
        return w;
      }
      case kProtocol:
        return w.Text(node.Network().Protocol());
      case kRoutingTable: {
        const auto table = node.Network().RoutingTable();
        w.U32(static_cast<std::uint32_t>(table.size()));
        for (const RouteEntry& e : table)
          w.U32(e.destination).U32(e.next_hop).I32(e.hops).Bool(e.valid).F64(e.expires_in);
        return w;
      }
      case kNeighbours: {
        const auto ids = node.Network().Neighbours();
        w.U32(static_cast<std::uint32_t>(ids.size()));
        for (NodeId id : ids) w.U32(id);
        return w;
      }
      case kInvalidateRoute:
        return w.Bool(node.Network().InvalidateRoute(r.U32()));
      case kRequestRoute:
        node.Network().RequestRoute(r.U32());
        return w;
      default:
        throw std::runtime_error("its process asked for an unknown node call " + std::to_string(call));
    }
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

}  // namespace sanet::agents
