// A file of the run's trace written by a layer above sim (trace.mcap, by ros2_presentation),
// attached by whoever runs the run (RunOptions::trace_files): made when the run starts if it
// writes a trace, under a temporary name in the results folder, subscribed to the run's events;
// closed before the results are committed.
#pragma once

#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "sim/run_events.h"
#include "sim/run_nodes.h"
#include "sim/run_spec.h"
#include "trace/results_folder.h"

namespace sanet::sim {

class TraceFile {
 public:
  virtual ~TraceFile() = default;
  virtual void Close() = 0;
  // What it adds to summary.json: its wall time under profile_s.trace, and warnings.
  virtual void Report(nlohmann::ordered_json& trace_profile, std::vector<std::string>& warnings) const = 0;
};

struct TraceFileContext {
  const RunSpec& spec;
  const RunNodes& nodes;  // grows while the run goes (robots spawned by front ends)
  RunBus& bus;
  trace::ResultsFolder& folder;
};
using MakeTraceFile = std::function<std::unique_ptr<TraceFile>(const TraceFileContext&)>;

}  // namespace sanet::sim
