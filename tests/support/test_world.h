// Builders shared by tests: small run specs and a registry with the built-in controllers.
#pragma once

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "builtin.h"
#include "hosting/controller_registry.h"
#include "sensors/sensor_registry.h"
#include "sim/run_spec.h"
#include "sim/world.h"

namespace sanet::testing {

inline ParamValue Scalar(double v) {
  ParamValue p;
  p.rows = {{std::to_string(v)}};
  return p;
}

inline ParamValue Text(const std::string& text) {
  ParamValue p;
  p.rows = {{text}};
  return p;
}

inline ParamValue Table(const std::vector<std::vector<double>>& rows) {
  ParamValue p;
  p.shape = ParamValue::Shape::kTable;
  for (const auto& r : rows) {
    p.rows.emplace_back();
    for (double v : r) p.rows.back().push_back(std::to_string(v));
  }
  return p;
}

inline sim::ControllerSpec UseController(std::string name, std::vector<std::pair<std::string, ParamValue>> params,
                                         double rate = 10) {
  sim::ControllerSpec c;
  c.name = std::move(name);
  c.rate = rate;
  for (auto& [k, v] : params) c.params.Set(k, v);
  return c;
}

inline sim::NodeSpec Robot(std::string name, robots::ModelKind kind, Pose2D pose,
                           std::optional<sim::ControllerSpec> controller = std::nullopt) {
  return {std::move(name), sensors::DefaultModel(kind), pose, std::move(controller), {}, std::nullopt};
}

// The settings of a node's sensor instance, as its kind keeps them (sensors::RangeFan for ir and
// laser, sensors::BearingSettings, ...).
template <typename T>
T& SensorSettings(sim::NodeSpec& node, const std::string& instance) {
  return std::any_cast<T&>(node.model.sensors.at(instance).settings);
}

inline sim::RunSpec Spec(double duration, std::vector<sim::NodeSpec> nodes) {
  sim::RunSpec spec;
  spec.duration = duration;
  spec.nodes = std::move(nodes);
  return spec;
}

// Both physics engines, for tests that every backend must pass (INSTANTIATE_TEST_SUITE_P).
inline const auto kEngines = ::testing::Values(physics::Engine::k3d, physics::Engine::k2d);
inline std::string EngineName(const ::testing::TestParamInfo<physics::Engine>& info) {
  return info.param == physics::Engine::k3d ? "Ode3d" : "Box2d";
}

inline sim::RunSpec On(physics::Engine engine, sim::RunSpec spec) {
  spec.physics.engine = engine;
  return spec;
}

inline sim::Obstacle Wall(Vec2 a, Vec2 b, double height = 1.0, double thickness = 0.2) {
  const Vec2 mid = (a + b) * 0.5;
  sim::Obstacle wall;
  wall.kind = "wall";
  wall.box = {{mid.x, mid.y, height / 2}, {Norm(b - a), thickness, height}, std::atan2(b.y - a.y, b.x - a.x)};
  return wall;
}

inline sim::Obstacle Box(Vec2 center, double lx, double ly, double h, double yaw = 0) {
  sim::Obstacle box;
  box.kind = "box";
  box.box = {{center.x, center.y, h / 2}, {lx, ly, h}, yaw};
  return box;
}

inline hosting::Registry& BuiltinRegistry() {
  static hosting::Registry* registry = [] {
    auto* r = new hosting::Registry;
    controllers::RegisterBuiltinControllers(*r);
    return r;
  }();
  return *registry;
}

// The whole content of a file ("" if it cannot be read).
inline std::string ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Distance from point p to a static box (in the plane), 0 inside.
inline double DistanceToBox(Vec2 p, const physics::StaticBox& box) {
  const Vec2 local = Rotate(p - Vec2{box.center.x, box.center.y}, -box.yaw);
  const double dx = std::max(0.0, std::fabs(local.x) - box.size.x / 2);
  const double dy = std::max(0.0, std::fabs(local.y) - box.size.y / 2);
  return std::hypot(dx, dy);
}

}  // namespace sanet::testing
