#include "run_common.h"

#include <cstdio>
#include <filesystem>

#include "options.h"
#include "trace/earlier_run.h"

namespace sanet::cli {

void PrintWarnings(const std::vector<std::string>& warnings) {
  for (const std::string& w : warnings) std::fprintf(stderr, "sanet: warning: %s\n", w.c_str());
}

sim::Provenance ProvenanceOf(const scenario::EffectiveScenario& effective) {
  return {effective.yaml, effective.fingerprint, CommandLine()};
}

void ClaimFolder(const std::string& dir, bool force) {
  try {
    trace::ClearEarlierRun(dir, force);
  } catch (const trace::FolderRefused& e) {
    throw CLI::ValidationError("--output", e.what());
  } catch (const std::filesystem::filesystem_error& e) {
    throw CLI::ValidationError("--output", "cannot use " + dir + ": " + e.code().message());
  }
}

scenario::Scenario LoadChecked(const std::string& file, const std::vector<std::string>& sets,
                               hosting::Registry& registry) {
  scenario::Scenario sc = scenario::LoadScenario(file, sets);
  scenario::CheckControllers(sc, registry);
  for (const std::string& warning : sc.warnings) std::fprintf(stderr, "sanet: warning: %s\n", warning.c_str());
  return sc;
}

}  // namespace sanet::cli
