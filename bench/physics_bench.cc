// Physics speed: physics steps per second and real-time factor of whole runs (ns-3 clock,
// controllers, recording) for 1, 10 and 100 omni3 robots and for 25 motes. Absolute times drift
// on a shared machine, so every case is also given as a ratio to a baseline measured in the same
// run: the empty world for motes (motes at rest should cost nothing), one robot for robots (cost
// per robot should stay flat; one robot among 25 motes should cost what one robot alone does),
// and the exact solver for the quick one. Last, the two engines at swarm scale: the physics
// stage alone (profile_s.physics) per robot-step for 1,000 diffdrive robots on the 2D engine
// (Box2D) against the 3D one (ODE).
//
//   bench/physics_bench [simulated seconds per case, default 20]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "builtin.h"
#include "hosting/controller_registry.h"
#include "sensors/sensor_registry.h"
#include "sim/world.h"

namespace {

using namespace sanet;

struct Measure {
  double wall, steps_per_s, rtf;
};

sim::RunSpec Robots(int count, double duration, physics::Solver solver,
                    robots::ModelKind kind = robots::ModelKind::kOmni3, physics::Engine engine = physics::Engine::k3d) {
  sim::RunSpec spec;
  spec.duration = duration;
  spec.physics.solver = solver;
  spec.physics.engine = engine;
  const int side = static_cast<int>(std::ceil(std::sqrt(count)));
  for (int i = 0; i < count; ++i) {
    sim::NodeSpec n{"r" + std::to_string(i),
                    sensors::DefaultModel(kind),
                    {3.0 * (i % side), 3.0 * (i / side), 0},
                    sim::ControllerSpec{},
                    {},
                    std::nullopt};
    n.controller->name = "constant_velocity";  // a 1 m circle: the robots keep driving, apart
    ParamValue vx, omega;
    vx.rows = {{"0.3"}};
    omega.rows = {{"0.3"}};
    n.controller->params.Set("vx", vx);
    n.controller->params.Set("omega", omega);
    spec.nodes.push_back(n);
  }
  return spec;
}

sim::RunSpec Motes(int count, double duration) {
  sim::RunSpec spec;
  spec.duration = duration;
  for (int i = 0; i < count; ++i)
    spec.nodes.push_back({"m" + std::to_string(i),
                          sensors::DefaultModel(robots::ModelKind::kMote),
                          {10.0 * (i % 20), 10.0 * (i / 20), 0},
                          std::nullopt,
                          {},
                          std::nullopt});
  return spec;
}

Measure Time(const sim::RunSpec& spec, hosting::Registry& registry) {
  sim::World world(spec, registry);
  const sim::RunResult r = world.Run({});
  return {r.wall, r.physics_steps / r.wall, r.real_time_factor};
}

void Row(const char* name, const Measure& m, const char* baseline, double ratio) {
  std::printf("%-24s %8.3f %12.0f %10.1f   %-22s %6.2f\n", name, m.wall, m.steps_per_s, m.rtf, baseline, ratio);
}

}  // namespace

int main(int argc, char** argv) {
  const double duration = argc > 1 ? std::atof(argv[1]) : 20;
  hosting::Registry registry;
  controllers::RegisterBuiltinControllers(registry);
  std::printf("sanet physics benchmark: %.0f s simulated per case, physics step 5 ms\n", duration);
  std::printf("%-24s %8s %12s %10s   %-22s %6s\n", "case", "wall s", "steps/s", "RTF", "ratio against", "ratio");

  const Measure motes = Time(Motes(25, duration), registry);
  Row("25 motes", motes, "-", 1.0);
  const Measure one = Time(Robots(1, duration, physics::Solver::kExact), registry);
  Row("1 omni3", one, "-", 1.0);
  for (int motes : {25, 400}) {
    sim::RunSpec among = Motes(motes, duration);
    among.nodes.push_back(Robots(1, duration, physics::Solver::kExact).nodes[0]);
    among.nodes.back().pose = {5, 5, 0};  // between the motes, touching none
    const Measure m = Time(among, registry);
    const std::string name = "1 omni3 + " + std::to_string(motes) + " motes";
    Row(name.c_str(), m, "wall of 1 omni3", m.wall / one.wall);
  }
  for (int n : {10, 100}) {
    const Measure m = Time(Robots(n, duration, physics::Solver::kExact), registry);
    const std::string name = std::to_string(n) + " omni3";
    Row(name.c_str(), m, "per-robot wall of 1", m.wall / n / one.wall);
  }
  const Measure exact100 = Time(Robots(100, duration / 4, physics::Solver::kExact), registry);
  const Measure quick100 = Time(Robots(100, duration / 4, physics::Solver::kQuick), registry);
  Row("100 omni3, quick solver", quick100, "wall of exact solver", quick100.wall / exact100.wall);

  std::printf("\nphysics stage alone, 1000 diffdrive robots (%.1f s simulated each)\n", duration / 10);
  std::printf("%-24s %14s %20s\n", "engine", "physics wall s", "us per robot-step");
  double per_robot_step[2];
  for (physics::Engine engine : {physics::Engine::k3d, physics::Engine::k2d}) {
    sim::World world(Robots(1000, duration / 10, physics::Solver::kExact, robots::ModelKind::kDiffDrive, engine),
                     registry);
    const sim::RunResult r = world.Run({});
    const int i = engine == physics::Engine::k2d;
    per_robot_step[i] = r.profile.physics / (1000.0 * r.physics_steps) * 1e6;
    std::printf("%-24s %14.3f %20.2f\n", i ? "2d (Box2D)" : "3d (ODE)", r.profile.physics, per_robot_step[i]);
  }
  std::printf("2d / 3d cost per robot-step: %.3f\n", per_robot_step[1] / per_robot_step[0]);
  return 0;
}
