// ODE implementation of PhysicsWorld. Internal to physics/: nothing outside includes it.
//
// Geoms live in three spaces so that things at rest cost nothing: `moving_` (vehicles), `still_`
// (the ground and static obstacles) and `resting_` (motes, dynamic bodies created disabled). Each
// step collides moving against everything and a mote against the world only while it is awake.
#pragma once

#include <ode/ode.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <set>
#include <unordered_map>
#include <vector>

#include "physics/physics_world.h"

namespace sanet::physics::ode {

constexpr double kChassisFriction = 0.3;  // robots slide along walls rather than stick
constexpr double kMoteFriction = 0.5;

enum class Part { kGround, kStatic, kChassis, kDriveWheel, kOmniWheel, kCaster, kMote };

class OdeBody;

// What a geom is, read in the collision callback (stored as the geom's user data).
struct GeomInfo {
  Part part = Part::kStatic;
  const Body* owner = nullptr;  // null for ground and static obstacles
  dJointID hinge = nullptr;     // omni wheels: the hinge whose axis slips
  double friction = 1.0;        // mu (grip direction for omni wheels)
  double slip_friction = 0.0;   // omni wheels: mu2 along the axis
  int index = -1;               // motes: index into the world's mote lists; static boxes: their number
};

class OdeWorld;

class OdeBody : public virtual Body {
 public:
  OdeBody(dBodyID main, Vec3 reference_offset) : main_(main), reference_offset_(reference_offset) {}
  Pose2D pose() const override;
  Vec3 position3() const override;
  Twist2D velocity() const override;
  bool awake() const override { return dBodyIsEnabled(main_) != 0; }
  dBodyID main() const { return main_; }

 protected:
  dBodyID main_;
  Vec3 reference_offset_;  // body frame: from the centre of mass to the reference point
};

// A mote is a static box (a geom without a body) until something moving touches it; then it
// gets a body, and loses it again once it has come to rest. At rest it costs the solver nothing.
class OdeMote : public Body {
 public:
  OdeMote(dGeomID geom, const MoteSpec& spec) : geom_(geom), spec_(spec) {}
  Pose2D pose() const override;
  Vec3 position3() const override;
  Twist2D velocity() const override;
  bool awake() const override { return body_ && dBodyIsEnabled(body_); }
  bool has_body() const { return body_ != nullptr; }
  void Wake(dWorldID world);  // gives it a body where it stands
  void Rest();                // a static box again, where the body came to rest

 private:
  dGeomID geom_;
  MoteSpec spec_;
  dBodyID body_ = nullptr;
};

class OdeVehicle : public OdeBody, public Vehicle {
 public:
  struct Wheel {
    dBodyID body;
    dJointID hinge;
    double radius = 0;
    double angle = 0;     // unwrapped
    double last_raw = 0;  // hinge angle at the previous step, in (-pi, pi]
    // Where ODE writes the forces the hinge applied in a step (its address must not move).
    std::unique_ptr<dJointFeedback> feedback = std::make_unique<dJointFeedback>();
  };
  OdeVehicle(dBodyID chassis, Vec3 reference_offset) : OdeBody(chassis, reference_offset) {}
  std::size_t wheel_count() const override { return wheels_.size(); }
  void set_wheel_speed(std::size_t wheel, double rad_per_s) override;
  double wheel_angle(std::size_t wheel) const override { return wheels_.at(wheel).angle; }
  DriveTally drive_tally() const override { return tally_; }
  // `weight_n`: the wheel's share of the robot's weight.
  void add_wheel(dBodyID body, dJointID hinge, double max_torque, double radius, double weight_n);
  // After each step: the wheels' angles, and what their motors did (DriveTally).
  void update_wheels();

 private:
  std::vector<Wheel> wheels_;
  std::vector<double> weights_n_;
  DriveTally tally_;
};

class OdeWorld : public PhysicsWorld {
 public:
  explicit OdeWorld(const WorldSettings& settings);
  ~OdeWorld() override;

  void add_static_box(const StaticBox& box) override;
  Vehicle* add_omni3(const Omni3Spec& spec, const Pose2D& pose) override;
  Vehicle* add_diffdrive(const DiffDriveSpec& spec, const Pose2D& pose) override;
  Body* add_mote(const MoteSpec& spec, const Pose2D& pose) override;
  double cast_ray(const Vec3& origin, const Vec3& direction, double max_range, const Body* ignore) const override;
  void step(double dt) override;
  std::size_t awake_body_count() const override;
  double gravity() const override { return settings_.gravity; }
  std::vector<EngineMessage> TakeMessages() override;

  // Used by the vehicle builders.
  dWorldID world() const { return world_; }
  dSpaceID moving_space() const { return moving_; }
  GeomInfo* make_info(GeomInfo info);

 private:
  static void NearCallback(void* data, dGeomID a, dGeomID b);
  void Collide(dGeomID a, dGeomID b);
  void WakeMote(int index);
  static std::int64_t CellOf(double x, double y);
  static std::int64_t CellKey(std::int64_t cx, std::int64_t cy);
  void PlaceInGrid(int mote);
  void CollideWithMotes(dGeomID geom, int self);
  void List(const GeomInfo& a, const GeomInfo& b);
  std::vector<EngineMessage::Contact> ContactsNow();

  WorldSettings settings_;
  dWorldID world_;
  dThreadingImplementationID threading_;
  dSpaceID moving_, still_, resting_;
  dJointGroupID contacts_;
  std::vector<std::unique_ptr<GeomInfo>> infos_;
  std::vector<std::unique_ptr<OdeVehicle>> vehicles_;
  std::vector<std::unique_ptr<OdeMote>> motes_;
  std::vector<dGeomID> mote_geoms_;
  // Motes are found through a grid of square cells (by their centre) rather than a space, whose
  // queries cost as much as it holds: a robot then costs the same among 4 motes or 4000.
  static constexpr double kMoteCell = 1.0;                        // m
  std::unordered_map<std::int64_t, std::vector<int>> mote_grid_;  // cell -> motes, sorted
  std::vector<std::optional<std::int64_t>> mote_cell_;
  double max_mote_reach_ = 0;      // m, from a mote's centre to its farthest corner
  std::vector<char> mote_done_;    // per mote: its pass ran in this step
  std::vector<char> mote_awake_;   // per mote: listed in awake_motes_
  std::vector<int> awake_motes_;   // motes awake or touched this step, in the order they woke
  mutable dGeomID ray_ = nullptr;  // reused by cast_ray, in no space
  int static_boxes_ = 0;
  bool listing_ = false;  // Collide lists the pairs that touch instead of joining them
  std::vector<EngineMessage::Contact> listed_;
  std::set<std::string> kinds_seen_;  // of the engine's messages
};

}  // namespace sanet::physics::ode
