// The omni3: a Robertino-like holonomic robot on three omni wheels, with six IR sensors.
#include "robots/node_model.h"

namespace sanet::robots {
namespace {

class Omni3 : public RobotModel {
 public:
  const char* Name() const override { return "omni3"; }
  const char* Summary() const override {
    return "Robertino-like omnidirectional robot with three omni wheels (holonomic), six IR sensors";
  }
  ModelSpec Defaults() const override {
    ModelSpec s;
    s.kind = ModelKind::kOmni3;
    s.max_speed = 1.0;
    s.max_turn_rate = 3.0;
    return s;
  }
  std::vector<std::string> DefaultSensors() const override { return {"ir", "odometry", "ground_truth"}; }
  bool Holonomic() const override { return true; }
  double FootprintRadius(const ModelSpec& s) const override { return s.omni3.body_radius; }
  double InscribedRadius(const ModelSpec& s) const override { return s.omni3.body_radius; }
  double EdgeRadius(const ModelSpec& s) const override { return s.omni3.body_radius; }
  double FrontX(const ModelSpec& s) const override { return s.omni3.body_radius; }
  BodyShape Shape(const ModelSpec& s) const override {
    return {false, 0, 0, s.omni3.body_radius, s.omni3.body_height, s.omni3.ground_clearance};
  }
  std::unique_ptr<Kinematics> MakeKinematics(const ModelSpec& s) const override {
    return std::make_unique<Omni3Kinematics>(s.omni3.wheel_angles, s.omni3.wheel_distance, s.omni3.wheel_radius);
  }
  double WheelRadius(const ModelSpec& s) const override { return s.omni3.wheel_radius; }
  double WheelSeparation(const ModelSpec& s) const override { return 2 * s.omni3.wheel_distance; }
  const char* UsarsimSteering() const override { return "OmniDrive"; }
  physics::Body* Build(physics::PhysicsWorld& world, const ModelSpec& s, const Pose2D& pose,
                       physics::Vehicle** vehicle) const override {
    return *vehicle = world.add_omni3(s.omni3, pose);
  }
};

}  // namespace

const RobotModel& Omni3Model() {
  static const Omni3 model;
  return model;
}

}  // namespace sanet::robots
