// Outputs::Begin: what made a run, written before anything else into its folder.
#include <nlohmann/json.hpp>

#include "core/host_time.h"
#include "core/json_text.h"
#include "core/version.h"
#include "sim/outputs.h"

namespace sanet::sim {

void Outputs::Begin(const Provenance& p) {
  scenario_fingerprint_ = p.scenario_fingerprint;
  if (!folder_.writes()) return;
  nlohmann::ordered_json j;
  j["sanet_version"] = SanetVersion();
  j["git_commit"] = SanetCommit();
  j["command"] = p.command;
  j["host"] = HostName();
  j["started_utc"] = UtcNow();
  j["scenario_fingerprint"] = p.scenario_fingerprint;
  j["scenario"] = "scenario.yaml";
  folder_.WriteWhole("scenario.yaml", p.effective_scenario);
  folder_.WriteWhole("provenance.json", JsonText(j, 2) + "\n");
}

}  // namespace sanet::sim
