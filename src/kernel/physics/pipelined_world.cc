#include "physics/pipelined_world.h"

namespace sanet::physics {

// A body of the engine, read only once the step in flight is done.
class PipelinedWorld::GatedBody : public virtual Body {
 public:
  GatedBody(PipelinedWorld& world, const Body& inner) : world_(world), inner_(inner) {}
  Pose2D pose() const override { return world_.SettleConst(), inner_.pose(); }
  Vec3 position3() const override { return world_.SettleConst(), inner_.position3(); }
  Twist2D velocity() const override { return world_.SettleConst(), inner_.velocity(); }
  bool awake() const override { return world_.SettleConst(), inner_.awake(); }
  const Body& inner() const { return inner_; }

 protected:
  PipelinedWorld& world_;

 private:
  const Body& inner_;
};

// A vehicle of the engine: its motors take commands only between steps.
class PipelinedWorld::GatedVehicle : public GatedBody, public Vehicle {
 public:
  GatedVehicle(PipelinedWorld& world, Vehicle& inner) : GatedBody(world, inner), vehicle_(inner) {}
  std::size_t wheel_count() const override { return vehicle_.wheel_count(); }
  void set_wheel_speed(std::size_t wheel, double rad_per_s) override {
    world_.Settle();
    vehicle_.set_wheel_speed(wheel, rad_per_s);
  }
  double wheel_angle(std::size_t wheel) const override { return world_.SettleConst(), vehicle_.wheel_angle(wheel); }
  DriveTally drive_tally() const override { return world_.SettleConst(), vehicle_.drive_tally(); }

 private:
  Vehicle& vehicle_;
};

PipelinedWorld::PipelinedWorld(std::unique_ptr<PhysicsWorld> engine, bool threaded, std::size_t depth)
    : engine_(std::move(engine)), worker_(threaded, depth) {}

// Steps still queued finish before the engine goes (a run that failed between two waits).
PipelinedWorld::~PipelinedWorld() {
  try {
    Settle();
  } catch (...) {
  }
}

void PipelinedWorld::add_static_box(const StaticBox& box) {
  Settle();
  engine_->add_static_box(box);
}

Vehicle* PipelinedWorld::add_omni3(const Omni3Spec& spec, const Pose2D& pose) {
  Settle();
  return Gate(engine_->add_omni3(spec, pose));
}

Vehicle* PipelinedWorld::add_diffdrive(const DiffDriveSpec& spec, const Pose2D& pose) {
  Settle();
  return Gate(engine_->add_diffdrive(spec, pose));
}

Vehicle* PipelinedWorld::Gate(Vehicle* engine_vehicle) {
  auto vehicle = std::make_unique<GatedVehicle>(*this, *engine_vehicle);
  Vehicle* handle = vehicle.get();
  outer_[engine_vehicle] = handle;
  bodies_.push_back(std::move(vehicle));
  return handle;
}

Body* PipelinedWorld::add_mote(const MoteSpec& spec, const Pose2D& pose) {
  Settle();
  const Body* engine_mote = engine_->add_mote(spec, pose);
  bodies_.push_back(std::make_unique<GatedBody>(*this, *engine_mote));
  outer_[engine_mote] = bodies_.back().get();
  return bodies_.back().get();
}

// Bodies handed out here are gated; the engine knows only its own.
const Body* PipelinedWorld::Inner(const Body* body) const {
  const auto* gated = dynamic_cast<const GatedBody*>(body);
  return gated ? &gated->inner() : body;
}

double PipelinedWorld::cast_ray(const Vec3& origin, const Vec3& direction, double max_range, const Body* ignore) const {
  SettleConst();
  return engine_->cast_ray(origin, direction, max_range, Inner(ignore));
}

std::vector<double> PipelinedWorld::cast_rays(const std::vector<Ray>& rays, double max_range,
                                              const Body* ignore) const {
  SettleConst();
  return engine_->cast_rays(rays, max_range, Inner(ignore));
}

void PipelinedWorld::step(double dt) {
  Settle();
  engine_->step(dt);
}

std::vector<EngineMessage> PipelinedWorld::TakeMessages() {
  std::vector<EngineMessage> messages = engine_->TakeMessages();
  for (EngineMessage& m : messages)
    for (EngineMessage::Contact& c : m.contacts) {
      if (const auto a = outer_.find(c.a); a != outer_.end()) c.a = a->second;
      if (const auto b = outer_.find(c.b); c.b && b != outer_.end()) c.b = b->second;
    }
  return messages;
}

std::size_t PipelinedWorld::awake_body_count() const {
  SettleConst();
  return engine_->awake_body_count();
}

}  // namespace sanet::physics
