#include "sections/spawn_section.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "sensors/sensor_registry.h"

namespace sanet::sections {

bool SameClass(const std::string& a, const std::string& b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

std::vector<SpawnClass> DefaultSpawnClasses() {
  std::vector<SpawnClass> classes;
  for (const char* pioneer : {"USARBot.P2DX", "USARBot.P2AT", "USARBot.P3AT"})
    classes.push_back({pioneer, sensors::DefaultModel(*robots::FindModel("diffdrive")), {}, std::nullopt});
  classes.push_back({"sanet.DiffDrive", sensors::DefaultModel(*robots::FindModel("diffdrive")), {}, std::nullopt});
  classes.push_back({"sanet.Omni3", sensors::DefaultModel(*robots::FindModel("omni3")), {}, std::nullopt});
  return classes;
}

std::pair<Vec2, Vec2> DefaultSpawnRegion(const sim::RunSpec& spec) {
  Vec2 low{HUGE_VAL, HUGE_VAL}, high{-HUGE_VAL, -HUGE_VAL};
  const auto hold = [&](Vec2 p) {
    low = {std::min(low.x, p.x), std::min(low.y, p.y)};
    high = {std::max(high.x, p.x), std::max(high.y, p.y)};
  };
  for (const sim::NodeSpec& n : spec.nodes) hold(n.pose.position());
  for (const sim::Obstacle& o : spec.obstacles) hold({o.box.center.x, o.box.center.y});
  if (low.x > high.x) low = high = {0, 0};
  const Vec2 middle = (low + high) * 0.5, half = spec.world_size * 0.5;
  return {middle - half, middle + half};
}

}  // namespace sanet::sections
