// What the run's batteries leave in its results folder: energy.csv (`time,node,remaining_j,power_w`
// at every sample, RunSpec::energy_interval) and the figure energy.svg (the charge over time: each
// node's for a few nodes, the least, mean and most charged for many). It hears EnergySampled on
// the bus; a run without energy writes neither.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/fingerprint.h"
#include "sim/run_events.h"
#include "sim/run_nodes.h"
#include "trace/figures.h"
#include "trace/results_folder.h"

namespace sanet::sim {

class EnergyOutputs {
 public:
  EnergyOutputs(const RunNodes& nodes, RunBus& bus, trace::ResultsFolder& folder);
  void Stop() { subscription_ = {}; }
  void AddTo(Fingerprint& fp) const;
  // energy.svg's text; empty when nothing was sampled.
  std::optional<std::string> Figure(const std::string& run_name) const;

 private:
  static constexpr std::size_t kNodesDrawnApart = 8;
  void Sampled(const EnergySampled& e);

  const RunNodes& nodes_;
  trace::ResultsFolder& folder_;
  Subscription subscription_;
  trace::CsvSink* csv_ = nullptr;
  bool apart_ = true;
  std::vector<trace::Series> series_;  // charge in % over time: per node, or least, mean and most
};

}  // namespace sanet::sim
