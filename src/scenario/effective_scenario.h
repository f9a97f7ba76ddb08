// The effective scenario: every field of the scenario format with every default filled in
// (controllers' parameters as written: their defaults are the controllers'), as a scenario
// file that loads (and runs) to the same run. Grids appear as their nodes, obstacles
// as boxes, sensors with all their keys. `sanet validate --print` writes it.
#pragma once

#include <string>

#include "scenario/scenario_loader.h"

namespace sanet::scenario {

std::string EffectiveScenarioYaml(const Scenario& scenario);

}  // namespace sanet::scenario
