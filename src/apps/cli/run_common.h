// What `sanet run`, `serve` and `launch` share: loading a scenario with its controllers checked,
// claiming the results folder, the provenance and the printing of warnings.
#pragma once

#include <string>
#include <vector>

#include "hosting/controller_registry.h"
#include "scenario/effective_scenario.h"
#include "scenario/scenario_loader.h"
#include "sim/world.h"

namespace sanet::cli {

// The scenario with --set applied and its controllers found; its warnings printed.
scenario::Scenario LoadChecked(const std::string& file, const std::vector<std::string>& sets,
                               hosting::Registry& registry);
// Before anything is built: the folder must be free for the run (trace/earlier_run.h).
void ClaimFolder(const std::string& dir, bool force);
sim::Provenance ProvenanceOf(const scenario::EffectiveScenario& effective);
// What the run's reader should know although nothing failed (also in summary.json).
void PrintWarnings(const std::vector<std::string>& warnings);

}  // namespace sanet::cli
