// trace.sqlite (trace::RunTrace) from the run's events: the run, its nodes where they start and
// the obstacles first, then pose rows, frames, route changes, messages, transitions, metrics and
// the nodes' events (log lines, switch-offs, spawns, deaths, revivals) and the batteries' samples
// as they happen. docs/trace.md.
#pragma once

#include <memory>
#include <vector>

#include "sim/run_events.h"
#include "sim/run_nodes.h"
#include "sim/run_spec.h"
#include "trace/results_folder.h"
#include "trace/run_trace.h"

namespace sanet::sim {

class SqliteTrace {
 public:
  SqliteTrace(const RunSpec& spec, const RunNodes& nodes, RunBus& bus, trace::ResultsFolder& folder);
  void Close();
  double seconds() const { return seconds_; }  // wall time spent writing it so far

 private:
  void Describe(const RunSpec& spec);
  void Subscribe(RunBus& bus);
  template <typename Event, typename Write>
  void Record(RunBus& bus, Write write);

  const RunNodes& nodes_;
  trace::RunTrace db_;
  std::vector<Subscription> subscriptions_;
  double seconds_ = 0;
};

}  // namespace sanet::sim
