// Loads a scenario file into a validated RunSpec. Every mistake is a ScenarioError naming the
// file, line and field. The format is documented in docs/scenario.md.
#pragma once

#include <optional>
#include <string>

#include "hosting/controller_registry.h"
#include "scenario/overrides.h"
#include "scenario/yaml_reader.h"
#include "sections/loop_section.h"
#include "sections/ros2_section.h"
#include "sections/spawn_section.h"
#include "sim/run_spec.h"

namespace sanet::scenario {

struct Scenario {
  std::string file;
  sim::RunSpec run;
  // Sections for the front ends, which the simulation never sees.
  sections::LoopSpec loop;                     // how `sanet launch` connects the agents
  std::optional<sections::SpawnSpec> spawn;    // robots the server's clients may add with INIT
  std::optional<sections::Ros2Spec> ros2;      // the ROS 2 face of `sanet serve`
  std::string output_folder;                   // as given, or results/<name>
  std::vector<int> controller_lines;           // per node: line of its controller (0 if none)
  std::vector<std::string> controller_fields;  // per node: its controller's field, "nodes[i].controller"
  std::optional<bool> trace;                   // outputs.trace as given (run.trace is the effective one)
  std::optional<bool> radio_contacts;          // outputs.radio_contacts as given (likewise)
  std::vector<Override> overrides;             // --set, in the order given
  std::vector<std::string> warnings;           // "file:line: 'field': ..." for the command to print
};

// Reads and checks the file with `overrides` (--set) applied (structure, types, ranges, names).
// Does not look at controllers. An error in a value set on the command line names the option.
Scenario LoadScenario(const std::string& path, const std::vector<std::string>& overrides = {});
// Folders where Python controllers' modules are looked for after the scenario's own folder, for
// every scenario loaded from now on (--python-path: an agent whose scenario came from a server).
void SetPythonPath(const std::vector<std::string>& folders);
// The same from text (the effective scenario a server sends); `name` stands for the file in errors
// and relative paths in it are taken from the working folder.
Scenario LoadScenarioText(const std::string& text, const std::string& name);

// Checks that every node's controller exists (loading libraries) and accepts its parameters.
void CheckControllers(const Scenario& scenario, hosting::Registry& registry);

}  // namespace sanet::scenario
