#include "ros2_agent/ros2_agent.h"

#include <chrono>
#include <cstdio>
#include <thread>

#include "hosting/controller_host.h"
#include "ros2_agent/agent_record.h"
#include "ros2_agent/ros2_node.h"
#include "usarsim_agent/agent_steps.h"
#include "wire/time_service.h"

namespace sanet::ros2_agent {
namespace {

double UnixNow() { return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count(); }

// The Unix time of the agent's time 0 on this computer's clock: the team's start, else now. None
// on /clock (use_sim_time), which every agent reads alike.
std::optional<double> TimeZeroUnix(const Ros2AgentSettings& settings) {
  if (settings.robot.topics.use_sim_time) return std::nullopt;
  return settings.start_at ? *settings.start_at : UnixNow();
}

// The robot's clock: its /clock with use_sim_time, else this computer's (monotonic) from time 0.
std::function<double()> RobotClock(const Ros2Robot& robot, std::optional<double> time_zero_unix) {
  if (!time_zero_unix) return [&robot] { return robot.SimTime().value_or(0); };
  const double origin = wire::MonotonicSeconds() + (*time_zero_unix - UnixNow());
  return [origin] { return wire::MonotonicSeconds() - origin; };
}

// How the run went, for summary.json.
struct Ending {
  std::optional<double> time_zero_unix;
  std::string by = "duration";
  double at = 0;
  std::uint64_t odometry_stops = 0;
  std::vector<std::string> warnings;  // what may be wrong with the robot's topics
};

// Once the controller has run a while, what may be wrong with the robot's topics is said (a
// robot that never moves, a sensor that never speaks), on stderr, in the log and the summary.
void CheckTopics(Ros2Robot& robot, Ros2Node& node, Ending& ending) {
  for (const std::string& trouble : robot.TopicTrouble()) {
    std::fprintf(stderr, "sanet agent %s: warning: %s\n", node.Name().c_str(), trouble.c_str());
    node.Log("warning: " + trouble);
    ending.warnings.push_back(trouble);
  }
}

nlohmann::ordered_json Summary(const sim::RunSpec& spec, NodeId id, const Ros2AgentSettings& settings,
                               const Ending& ending, const usarsim_agent::StepGrid& grid, const Ros2Node& node,
                               const Ros2Robot& robot, const usarsim_agent::PeerSocket& peers) {
  const Ros2Robot::Counts& c = robot.counts();
  const usarsim_agent::PeerSocket::Datagrams& d = peers.datagrams();
  nlohmann::ordered_json j;
  j["scenario"] = spec.name;
  j["robot"] = spec.nodes[id].name;
  j["mode"] = "ros2";
  j["clock"] = settings.robot.topics.use_sim_time ? "/clock (use_sim_time)" : "this computer's";
  if (settings.start_at) j["start_at_unix_s"] = *settings.start_at;
  if (ending.time_zero_unix) j["time_zero_unix_s"] = *ending.time_zero_unix;  // for sanet merge
  j["scenario_fingerprint"] = settings.scenario_fingerprint;
  j["ended_by"] = ending.by;
  j["ended_at_s"] = ending.at;
  j["steps"] = {{"run", grid.run()}, {"missed", grid.missed()}, {"achieved_rate_hz", grid.achieved_rate()}};
  j["messages"] = {{"sent", node.messages_sent()}, {"to_nodes_without_agents", node.messages_to_nowhere()}};
  j["datagrams"] = {
      {"sent", d.sent}, {"received", d.received}, {"rejected", d.rejected}, {"send_errors", d.send_errors}};
  j["ros2"] = {{"odometry", c.odometry}, {"scans", c.scans},
               {"ranges", c.ranges},     {"ground_truth", c.ground_truth},
               {"clock", c.clock},       {"undecodable", c.undecodable},
               {"cmd_vel", c.cmd_vel},   {"odometry_stops", ending.odometry_stops}};
  j["warnings"] = ending.warnings;
  return j;
}

// What is still awaited, for the line said every 10 s while the agent waits.
std::string Awaited(const Ros2Robot& robot, const RobotTopics& t, double clock) {
  std::string text = FullName(t, t.odom) + (robot.Odometry() ? " (here)" : " (nothing yet)");
  if (t.use_sim_time)
    text += " and " + FullName(t, t.clock) + (robot.SimTime() ? " (here)" : " (nothing yet)");
  else if (clock < 0)
    text += ", and the team's start in " + std::to_string(static_cast<long long>(-clock)) + " s";
  return text;
}

// Polls until the robot's first odometry (and /clock with use_sim_time) and the team's start.
// Returns "" when the robot is there, else why the agent ends without driving it.
std::string WaitForTheRobot(Ros2Robot& robot, const Ros2AgentSettings& settings, const std::function<double()>& clock,
                            double duration) {
  const RobotTopics& t = settings.robot.topics;
  double said_at = -1e9;
  for (;;) {
    if (settings.stop_requested && settings.stop_requested()) return "interrupted";
    robot.Poll(wire::MonotonicSeconds());
    const bool has_clock = !t.use_sim_time || robot.SimTime();
    if (has_clock && clock() >= duration)
      return robot.Odometry() ? "the robot's clock was past the run's duration (" + std::to_string(duration) +
                                    " s) when its odometry came: start the agent sooner, or give --duration"
                              : "the robot never came: no odometry on " + FullName(t, t.odom) + " before " +
                                    std::to_string(duration) + " s of the robot's clock";
    if (robot.Odometry() && has_clock && clock() >= 0) return "";
    if (!settings.quiet && wire::MonotonicSeconds() - said_at >= 10) {
      std::printf("sanet agent: waiting for %s\n", Awaited(robot, t, clock()).c_str());
      std::fflush(stdout);
      said_at = wire::MonotonicSeconds();
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

// The robot's motion is stopped while odometry is older than the topics' odom_timeout: a robot
// whose driver or link fails must not go on with its last command. Returns whether steps may run.
class OdometryWatch {
 public:
  OdometryWatch(Ros2Robot& robot, Ros2Node& node, double timeout) : robot_(robot), node_(node), timeout_(timeout) {}
  bool Fresh(double monotonic) {
    const auto at = robot_.OdometryAt();
    const bool fresh = at && monotonic - *at <= timeout_;
    if (!fresh && !stopped_) {
      robot_.Drive({}, node_.ClockNow());
      char why[128];
      std::snprintf(why, sizeof why, "no odometry for %.2g s: the robot is stopped", timeout_);
      std::fprintf(stderr, "sanet agent %s: %s\n", node_.Name().c_str(), why);
      node_.Log(why);
      ++stops_;
    }
    if (fresh && stopped_) {
      std::fprintf(stderr, "sanet agent %s: odometry is back: the controller drives again\n", node_.Name().c_str());
      node_.Log("odometry is back: the controller drives again");
    }
    stopped_ = !fresh;
    return fresh;
  }
  std::uint64_t stops() const { return stops_; }

 private:
  Ros2Robot& robot_;
  Ros2Node& node_;
  double timeout_;
  bool stopped_ = false;
  std::uint64_t stops_ = 0;
};

struct Loop {
  Ros2Robot& robot;
  Ros2Node& node;
  usarsim_agent::PeerSocket& peers;
  hosting::ControllerHost& host;
  usarsim_agent::AgentClock& clock;
  usarsim_agent::StepGrid& grid;
};

// Control steps on the robot's clock until the scenario's duration, a stop or a failure.
void RunSteps(const Loop& l, const sim::RunSpec& spec, const Ros2AgentSettings& settings, Ending& ending) {
  OdometryWatch watch(l.robot, l.node, settings.robot.topics.odom_timeout);
  const auto deliver = [&](const Message& m) { l.host.Receive(m); };
  const double check_at = wire::MonotonicSeconds() + 3;  // DDS has matched, sensors have spoken
  bool checked = false;
  while (l.host.running() && l.node.ClockNow() < spec.duration) {
    if (settings.stop_requested && settings.stop_requested()) {
      ending.by = "interrupted";
      break;
    }
    l.robot.Poll(wire::MonotonicSeconds());
    l.peers.Read(deliver);
    l.clock.RunDue();
    // Steps that fall while odometry is missing are not taken: the grid counts them missed.
    const bool fresh = watch.Fresh(wire::MonotonicSeconds());
    if (const auto t = fresh ? l.grid.Due(l.node.ClockNow()) : std::nullopt) {
      l.node.SetStepTime(*t);
      if (l.grid.run() == 1) l.host.Start();
      l.host.Step();
      l.node.SetStepTime(std::nullopt);
    }
    if (!checked && wire::MonotonicSeconds() >= check_at) {
      CheckTopics(l.robot, l.node, ending);
      checked = true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ending.odometry_stops = watch.stops();
}

}  // namespace

int RunRos2Agent(const sim::RunSpec& spec, NodeId id, const Ros2AgentSettings& settings, hosting::Registry& registry) {
  const sim::ControllerSpec& controller = *spec.nodes.at(id).controller;
  Ros2Robot robot(settings.robot);
  AgentRecord record(settings.output, spec, id, settings.force);
  Ending ending;
  ending.time_zero_unix = TimeZeroUnix(settings);
  const std::function<double()> now = RobotClock(robot, ending.time_zero_unix);
  usarsim_agent::PeerSocket peers(spec, id, settings.peer, now);
  peers.SetKey(settings.key);
  Ros2Node node(spec, id, robot, peers, record, now);
  usarsim_agent::AgentClock clock([&node] { return node.Now(); });
  hosting::ControllerHost::Hooks hooks;
  hooks.failed = [&](const std::string& why) { ending.by = "controller failed: " + why; };
  hooks.delivered = [&](const Message& m) { record.Received(m); };
  registry.StartRun(spec.seed);
  hosting::ControllerHost host(node, hosting::MakeController(controller, registry), controller.rate,
                               {spec.message_loss, spec.message_delay}, spec.seed, clock, hooks);
  usarsim_agent::StepGrid grid(controller.rate);
  if (const std::string missing = WaitForTheRobot(robot, settings, now, spec.duration); missing.empty()) {
    RunSteps({robot, node, peers, host, clock, grid}, spec, settings, ending);
    host.Finish();  // the controller's end of run, into the agent's own record
  } else
    ending.by = missing;
  robot.Drive({}, now());  // whatever ended the run, the robot stops
  ending.at = now();
  record.Finish(Summary(spec, id, settings, ending, grid, node, robot, peers));
  if (!settings.quiet)
    std::printf(
        "sanet agent %s: ended at %.1f s (%s): %llu steps, %llu datagrams sent, %llu received, %llu rejected; "
        "results in %s/\n",
        spec.nodes[id].name.c_str(), ending.at, ending.by.c_str(), static_cast<unsigned long long>(grid.run()),
        static_cast<unsigned long long>(peers.datagrams().sent),
        static_cast<unsigned long long>(peers.datagrams().received),
        static_cast<unsigned long long>(peers.datagrams().rejected), record.dir().c_str());
  if (ending.by.rfind("controller failed", 0) == 0) return 1;
  return ending.by.rfind("the robot", 0) == 0 ? 3 : 0;  // it never drove: 3
}

}  // namespace sanet::ros2_agent
