// The diffdrive: a Pioneer-P2DX-like differential drive (two wheels, a passive caster), with a
// 180-degree laser. Its chassis is centred a quarter of the caster offset behind the axle.
#include <algorithm>
#include <cmath>

#include "robots/node_model.h"

namespace sanet::robots {
namespace {

class DiffDrive : public RobotModel {
 public:
  const char* Name() const override { return "diffdrive"; }
  const char* Summary() const override {
    return "Pioneer-P2DX-like differential drive: two wheels and a passive caster, 180-degree laser";
  }
  ModelSpec Defaults() const override {
    ModelSpec s;
    s.kind = ModelKind::kDiffDrive;
    s.max_speed = 1.2;
    s.max_turn_rate = 3.0;
    return s;
  }
  std::vector<std::string> DefaultSensors() const override { return {"laser", "odometry", "ground_truth"}; }
  double FootprintRadius(const ModelSpec& s) const override {
    const auto& d = s.diffdrive;
    return std::hypot(d.body_length / 2, d.body_width / 2) + d.caster_offset / 4;
  }
  double InscribedRadius(const ModelSpec& s) const override {
    const auto& d = s.diffdrive;
    return std::max(0.0, std::min(d.body_width / 2, d.body_length / 2 - d.caster_offset / 4));
  }
  double EdgeRadius(const ModelSpec& s) const override { return s.diffdrive.body_width / 2; }
  double FrontX(const ModelSpec& s) const override {
    return s.diffdrive.body_length / 2 - s.diffdrive.caster_offset / 4 + 0.01;
  }
  BodyShape Shape(const ModelSpec& s) const override {
    const auto& d = s.diffdrive;
    return {true, d.body_length, d.body_width, 0, d.body_height, d.ground_clearance};
  }
  std::unique_ptr<Kinematics> MakeKinematics(const ModelSpec& s) const override {
    return std::make_unique<DiffDriveKinematics>(s.diffdrive.axle_length, s.diffdrive.wheel_radius);
  }
  double WheelRadius(const ModelSpec& s) const override { return s.diffdrive.wheel_radius; }
  double WheelSeparation(const ModelSpec& s) const override { return s.diffdrive.axle_length; }
  const char* UsarsimSteering() const override { return "SkidSteered"; }
  physics::Body* Build(physics::PhysicsWorld& world, const ModelSpec& s, const Pose2D& pose,
                       physics::Vehicle** vehicle) const override {
    return *vehicle = world.add_diffdrive(s.diffdrive, pose);
  }
};

}  // namespace

const RobotModel& DiffDriveModel() {
  static const DiffDrive model;
  return model;
}

}  // namespace sanet::robots
