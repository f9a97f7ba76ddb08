// The diffdrive's `body` keys.
#include "scenario/declarations.h"

namespace sanet::scenario {

// `m.diffdrive.body_length` and the like, as an accessor of the model spec.
#define SANET_DIFFDRIVE(key) [](robots::ModelSpec& m) -> double& { return m.diffdrive.key; }

const Fields<robots::ModelSpec>& DiffDriveBodyFields() {
  static const Fields<robots::ModelSpec> fields = [] {
    Fields<robots::ModelSpec> f;
    f.Number("body_length", SANET_DIFFDRIVE(body_length), "m", 0.02, 10, "box chassis, along x");
    f.Number("body_width", SANET_DIFFDRIVE(body_width), "m", 0.02, 10, "along y");
    f.Number("body_height", SANET_DIFFDRIVE(body_height), "m", 0.02, 10, "");
    f.Number("body_mass", SANET_DIFFDRIVE(body_mass), "kg", 0.01, 10000, "");
    BodyInertia(f, [](robots::ModelSpec& m) -> std::array<double, 3>& { return m.diffdrive.body_inertia; });
    BodyColor(f);
    f.Number("ground_clearance", SANET_DIFFDRIVE(ground_clearance), "m", 0, 1, "gap under the chassis");
    f.Number("wheel_radius", SANET_DIFFDRIVE(wheel_radius), "m", 0.005, 2, "");
    f.Number("wheel_mass", SANET_DIFFDRIVE(wheel_mass), "kg", 0.001, 100, "for each wheel");
    f.Number("axle_length", SANET_DIFFDRIVE(axle_length), "m", 0.02, 10, "between the two wheels' contact points");
    f.Number("caster_offset", SANET_DIFFDRIVE(caster_offset), "m", 0.01, 10, "how far the caster sits behind the axle");
    f.Number("caster_radius", SANET_DIFFDRIVE(caster_radius), "m", 0.005, 1, "frictionless caster");
    f.Number("max_wheel_torque", SANET_DIFFDRIVE(max_wheel_torque), "N·m", 0.001, 10000, "motor limit");
    f.Number("wheel_friction", SANET_DIFFDRIVE(wheel_friction), "", 0, 10, "");
    DriveLimits(f, "limit on `vx` given to `Drive`", "limit on `omega` given to `Drive`");
    return f;
  }();
  return fields;
}

#undef SANET_DIFFDRIVE

}  // namespace sanet::scenario
