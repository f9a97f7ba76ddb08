// Whether a client's INIT {ClassName} may add a robot to the running world, as the scenario's
// spawn section allows: a class it lists, a free and safe name, fewer robots added than its
// max, and a place in its region that no obstacle or body takes. The driver adds the robot.
#pragma once

#include <optional>
#include <string>

#include "sections/spawn_section.h"
#include "sim/driver.h"

namespace sanet::robot_server {

struct SpawnRequest {
  std::string usarsim_class;  // e.g. USARBot.P2DX
  std::string name;           // empty: one is made from the class
  Pose2D pose;                // in sanet's frame (z up)
};

// The robot a request adds, or why it is refused (one sentence for the client).
struct SpawnPlan {
  std::optional<sim::NodeSpec> node;
  std::string usarsim_class;  // as the scenario spells it
  std::string refusal;
};

// `spawn` is the scenario's section; without one, no robot may be added.
SpawnPlan PlanSpawn(const sim::Driver& world, const std::optional<sections::SpawnSpec>& spawn,
                    const SpawnRequest& request);

}  // namespace sanet::robot_server
