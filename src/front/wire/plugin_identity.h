// Which controller code a robot runs: the plugin library (.so) its scenario names, or the Python
// module, by its SHA-256, and the controller interface version (include/sanet/plugin.h). A server and an agent
// on another computer compare theirs before the agent drives the robot: the same scenario run by
// different code is not the same experiment.
#pragma once

#include <string>

#include "sim/run_spec.h"

namespace sanet::wire {

struct PluginIdentity {
  std::string library;  // path; empty for a controller built into sanet
  std::string sha256;   // of the library file, hex; empty without one
  int controller_api = 0;
  // A Python controller: MODULE:CLASS, and in `library` and `sha256` its module's file as found
  // on the spec's python_path (none when it comes from elsewhere, e.g. PYTHONPATH).
  std::string python;
};

// Throws std::runtime_error when the library cannot be read.
PluginIdentity IdentifyPlugin(const sim::ControllerSpec& controller);

// Empty when they match; else what differs, naming both sides' values.
std::string PluginDifference(const PluginIdentity& server, const PluginIdentity& agent);

}  // namespace sanet::wire
