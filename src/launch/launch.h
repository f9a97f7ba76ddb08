// `sanet launch`: the server and one agent process per robot with a controller, on this machine,
// each agent in its own network namespace where the scenario asks and the machine permits; all
// stopped when the server's run ends or on Ctrl-C (which ends the run with its results).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "sections/loop_section.h"
#include "sim/run_spec.h"

namespace sanet::hil {

struct LaunchSettings {
  std::string scenario_file;
  std::vector<std::string> sets;  // --set, given to the server with the file
  std::string output;             // the results folder
  bool force = false;             // the server writes beside files no sanet run wrote
  sections::LoopSpec loop;        // the scenario's loop section
  int udp_base = 47000;
  std::optional<double> duration;  // overrides the scenario's
  // A program to run beside the agents, in `exec_robot`'s network namespace when there is one
  // (ended when the run ends).
  std::string exec_robot;
  std::vector<std::string> exec_command;
};

// Returns the server's exit code.
int Launch(const sim::RunSpec& spec, const LaunchSettings& settings);

}  // namespace sanet::hil
