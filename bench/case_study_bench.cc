// Real-time factor of the case-study scenarios as shipped (no outputs written): the base
// help-request run (1 robot, 25 motes, AODV) and its team variant (12 robots), with the team's
// cost per simulated second as a ratio to the base run's, measured in the same process.
//
//   bench/case_study_bench [scenarios folder, default ./scenarios]
#include <cstdio>
#include <string>

#include "builtin.h"
#include "hosting/controller_registry.h"
#include "scenario/scenario_loader.h"
#include "sim/world.h"

namespace {

struct Measure {
  double simulated, wall, rtf;
  unsigned long long events;
};

Measure Run(const std::string& file, sanet::hosting::Registry& registry) {
  const sanet::scenario::Scenario sc = sanet::scenario::LoadScenario(file);
  sanet::sim::World world(sc.run, registry);
  const sanet::sim::RunResult r = world.Run({});
  return {r.simulated, r.wall, r.real_time_factor, static_cast<unsigned long long>(r.events)};
}

}  // namespace

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : "scenarios";
  sanet::hosting::Registry registry;
  sanet::controllers::RegisterBuiltinControllers(registry);
  std::printf("%-20s %12s %10s %10s %12s %22s\n", "scenario", "simulated s", "wall s", "RTF", "events",
              "wall per sim s vs base");
  const Measure base = Run(dir + "/help-request.yaml", registry);
  std::printf("%-20s %12.1f %10.2f %10.1f %12llu %22.2f\n", "help-request", base.simulated, base.wall, base.rtf,
              base.events, 1.0);
  const Measure team = Run(dir + "/help-request-team.yaml", registry);
  std::printf("%-20s %12.1f %10.2f %10.1f %12llu %22.2f\n", "help-request-team", team.simulated, team.wall, team.rtf,
              team.events, (team.wall / team.simulated) / (base.wall / base.simulated));
  return 0;
}
