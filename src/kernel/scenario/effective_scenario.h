// The effective scenario: every field of the scenario format with every default filled in
// (controllers' parameters as written: their defaults are the controllers'), as a scenario
// file that loads (and runs) to the same run. Grids appear as their nodes, obstacles
// as boxes, sensors with all their keys. `sanet validate --print` writes it.
#pragma once

#include <string>

#include "scenario/scenario_loader.h"

namespace sanet::scenario {

struct EffectiveScenario {
  std::string yaml;  // with a first comment line naming the file and the --set given
  // A hash of the effective scenario (16 hex digits, the comment left out): two scenarios with
  // the same fingerprint describe the same run, whatever their files looked like and whatever
  // --set gave.
  std::string fingerprint;
};

// Both at once: printing a scenario of 10 000 nodes takes seconds, so it is printed once.
EffectiveScenario Effective(const Scenario& scenario);

std::string EffectiveScenarioYaml(const Scenario& scenario);
std::string ScenarioFingerprint(const Scenario& scenario);

}  // namespace sanet::scenario
