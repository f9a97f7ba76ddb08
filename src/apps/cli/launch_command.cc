// `sanet launch`: a server and one agent process per robot on this machine (launch/launch.h).
#include "launch_command.h"

#include <filesystem>

#include "launch/launch.h"
#include "net/network_spec.h"
#include "run_common.h"

namespace sanet::cli {
namespace {

struct LaunchArgs {
  std::string file, output, exec_robot;
  std::vector<std::string> sets;
  std::optional<int> udp_base;
  std::optional<double> duration;
  std::vector<std::string> command;
  bool force = false;
  bool view = false;
  std::string test_unreachable;
};

static_assert(kExitRobotsMissing == launch::kExitRobotsMissing, "serve and launch end alike without a robot");

int Launch(const LaunchArgs& a, hosting::Registry& registry) {
  const scenario::Scenario sc = LoadChecked(a.file, a.sets, registry);
  if (!a.command.empty() && a.exec_robot.empty())
    throw CLI::ValidationError("--exec", "a command after -- runs in robots' namespaces: name them with --exec ROBOT");
  if (!a.exec_robot.empty() && a.command.empty())
    throw CLI::ValidationError("--exec", "give the program to run after --, e.g. --exec r1 -- ping 10.0.0.2");
  std::vector<NodeId> exec_robots;
  try {
    if (!a.exec_robot.empty()) exec_robots = launch::ExecRobots(sc.run, sc.ros2.has_value(), a.exec_robot);
  } catch (const std::invalid_argument& e) {
    throw CLI::ValidationError("--exec", e.what());
  }
  const int udp_base = a.udp_base.value_or(sc.loop.udp_port);
  if (sc.loop.network == sections::LoopNetwork::kSimulated && sc.run.network &&
      (udp_base == sc.run.network->port || udp_base == net::kAodvPort || udp_base == net::kOlsrPort ||
       udp_base == net::kDsdvPort))
    throw CLI::ValidationError(
        "--udp-base", std::to_string(udp_base) + " is network.port, which the simulated network serves itself");
  launch::LaunchSettings settings;
  settings.scenario_file = a.file;
  settings.sets = a.sets;
  settings.output = a.output.empty() ? sc.output_folder : a.output;
  settings.force = a.force;
  ClaimFolder(settings.output, a.force);
  settings.loop = sc.loop;
  settings.udp_base = udp_base;
  settings.duration = a.duration;
  settings.ros2_face = sc.ros2.has_value();
  settings.ros2_domain = sc.ros2 ? sc.ros2->domain : -1;
  settings.view = a.view;
  settings.test_unreachable = a.test_unreachable;
  settings.exec_robots = exec_robots;
  settings.exec_command = a.command;
  settings.python_path = {std::filesystem::absolute(a.file).parent_path().string()};
  for (const std::string& folder : PythonPathArgs()) settings.python_path.push_back(folder);
  return launch::Launch(sc.run, settings);
}

}  // namespace

Command AddLaunch(CLI::App& app) {
  auto a = std::make_shared<LaunchArgs>();
  CLI::App* cmd = app.add_subcommand("launch",
                                     "Start a server and one agent process per robot on this machine, run "
                                     "the scenario in real time, stop them all (also on Ctrl-C); exit status 3 "
                                     "when a robot's agent never drove it or ended early (docs/protocol.md)");
  AddScenario(cmd, a->file);
  AddSet(cmd, a->sets);
  AddPythonPath(cmd);
  cmd->add_option("-o,--output", a->output, "Results folder (default: the scenario's)");
  AddDuration(cmd, a->duration);
  cmd->add_option("--udp-base", a->udp_base,
                  "UDP port of node 0 on loopback (default: the scenario's loop.udp_port, 47000; a launch beside "
                  "others moves it by 256 for each slot below its own)")
      ->check(CLI::Range(1024, 60000));
  cmd->add_option("--exec", a->exec_robot,
                  "Run the program given after -- beside the agents, once per robot named (ROBOT,ROBOT... or all: "
                  "robots with controllers and, with a ros2 section, the others too), in its network namespace "
                  "(with loop.namespaces or loop.network: simulated), with SANET_ROBOT and SANET_SERVER set (and, "
                  "over the simulated radio, SANET_RADIO_ADDRESS; with a ros2 section, ROS_DOMAIN_ID); stopped when "
                  "the run ends");
  cmd->add_option("command", a->command, "The program and its arguments for --exec, after --");
  AddForce(cmd, a->force);
  cmd->add_flag("--view", a->view,
                "The server's live page and Foxglove stream (serve --view; it prints where they are); without it "
                "the launch streams nothing");
  cmd->add_option("--test-unreachable", a->test_unreachable,
                  "For tests: give this robot's agent an address where no server listens")
      ->group("");  // for tests: not in --help
  return {cmd, [a](hosting::Registry& r) { return Launch(*a, r); }};
}

}  // namespace sanet::cli
