// Outputs::Begin: what made a run, written before anything else into its folder.
#include <unistd.h>

#include <array>
#include <ctime>
#include <nlohmann/json.hpp>

#include "core/json_text.h"
#include "core/version.h"
#include "sim/outputs.h"

namespace sanet::sim {
namespace {

std::string HostName() {
  std::array<char, 256> name{};
  if (::gethostname(name.data(), name.size() - 1) != 0) return "unknown";
  return name.data();
}

std::string UtcNow() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  ::gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

}  // namespace

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
