// The omni3's `body` keys.
#include "scenario/declarations.h"

namespace sanet::scenario {

// `m.omni3.body_radius` and the like, as an accessor of the model spec.
#define SANET_OMNI3(key) [](robots::ModelSpec& m) -> double& { return m.omni3.key; }

const Fields<robots::ModelSpec>& Omni3BodyFields() {
  static const Fields<robots::ModelSpec> fields = [] {
    Fields<robots::ModelSpec> f;
    f.Number("body_radius", SANET_OMNI3(body_radius), "m", 0.02, 5,
             "radius of the lower cylinder; the upper cylinder is 80 % of it");
    f.Number("body_height", SANET_OMNI3(body_height), "m", 0.02, 5, "both cylinders together, each half of it");
    f.Number("body_mass", SANET_OMNI3(body_mass), "kg", 0.01, 1000, "");
    BodyInertia(f, [](robots::ModelSpec& m) -> std::array<double, 3>& { return m.omni3.body_inertia; });
    BodyColor(f);
    f.Number("ground_clearance", SANET_OMNI3(ground_clearance), "m", 0, 1, "gap under the lower cylinder");
    f.Number("wheel_radius", SANET_OMNI3(wheel_radius), "m", 0.005, 1, "");
    f.Number("wheel_mass", SANET_OMNI3(wheel_mass), "kg", 0.001, 100, "for each wheel");
    f.Number("wheel_distance", SANET_OMNI3(wheel_distance), "m", 0.01, 5,
             "from the centre to each wheel; must be less than `body_radius + wheel_radius`");
    f.Number("max_wheel_torque", SANET_OMNI3(max_wheel_torque), "N·m", 0.001, 1000, "motor limit");
    f.Number("grip_friction", SANET_OMNI3(grip_friction), "", 0, 10, "friction along each wheel's rolling direction");
    f.Number("slip_friction", SANET_OMNI3(slip_friction), "", 0, 10,
             "friction along each wheel's axle, standing in for the rollers");
    DriveLimits(f, "limit on the magnitude of (`vx`, `vy`) given to `Drive`", "limit on `omega` given to `Drive`");
    return f;
  }();
  return fields;
}

#undef SANET_OMNI3

}  // namespace sanet::scenario
