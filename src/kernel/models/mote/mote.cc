// The mote: a small cube that rests until something pushes it; no drive.
#include <cmath>

#include "robots/node_model.h"

namespace sanet::robots {
namespace {

class Mote : public RobotModel {
 public:
  const char* Name() const override { return "mote"; }
  const char* Summary() const override {
    return "a sensor mote: a cube that rests until something pushes it; no drive";
  }
  ModelSpec Defaults() const override {
    ModelSpec s;
    s.kind = ModelKind::kMote;
    return s;
  }
  std::vector<std::string> DefaultSensors() const override { return {"ground_truth"}; }
  bool HasDrive() const override { return false; }
  double FootprintRadius(const ModelSpec& s) const override { return s.mote.size * std::sqrt(0.5); }
  double InscribedRadius(const ModelSpec& s) const override { return s.mote.size / 2; }
  double EdgeRadius(const ModelSpec& s) const override { return s.mote.size / 2; }
  double FrontX(const ModelSpec& s) const override { return s.mote.size / 2; }
  BodyShape Shape(const ModelSpec& s) const override { return {true, s.mote.size, s.mote.size, 0, s.mote.size, 0}; }
  physics::Body* Build(physics::PhysicsWorld& world, const ModelSpec& s, const Pose2D& pose,
                       physics::Vehicle** vehicle) const override {
    *vehicle = nullptr;
    return world.add_mote(s.mote, pose);
  }
};

}  // namespace

const RobotModel& MoteModel() {
  static const Mote model;
  return model;
}

}  // namespace sanet::robots
