#include "hil/sim_server.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "core/json_text.h"
#include "core/statistics.h"
#include "hil/agent_datagram.h"
#include "hil/message_lines.h"
#include "hil/sockets.h"
#include "hil/tcp_window.h"
#include "sim/spawning.h"

namespace sanet::hil {
namespace {

double WallNow() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

// sanet's frame is z up (x forward, y left, angles counter-clockwise); USARSim's is z down
// (x forward, y right, yaw clockwise): y and yaw change sign at the boundary.
std::vector<double> ToUsarsim(const Pose2D& p) { return {p.x, -p.y, -p.theta}; }

// A client whose advertised window is this close to the widest it has advertised has read what
// reached it, give or take the last lines (a laser scan line is about 1.5 KB).
constexpr std::uint32_t kWindowSlack = 4 * 1024;
constexpr int kSendBuffer = 16 * 1024;  // bytes the server's kernel holds for one client
std::string ShortSeconds(double s) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", s);
  return text;
}

constexpr double kClosingLinger = 1.0;  // s a connection the server ends has to read its ERR and hang up

}  // namespace

void RaiseDescriptorLimit(std::size_t max_clients) {
  const rlim_t needed = 2 * static_cast<rlim_t>(max_clients) + 64;  // clients, refused ones, results, ns-3
  rlimit limit{};
  ::getrlimit(RLIMIT_NOFILE, &limit);
  if (limit.rlim_cur >= needed) return;
  if (limit.rlim_max != RLIM_INFINITY && limit.rlim_max < needed)
    throw std::runtime_error("a cap of " + std::to_string(max_clients) + " connections needs " +
                             std::to_string(needed) + " file descriptors; this process may open at most " +
                             std::to_string(limit.rlim_max) + " (ulimit -Hn)");
  limit.rlim_cur = needed;
  ::setrlimit(RLIMIT_NOFILE, &limit);
}

std::size_t DefaultMaxClients(const sim::RunSpec& spec) {
  const auto robots = std::count_if(spec.nodes.begin(), spec.nodes.end(),
                                    [](const sim::NodeSpec& n) { return n.model.kind != robots::ModelKind::kMote; });
  return std::max<std::size_t>(64, 2 * static_cast<std::size_t>(robots));
}

SimServer::SimServer(sim::World& world, ServerSettings settings)
    : world_(world), settings_(std::move(settings)), claimed_(world.NodeCount(), false) {
  world_.parts().SetRemoteInbox([this](NodeId to, const Message& m) { return Forward(to, m); });
  if (settings_.max_clients == 0) throw std::runtime_error("the connection cap must be at least 1");
  RaiseDescriptorLimit(settings_.max_clients);
  listener_ = ListenTcp(settings_.bind, settings_.port, static_cast<int>(settings_.max_clients), &port_);
}

SimServer::~SimServer() {
  world_.parts().SetRemoteInbox(nullptr);
  for (auto& c : clients_) ::close(c->fd);
  for (const Closing& r : closing_) ::close(r.fd);
  if (listener_ >= 0) ::close(listener_);
}

void SimServer::Start() {
  world_.Every(settings_.poll_period, [this] { Poll(); });
  world_.AddObserver(*this);
}

// The lag of every physics step behind the wall clock.
void SimServer::AfterStep(const sim::WorldSnapshot& snapshot) {
  lags_.push_back(std::max(0.0, (WallNow() - wall_start_) - snapshot.time()));
}

nlohmann::ordered_json SimServer::LagSummary() const {
  std::vector<double> sorted = lags_;
  std::sort(sorted.begin(), sorted.end());
  const auto at = [&](double q) {
    return sorted.empty() ? 0.0 : sorted[static_cast<std::size_t>(q * (sorted.size() - 1))];
  };
  const double step = world_.spec().physics_step;
  const auto missed = std::count_if(lags_.begin(), lags_.end(), [&](double l) { return l > step; });
  return {{"steps", lags_.size()},      {"p50_s", at(0.5)},
          {"p99_s", at(0.99)},          {"max_s", sorted.empty() ? 0 : sorted.back()},
          {"missed_deadlines", missed}, {"deadline_s", step}};
}

void SimServer::Poll() {
  const double now = world_.Now();
  // The first poll runs as the real-time scheduler starts: simulated time 0 is now.
  if (wall_start_ < 0) {
    wall_start_ = WallNow() - now;
    // The time service's port: the robot protocol's number when UDP has it free.
    time_service_ = std::make_unique<TimeService>(settings_.bind, port_, wall_start_);
  }
  Accept();
  TakeLinesInTurn();
  for (auto& client : clients_) {
    Client& c = *client;
    if (c.fd >= 0 && c.robot) SendSensors(c, now);
    if (c.fd >= 0) Flush(c);
  }
  clients_.erase(std::remove_if(clients_.begin(), clients_.end(), [](const auto& c) { return c->fd < 0; }),
                 clients_.end());
  CloseLingering();
}

void SimServer::Accept() {
  // Bounded, so that a storm of connections cannot hold the poll; the rest wait in the backlog.
  for (std::size_t accepted = 0; accepted < settings_.max_clients; ++accepted) {
    const int fd = AcceptClient(listener_);
    if (fd < 0) return;
    if (clients_.size() >= settings_.max_clients) {
      Refuse(fd);
      continue;
    }
    // A small kernel buffer: what a client leaves unread piles up where the server can see it.
    ::setsockopt(fd, SOL_SOCKET, SO_SNDBUF, &kSendBuffer, sizeof kSendBuffer);
    clients_.push_back(std::make_unique<Client>(fd, settings_.max_line, WallNow()));
    ProtocolMessage hello{"NFO"};
    hello.Add("Gametype", "BotDeathMatch").Add("Level", world_.spec().name).Add("TimeLimit", world_.spec().duration);
    // sanet extension: the machine's monotonic clock (s) at simulated time 0, so that processes
    // on this machine share the simulation's time to the microsecond.
    hello.Add("ClockOrigin", FormatPrecise(wall_start_));
    Send(*clients_.back(), hello);
  }
}

void SimServer::Refuse(int fd) {
  const std::string n = std::to_string(settings_.max_clients);
  const std::string line =
      FormatLine(ProtocolMessage{"ERR"}.Add("Message", "connection refused: the server already has " + n +
                                                           " connections (its cap, --max-clients " + n + ")"));
  ::send(fd, line.data(), line.size(), MSG_NOSIGNAL);
  Linger(fd);
}

// The server stops writing and waits (briefly) for the client to hang up before it closes: closing
// on bytes the client has sent and the server has not read would reset the connection, and the
// client could lose the ERR that says why.
void SimServer::Linger(int fd) {
  ::shutdown(fd, SHUT_WR);
  if (closing_.size() >= settings_.max_clients) {
    ::close(fd);
    return;
  }
  closing_.push_back({fd, WallNow() + kClosingLinger});
}

// What the client still sends is read and thrown away, one turn's bytes per poll at most: one that
// keeps sending is closed at its deadline all the same.
void SimServer::CloseLingering() {
  const double now = WallNow();
  read_buffer_.resize(settings_.bytes_per_turn);
  for (Closing& r : closing_) {
    const ssize_t n = ::recv(r.fd, read_buffer_.data(), read_buffer_.size(), 0);
    const bool hung_up = n == 0 || (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK);
    if (hung_up || now > r.close_by) ::close(r.fd), r.fd = -1;
  }
  closing_.erase(std::remove_if(closing_.begin(), closing_.end(), [](const Closing& r) { return r.fd < 0; }),
                 closing_.end());
}

// Clients take turns, each at most `lines_per_turn` lines and `bytes_per_turn` bytes a turn, for
// as long as the poll's budget lasts; the next poll begins where this one stopped. A client that
// floods the server waits for its own next turn, and its bytes wait in its socket (TCP slows it
// down), so every other client's lines are taken within a few polls however many flood.
void SimServer::TakeLinesInTurn() {
  const double deadline = WallNow() + settings_.poll_budget;
  std::size_t idle = 0;  // clients in a row that had nothing more
  for (std::size_t k = 0; !clients_.empty() && idle < clients_.size(); ++k) {
    if (k > 0 && WallNow() > deadline) break;
    next_turn_ %= clients_.size();
    Client& c = *clients_[next_turn_++];
    const bool more = c.fd >= 0 && TakeLines(c);
    idle = more ? 0 : idle + 1;
  }
}

bool SimServer::TakeLines(Client& c) {
  std::string gone;  // why the connection ended, once the lines it brought are handled
  bool full_read = false;
  if (c.reader.Pending() <= settings_.max_line) {  // never more than a line and a turn's bytes held
    std::vector<char>& buffer = read_buffer_;
    buffer.resize(settings_.bytes_per_turn);
    const ssize_t n = ::recv(c.fd, buffer.data(), buffer.size(), 0);
    if (n == 0) gone = "disconnected";
    if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK) gone = std::strerror(errno);
    if (n > 0) c.reader.Append(std::string_view(buffer.data(), static_cast<std::size_t>(n)));
    full_read = n == static_cast<ssize_t>(buffer.size());
  }
  bool too_long = false;
  std::size_t taken = 0;
  for (; taken < settings_.lines_per_turn; ++taken) {
    const auto line = c.reader.Next(&too_long);
    if (!line) break;
    if (line->find_first_not_of(" \t") == std::string::npos) continue;
    std::string error;
    if (auto m = ParseLine(*line, &error))
      Handle(c, *m);
    else
      Error(c, "malformed line: " + error);
    if (c.fd < 0) return false;
  }
  if (taken > 0) c.last_heard = WallNow();  // once a turn, not for every line
  if (too_long) {
    Error(c, "line longer than " + std::to_string(settings_.max_line) + " bytes: closing");
    Flush(c);
    Drop(c, "line too long");
    return false;
  }
  if (!gone.empty()) {
    if (c.reader.Pending() > 0 && taken == settings_.lines_per_turn) return true;  // its last lines first
    Drop(c, gone);
    return false;
  }
  return full_read || taken == settings_.lines_per_turn;
}

void SimServer::Handle(Client& c, const ProtocolMessage& m) {
  if (m.type == "INIT") return Init(c, m);
  if (m.type == "SANET") return Hello(c, m);
  if (m.type == "GETSCENARIO") return SendScenario(c, m);
  if (m.type == "GETPLUGIN") return SendPlugin(c, m);
  if (m.type == "GETSTARTPOSES") {
    ProtocolMessage reply{"NFO"};
    std::string poses;
    int count = 0;
    for (NodeId id = 0; id < world_.NodeCount(); ++id) {
      const sim::NodeSpec& node = world_.spec().nodes[id];
      if (node.model.kind == robots::ModelKind::kMote || world_.parts().IsSpawned(id)) continue;
      const auto p = ToUsarsim(world_.spec().nodes[id].pose);
      poses += (count++ ? " " : "") + world_.NameOf(id) + " " + FormatNumber(p[0]) + "," + FormatNumber(p[1]) +
               ",0.0000 0.0000,0.0000," + FormatNumber(p[2]);
    }
    reply.Add("StartPoses", std::to_string(count)).Add(poses.empty() ? "None" : poses, "");
    return Send(c, reply);
  }
  if (!c.robot) return Error(c, m.type + " before INIT");
  const NodeId id = *c.robot;
  const auto& spec = world_.spec().nodes[id].model;
  if (m.type == "DRIVE") return Drive(c, m);
  if (m.type == "SEND") return SendMessage(c, m);
  if (m.type == "LOG" || m.type == "TRANSITION" || m.type == "METRIC") return Report(c, m);
  if (m.type == "STATS") return TakeStats(c, m);
  if (m.type == "PEER") return TakePeer(c, m);
  if (m.type == "CLOCK") return TakeClock(c, m);
  if (m.type == "RECV") {
    const std::string* from = m.Get("From");
    std::string error;
    const auto report = ParseRecvLine(m, from ? world_.Lookup(*from) : std::nullopt, id, &error);
    return report ? world_.parts().RecordDelivery(id, report->message) : Error(c, error);
  }
  if (m.type == "GETCONF") {
    ProtocolMessage reply{"CONF"};
    reply.Add("Type", "GroundVehicle")
        .Add("Name", world_.NameOf(id))
        .Add("SteeringType", spec.kind == robots::ModelKind::kOmni3 ? "OmniDrive" : "SkidSteered")
        .Add("MaxSpeed", spec.max_speed)
        .Add("MaxTurnRate", spec.max_turn_rate);
    return Send(c, reply);
  }
  if (m.type == "GETGEO") {
    ProtocolMessage reply{"GEO"};
    const bool omni = spec.kind == robots::ModelKind::kOmni3;
    reply.Add("Type", "GroundVehicle")
        .Add("Name", world_.NameOf(id))
        .Add("WheelRadius", omni ? spec.omni3.wheel_radius : spec.diffdrive.wheel_radius)
        .Add("WheelSeparation", omni ? 2 * spec.omni3.wheel_distance : spec.diffdrive.axle_length);
    return Send(c, reply);
  }
  Error(c, "unknown command " + m.type);
}

// INIT {Name r} claims a robot that is there (the scenario's, or one spawned before); with a
// {ClassName} and a name nobody has, it spawns a new robot, as in USARSim.
void SimServer::Init(Client& c, const ProtocolMessage& m) {
  if (c.robot) return Error(c, "INIT refused: this connection already drives " + world_.NameOf(*c.robot));
  const std::string* name = m.Get("Name");
  const std::string* usarsim_class = m.Get("ClassName");
  if (name)
    if (const auto id = world_.Lookup(*name)) return Claim(c, *id, usarsim_class);
  if (!usarsim_class)
    return Error(c, name ? "INIT refused: no robot named '" + *name + "' in this scenario; INIT {ClassName c} {Name " +
                               *name + "} {Location x,y,z} adds one where the scenario allows it"
                         : "INIT refused: give {Name robot} to claim one of the scenario's robots, or {ClassName c} "
                           "{Location x,y,z} to add one");
  if (m.Get("Start"))
    return Error(c,
                 "INIT refused: {Start tag}: the start poses belong to the scenario's robots; claim one with INIT "
                 "{Name tag}, or give {Location x,y,z} for a new robot");
  Spawn(c, *usarsim_class, name ? *name : "", m);
}

void SimServer::Claim(Client& c, NodeId id, const std::string* usarsim_class) {
  const std::string name = world_.NameOf(id);
  if (world_.spec().nodes[id].model.kind == robots::ModelKind::kMote)
    return Error(c, "INIT refused: the name '" + name + "' is taken by a mote of this scenario");
  if (claimed_[id]) return Error(c, "INIT refused: robot '" + name + "' is already driven by another client");
  const std::string spawned_as = world_.parts().SpawnedAs(id);
  if (usarsim_class && !spawned_as.empty() && !sim::SameClass(*usarsim_class, spawned_as))
    return Error(c, "INIT refused: robot '" + name + "' is a " + spawned_as + ", not a " + *usarsim_class);
  claimed_[id] = true;
  ever_claimed_.resize(world_.NodeCount());
  ever_claimed_[id] = true;
  if (settings_.announce) std::printf("sanet: client %s drives %s\n", c.peer.c_str(), name.c_str());
  c.robot = id;
  c.next_sensors = c.next_status = world_.Now();
  // sanet extension: the run's key for the datagrams agents send each other (hil/agent_datagram.h).
  Send(c, ProtocolMessage{"KEY"}.Add("Datagrams", datagram_key_.Hex()));
  world_.parts().Log(id, "client " + c.peer + " drives this robot");
}

// {Location} and {Rotation} are in USARSim's frame (y right, yaw clockwise); the robot stands
// on the ground, whatever z says.
void SimServer::Spawn(Client& c, const std::string& usarsim_class, const std::string& name, const ProtocolMessage& m) {
  if (!m.Get("Location"))
    return Error(
        c, "INIT refused: {ClassName " + usarsim_class + "} needs {Location x,y,z}: where the new robot stands (m)");
  const auto location = m.Numbers("Location");
  if (!location || location->size() != 3)
    return Error(c, "INIT refused: {Location " + *m.Get("Location") + "}: expected three numbers x,y,z");
  const auto rotation = m.Get("Rotation") ? m.Numbers("Rotation") : std::vector<double>{0, 0, 0};
  if (!rotation || rotation->size() != 3)
    return Error(c, "INIT refused: {Rotation " + *m.Get("Rotation") + "}: expected three numbers r,p,y (rad)");
  const sim::SpawnRequest request{usarsim_class, name, {(*location)[0], -(*location)[1], -(*rotation)[2]}};
  const sim::SpawnPlan plan = sim::PlanSpawn(world_.parts(), request);
  if (!plan.node) return Error(c, "INIT refused: " + plan.refusal);
  const NodeId id =
      world_.parts().Spawn(*plan.node, plan.usarsim_class, "spawned as " + plan.usarsim_class + " by client " + c.peer);
  claimed_.resize(world_.NodeCount(), false);
  Claim(c, id, nullptr);
}

// Through the robot's simulated node, as its controller would drive it: a switched-off robot
// does not move, whoever asks.
void SimServer::Drive(Client& c, const ProtocolMessage& m) {
  agents::SimulatedNode& node = NodeOf(c);
  if (node.switched_off()) {
    if (!c.told_off) Error(c, "robot " + node.Name() + " is switched off: DRIVE ignored");
    c.told_off = true;
    return;
  }
  const auto& spec = world_.spec().nodes[*c.robot].model;
  if (m.Get("Left") || m.Get("Right")) {
    const auto left = m.Number("Left"), right = m.Number("Right");
    if (!left || !right) return Error(c, "DRIVE needs numbers for both {Left} and {Right}");
    double l = *left, r = *right;
    if (const std::string* normalized = m.Get("Normalized");
        normalized && (*normalized == "True" || *normalized == "true")) {
      const double radius =
          spec.kind == robots::ModelKind::kOmni3 ? spec.omni3.wheel_radius : spec.diffdrive.wheel_radius;
      const double top = spec.max_speed / radius;  // rad/s at 100 %
      l = std::clamp(l, -100.0, 100.0) / 100 * top, r = std::clamp(r, -100.0, 100.0) / 100 * top;
    }
    if (spec.kind != robots::ModelKind::kDiffDrive)
      return Error(c, "{Left} {Right} drive a diffdrive; use {LinearVelocity} ... for omni3");
    node.SetWheelSpeeds({l, r});
    return;
  }
  if (m.Get("LinearVelocity") || m.Get("RotationalVelocity") || m.Get("LateralVelocity")) {
    const auto v = m.Number("LinearVelocity"), lateral = m.Number("LateralVelocity"),
               w = m.Number("RotationalVelocity");
    if ((m.Get("LinearVelocity") && !v) || (m.Get("LateralVelocity") && !lateral) ||
        (m.Get("RotationalVelocity") && !w))
      return Error(c, "DRIVE velocities must be numbers");
    node.Drive({v.value_or(0), -lateral.value_or(0), -w.value_or(0)});  // USARSim: y right, yaw clockwise
    return;
  }
  Error(c, "DRIVE needs {Left l} {Right r}, or {LinearVelocity} {LateralVelocity} {RotationalVelocity}");
}

void SimServer::SendSensors(Client& c, double now) {
  robots::NodeModel& model = NodeOf(c).model();
  if (now + 1e-9 >= c.next_sensors) {
    c.next_sensors = now + settings_.sensor_period;
    const std::string time = FormatNumber(now);
    const Pose2D truth = model.GroundTruth();
    ProtocolMessage gt{"SEN"};
    const auto p = ToUsarsim(truth);
    gt.Add("Time", time)
        .Add("Type", "GroundTruth")
        .Add("Name", "GroundTruth")
        .Add("Location", std::vector<double>{p[0], p[1], model.body().position3().z})
        .Add("Orientation", std::vector<double>{0, 0, p[2]});
    Send(c, gt);
    if (auto odometry = model.Odometry()) {
      ProtocolMessage odo{"SEN"};
      odo.Add("Time", time).Add("Type", "Odometry").Add("Name", "Odometry").Add("Pose", ToUsarsim(*odometry));
      Send(c, odo);
    }
    if (auto scan = model.Laser()) {
      ProtocolMessage laser{"SEN"};
      const double resolution = scan->angles.size() > 1 ? scan->angles[1] - scan->angles[0] : 0;
      const double fov = scan->angles.empty() ? 0 : scan->angles.back() - scan->angles.front();
      laser.Add("Time", time)
          .Add("Type", "RangeScanner")
          .Add("Name", "Scanner1")
          .Add("Resolution", resolution)
          .Add("FOV", fov)
          .Add("Range", scan->ranges);
      Send(c, laser);
    }
    if (auto ir = model.Ir()) {
      ProtocolMessage sonar{"SEN"};
      sonar.Add("Time", time).Add("Type", "IR");
      for (std::size_t i = 0; i < ir->ranges.size(); ++i)
        sonar.Add("Name", "IR" + std::to_string(i) + " Range " + FormatNumber(ir->ranges[i]));
      Send(c, sonar);
    }
  }
  if (now + 1e-9 >= c.next_status) {
    c.next_status = now + settings_.status_period;
    ProtocolMessage status{"STA"};
    status.Add("Type", "GroundVehicle")
        .Add("Time", now)
        .Add("FrontSteer", 0.0)
        .Add("RearSteer", 0.0)
        .Add("LightToggle", "False")
        .Add("LightIntensity", "0")
        .Add("Battery", "3600")
        .Add("View", "-1");
    Send(c, status);
  }
}

void SimServer::Send(Client& c, const ProtocolMessage& m) {
  if (c.fd < 0) return;
  c.out += FormatLine(m);
  if (c.out.size() > settings_.max_backlog)
    Drop(c, "not reading (more than " + std::to_string(settings_.max_backlog) + " bytes waiting)");
}

// An ERR line carries no braces, whatever it quotes (a client's own text, a field's name):
// braces would end its {Message ...} field early for a client's parser. A field's name in braces
// becomes quoted ('Left'), a field with its value parenthesised ((ClassName c)), a lone brace '.
std::string WithoutBraces(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const std::size_t close = text[i] == '{' ? text.find_first_of("{}", i + 1) : std::string::npos;
    if (close != std::string::npos && text[close] == '}') {
      const std::string inside = text.substr(i + 1, close - i - 1);
      const bool one_word = inside.find(' ') == std::string::npos;
      out += one_word ? "'" + inside + "'" : "(" + inside + ")";
      i = close;
    } else {
      out += text[i] == '{' || text[i] == '}' ? '\'' : text[i];
    }
  }
  return out;
}

void SimServer::Error(Client& c, const std::string& why) {
  ProtocolMessage error{"ERR"};
  error.Add("Message", WithoutBraces(why));
  Send(c, error);
}

void SimServer::Flush(Client& c) {
  while (c.fd >= 0 && !c.out.empty()) {
    const ssize_t n = ::send(c.fd, c.out.data(), c.out.size(), MSG_NOSIGNAL);
    if (n < 0) {
      if (errno != EAGAIN && errno != EWOULDBLOCK) Drop(c, std::strerror(errno));
      break;
    }
    c.out.erase(0, static_cast<std::size_t>(n));
  }
  if (c.fd >= 0) RecordProgress(c, WallNow());
}

// A client keeps up when nothing waits for it here and its receive window is (nearly) as wide as
// it has ever been or has just widened: it has read what reached it, or some of it. One that
// has not kept up for `stall_timeout` is dropped. TCP gives no earlier sign: until its window narrows, a client that
// stopped reading looks like one that reads (the window narrows as soon as long lines such as laser scans arrive
// unread, only after tens of kilobytes of short ones).
void SimServer::RecordProgress(Client& c, double now) {
  const auto window = PeerReceiveWindow(c.fd);
  bool reads = true;  // without the window's word, a client that takes every byte reads
  if (window) {
    reads = *window + kWindowSlack >= c.widest_window || *window > c.last_window;
    c.widest_window = std::max(c.widest_window, *window);
    c.last_window = *window;
  }
  if (c.out.empty() && reads) c.last_caught_up = now;
  if (now - c.last_caught_up > settings_.stall_timeout)
    Drop(c, "not reading for " + ShortSeconds(settings_.stall_timeout) + " s");
  // An agent reads and writes in one loop: silence tells that it stopped, whatever TCP shows.
  else if (c.agent && now - c.last_heard > settings_.stall_timeout)
    Drop(c, "an agent silent for " + ShortSeconds(settings_.stall_timeout) + " s");
}

void SimServer::Drop(Client& c, const std::string& why) {
  if (c.fd < 0) return;
  Linger(c.fd);
  c.fd = -1;
  if (c.robot) {
    NodeOf(c).Drive({});  // a robot without its client stops
    claimed_[*c.robot] = false;
    world_.parts().Log(*c.robot, "client " + c.peer + " gone (" + why + "): robot stopped");
    if (settings_.announce)
      std::printf("sanet: client %s of %s gone (%s)\n", c.peer.c_str(), world_.NameOf(*c.robot).c_str(), why.c_str());
  }
}

// SEND: the robot's message leaves from its own ns-3 node, like any node's. Values are
// case-sensitive, as node names are.
void SimServer::SendMessage(Client& c, const ProtocolMessage& m) {
  const std::string* delivery = m.Get("Delivery");
  const std::string* data = m.Get("Data");
  const auto kind = ParseDelivery(delivery ? *delivery : "unicast");
  if (!kind) return Error(c, "SEND {Delivery " + *delivery + "}: expected unicast, broadcast or flood");
  if (!data) return Error(c, "SEND needs {Data hex bytes}");
  const auto payload = FromHex(*data);
  if (!payload) return Error(c, "SEND {Data ...}: expected hex bytes (pairs of 0-9, a-f), not '" + *data + "'");
  agents::SimulatedNode& node = NodeOf(c);
  if (node.switched_off()) return Error(c, "robot " + node.Name() + " is switched off: SEND ignored");
  if (*kind == Delivery::kBroadcast) return node.Broadcast(*payload);
  if (*kind == Delivery::kFlood) return node.Flood(*payload);
  const std::string* to = m.Get("To");
  if (!to) return Error(c, "SEND to one node needs {To node}; or give {Delivery broadcast} or {Delivery flood}");
  const auto target = world_.Lookup(*to);
  if (!target) return Error(c, "SEND {To " + *to + "}: no node named '" + *to + "' in this scenario");
  if (*target == node.Id()) return Error(c, "SEND {To " + *to + "}: that is this robot");
  node.Send(*target, *payload);
}

// LOG, TRANSITION and METRIC: the controller's reports, as its node would make them in process.
void SimServer::Report(Client& c, const ProtocolMessage& m) {
  agents::SimulatedNode& node = NodeOf(c);
  const std::string* text = m.Get("Text");
  if (m.type == "LOG") return text && !text->empty() ? node.Log(*text) : Error(c, "LOG needs {Text ...}");
  if (m.type == "METRIC") {
    const std::string* name = m.Get("Name");
    const auto value = m.Number("Value");
    return name && value ? node.Metric(*name, *value) : Error(c, "METRIC needs {Name n} and a number {Value v}");
  }
  const std::string *from = m.Get("From"), *to = m.Get("To"), *why = m.Get("Why");
  if (!from || !to || from->empty() || to->empty())
    return Error(c, "TRANSITION needs {From state} {To state}, both named, and may give {Why ...}");
  node.Transition(*from, *to, why ? *why : "");
}

namespace {

// STATS keys and their names in the results; counts are whole numbers.
struct StatsKey {
  const char* key;
  const char* name;
  bool count;
};
constexpr StatsKey kStatsKeys[] = {{"Steps", "steps", true},
                                   {"Missed", "steps_missed", true},
                                   {"Rate", "achieved_rate_hz", false},
                                   {"Sent", "messages_sent", true},
                                   {"Received", "messages_received", true},
                                   {"DatagramsSent", "datagrams_sent", true},
                                   {"DatagramsReceived", "datagrams_received", true},
                                   {"DatagramsRejected", "datagrams_rejected", true},
                                   {"SendErrors", "send_errors", true},
                                   {"LatenessP50", "lateness_p50_s", false},
                                   {"LatenessP99", "lateness_p99_s", false},
                                   {"LatenessMax", "lateness_max_s", false},
                                   {"ClockOffset", "clock_offset_s", false},
                                   {"ClockError", "clock_error_s", false},
                                   {"ClockErrorMax", "clock_error_max_s", false}};

}  // namespace

// STATS (sanet extension): an agent's steps, messages and packets so far; the last one counts.
void SimServer::TakeStats(Client& c, const ProtocolMessage& m) {
  nlohmann::ordered_json stats = nlohmann::ordered_json::object();
  for (const StatsKey& k : kStatsKeys) {
    constexpr std::uint64_t kMostCount = std::uint64_t{1} << 53;  // whole numbers a double holds exactly
    if (k.count) {
      const auto count = m.Count(k.key, kMostCount);
      if (!count) return Error(c, std::string("STATS needs a whole number from 0 to 2^53 '") + k.key + " ...'");
      stats[k.name] = *count;
    } else {
      const auto value = m.Number(k.key);
      if (!value) return Error(c, std::string("STATS needs a number '") + k.key + " ...'");
      stats[k.name] = *value;
    }
  }
  agent_stats_[world_.NameOf(*c.robot)] = stats;
  c.agent = true;
}

// agents.csv: one row per agent, its last STATS, in node order; clock.csv: their CLOCK lines.
void SimServer::WriteAgentTable(trace::ResultsFolder& folder) const {
  if (!clock_rows_.empty()) {
    trace::CsvSink& clocks = folder.Csv("clock.csv", "time_s,node,offset_s,error_bound_s,round_trip_s,drift_ppm");
    for (const std::string& row : clock_rows_) clocks.Row(row);
  }
  if (agent_stats_.empty()) return;
  std::string header = "node";
  for (const StatsKey& k : kStatsKeys) header += std::string(",") + k.name;
  trace::CsvSink& table = folder.Csv("agents.csv", header);
  for (NodeId id = 0; id < world_.NodeCount(); ++id) {
    const auto it = agent_stats_.find(world_.NameOf(id));
    if (it == agent_stats_.end()) continue;
    std::string row = trace::CsvField(world_.NameOf(id));
    for (const StatsKey& k : kStatsKeys) row += "," + JsonText((*it)[k.name]);
    table.Row(row);
  }
}

std::vector<std::string> SimServer::NeverDriven() const {
  std::vector<std::string> names;
  for (NodeId id = 0; id < world_.spec().nodes.size(); ++id)
    if (sim::RunsAsAgent(world_.spec().nodes[id]) && !(id < ever_claimed_.size() && ever_claimed_[id]))
      names.push_back(world_.NameOf(id));
  return names;
}

SimServer::Client* SimServer::ClientOf(NodeId robot) {
  for (auto& c : clients_)
    if (c->fd >= 0 && c->robot == robot) return c.get();
  return nullptr;
}

// A message reached a client's robot in the simulated network: it goes on to the client. Agents
// hear each other over their own UDP sockets, so the server passes on only what comes from
// nodes that live here.
sim::InboxResult SimServer::Forward(NodeId to, const Message& m) {
  if (world_.spec().robots_remote && sim::RunsAsAgent(world_.spec().nodes[m.from])) return sim::InboxResult::kIgnored;
  Client* c = ClientOf(to);
  if (c) Send(*c, MsgLine(m, world_.NameOf(m.from)));
  return c && c->fd >= 0 ? sim::InboxResult::kDelivered : sim::InboxResult::kLost;
}

}  // namespace sanet::hil
