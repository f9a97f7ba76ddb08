// Any bytes as a scenario file: the loader either accepts them or says why with a ScenarioError
// (file, line, field). Anything else escaping it, a crash, a hang or a sanitizer report is a
// finding.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "builtin.h"
#include "hosting/controller_registry.h"
#include "scenario/scenario_loader.h"

namespace {

const std::string& ScenarioPath() {
  static const std::string path = "/tmp/sanet-fuzz-scenario-" + std::to_string(::getpid()) + ".yaml";
  return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static sanet::hosting::Registry registry = [] {
    sanet::hosting::Registry r;
    sanet::controllers::RegisterBuiltinControllers(r);
    return r;
  }();
  std::FILE* file = std::fopen(ScenarioPath().c_str(), "wb");
  if (!file) std::abort();
  std::fwrite(data, 1, size, file);
  std::fclose(file);
  try {
    const sanet::scenario::Scenario scenario = sanet::scenario::LoadScenario(ScenarioPath());
    sanet::scenario::CheckControllers(scenario, registry);
  } catch (const sanet::scenario::ScenarioError&) {
    // the expected answer to a bad file
  } catch (const sanet::hosting::RegistryError&) {
    // a controller library named by the file that cannot be loaded
  }
  return 0;
}
