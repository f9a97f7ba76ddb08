// `sanet launch`: the server and one agent process per robot with a controller, on this machine,
// each agent in its own network namespace where the scenario asks and the machine permits; all
// stopped when the server's run ends or on Ctrl-C (which ends the run with its results).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "sections/loop_section.h"
#include "sim/run_spec.h"

namespace sanet::launch {

struct LaunchSettings {
  std::string scenario_file;
  std::vector<std::string> sets;  // --set, given to the server with the file
  std::string output;             // the results folder
  bool force = false;             // the server writes beside files no sanet run wrote
  sections::LoopSpec loop;        // the scenario's loop section
  int udp_base = 47000;
  int ros2_domain = -1;  // the scenario's ros2.domain; -1: the launch's own (RunSlot::DdsDomain)
  bool view = false;     // the server's live page and Foxglove stream (--view); none otherwise
  // For tests: this robot's agent is given an address where no server listens.
  std::string test_unreachable;
  std::optional<double> duration;  // overrides the scenario's
  // The scenario has a ros2 section: the server's ROS 2 face drives the robots without
  // controllers, which get namespaces (and radio taps) too; the face's DDS uses the bridge.
  bool ros2_face = false;
  // A program to run beside the agents, once in each of these robots' network namespaces when
  // there are namespaces (ended when the run ends).
  std::vector<NodeId> exec_robots;
  std::vector<std::string> exec_command;
  // Where the agents look for Python controllers' modules (they fetch the scenario from the
  // server, so its folder is not theirs): the scenario's folder, then --python-path's.
  std::vector<std::string> python_path;
};

// The robots a launch gives processes of their own, and namespaces where it makes them: those
// with controllers (run as agents) and, with the ROS 2 face on, every other robot too.
std::vector<NodeId> LaunchedRobots(const sim::RunSpec& spec, bool ros2_face);

// --exec WHICH: "all", or robot names separated by commas, each one of LaunchedRobots. Throws
// std::invalid_argument saying which name is not and what the choices are.
std::vector<NodeId> ExecRobots(const sim::RunSpec& spec, bool ros2_face, const std::string& which);

// The exit code of a run that ended without a robot that needed a client (`sanet serve`'s too):
// one never driven, or whose agent ended before the run did.
constexpr int kExitRobotsMissing = 3;

// Runs the launch on a slot of its own (launch/run_slot.h). Returns the exit code: 0 when the run
// completed with every agent's robot driven to the end; the server's code when it failed or was
// interrupted; kExitRobotsMissing when an agent failed the run (summary.json names the robot and
// the cause).
int Launch(const sim::RunSpec& spec, const LaunchSettings& settings);

}  // namespace sanet::launch
