// The physical world as the rest of sanet sees it: static obstacles, wheeled vehicles, resting
// bodies (motes), ray casts and a fixed-length step. No engine header leaks through here; the
// ODE implementation lives in physics/ode/, the Box2D one in physics/box2d/.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "sanet/geometry.h"

namespace sanet::physics {

struct Vec3 {
  double x = 0, y = 0, z = 0;
};

// Which engine simulates the world: ODE in 3D (wheels, casters and contacts as bodies and
// joints), or Box2D seen from above (robots as single bodies driven at their wheels' contact
// points; for swarms).
enum class Engine { k3d, k2d };

// How contacts and joints are solved each step. `kExact` (a direct LCP solve per island) is
// exact and, for islands as small as one robot, also the faster; `kQuick` (iterative) scales
// better when many bodies touch each other in one island, but does not fully converge: a robot
// standing still creeps by millimetres per second at 20 iterations.
enum class Solver { kExact, kQuick };

struct WorldSettings {
  Engine engine = Engine::k3d;
  double gravity = 9.81;         // m/s^2, pointing down (-z)
  double ground_friction = 1.0;  // Coulomb coefficient for bodies on the ground
  Solver solver = Solver::kExact;
  int solver_iterations = 20;  // iterations of the quick solver per step
};

// An axis-aligned box on the ground, turned by `yaw` about its vertical axis.
struct StaticBox {
  Vec3 center;  // m
  Vec3 size;    // m: length (along yaw), width, height
  double yaw = 0;
};

// The distance from `p` to the box, seen from above (0 inside it).
double DistanceFromAbove(Vec2 p, const StaticBox& box);
// The box's corners seen from above, counter-clockwise (a polygon).
std::array<Vec2, 4> FootprintCorners(const StaticBox& box);

// Robertino-like omnidirectional robot: two stacked cylinders, three sphere wheels on radial
// hinges; anisotropic friction (grip along the rolling direction, slip along the wheel axis)
// stands in for the rollers of a Swedish wheel.
struct Omni3Spec {
  double body_radius = 0.19;             // m, lower cylinder; the upper one is 80 % of it
  double body_height = 0.2;              // m, both cylinders together
  double body_mass = 3.2;                // kg
  std::array<double, 3> body_inertia{};  // kg m², principal moments about the body's centre of mass; 0: its shape's
  double ground_clearance = 0.02;        // m, under the lower cylinder
  double wheel_radius = 0.04;            // m
  double wheel_mass = 0.1;               // kg each
  double wheel_distance = 0.13;          // m, from the centre to each wheel's contact point
  std::array<double, 3> wheel_angles{kPi / 3, kPi, 5 * kPi / 3};  // rad, from forward
  double max_wheel_torque = 0.5;                                  // N m, the motors' limit
  double grip_friction = 1.0;                                     // along the rolling direction
  double slip_friction = 0.01;                                    // along the wheel axis
};

// Pioneer-P2DX-like differential drive: a box chassis, two driven wheels on one axle and a
// passive (frictionless) caster behind.
struct DiffDriveSpec {
  double body_length = 0.44;             // m
  double body_width = 0.38;              // m
  double body_height = 0.22;             // m
  double body_mass = 9.0;                // kg
  std::array<double, 3> body_inertia{};  // kg m², principal moments about the body's centre of mass; 0: its shape's
  double ground_clearance = 0.05;        // m
  double wheel_radius = 0.0975;          // m
  double wheel_mass = 0.5;               // kg each
  double axle_length = 0.33;             // m, between the wheels' contact points
  double caster_offset = 0.2;            // m, behind the axle
  double caster_radius = 0.03;           // m
  double max_wheel_torque = 3.0;         // N m
  double wheel_friction = 1.0;
};

// A sensor mote: a small box that rests until something pushes it.
struct MoteSpec {
  double size = 0.1;   // m, cube side
  double mass = 0.05;  // kg
};

// Handle on a body made of one or more rigid parts (vehicle or mote).
class Body {
 public:
  virtual ~Body() = default;
  // Pose of the body's reference point (a vehicle's centre between its wheels) on the ground.
  virtual Pose2D pose() const = 0;
  virtual Vec3 position3() const = 0;
  // World-frame velocity of the reference point and yaw rate.
  virtual Twist2D velocity() const = 0;
  // True while the engine integrates it (resting motes are not).
  virtual bool awake() const = 0;
};

// What a vehicle's drive has done since it was made, for the energy it cost (the energy layer
// turns it into electrical energy, docs/energy.md#motion).
struct DriveTally {
  // The motors' positive mechanical work: over every step and wheel, the torque the motor
  // applied times the angle its wheel turned against the chassis, where that is positive (a motor
  // that brakes gives nothing back).
  double motor_work_j = 0;
  // Over every step and wheel, the weight the wheel carries times the distance its rim rolled:
  // the rolling resistance's work is its coefficient times this.
  double weight_rolled_j = 0;
};

class Vehicle : public virtual Body {
 public:
  virtual std::size_t wheel_count() const = 0;
  // Speed the wheel's motor drives towards, limited by its maximum torque (rad/s, positive =
  // the direction the kinematics of the model define as forward rolling).
  virtual void set_wheel_speed(std::size_t wheel, double rad_per_s) = 0;
  // Accumulated wheel rotation since creation (rad), unwrapped.
  virtual double wheel_angle(std::size_t wheel) const = 0;
  virtual DriveTally drive_tally() const = 0;
};

// A vehicle's first three wheels' angles (rad, as wheel_angle); zeros for none or no vehicle.
inline std::array<double, 3> WheelAngles(const Vehicle* vehicle) {
  std::array<double, 3> angles{};
  for (std::size_t i = 0; vehicle && i < std::min<std::size_t>(3, vehicle->wheel_count()); ++i)
    angles[i] = vehicle->wheel_angle(i);
  return angles;
}

// A message the engine printed (ODE's "LCP internal error" and the like), kept for the run's
// warnings instead of going to the terminal unexplained.
struct EngineMessage {
  std::string kind;  // the same for every message of one kind (the engine's format)
  std::string text;  // as the engine formatted it
  // What touched what just after the first message of its kind (later ones leave it empty):
  // two bodies, or a body and the static box `obstacle` (in add_static_box order).
  struct Contact {
    const Body* a = nullptr;
    const Body* b = nullptr;  // null: an obstacle
    int obstacle = -1;
  };
  std::vector<Contact> contacts;
};

class PhysicsWorld {
 public:
  virtual ~PhysicsWorld() = default;

  virtual void add_static_box(const StaticBox& box) = 0;
  // The world owns the returned bodies; the pointers stay valid for its lifetime.
  virtual Vehicle* add_omni3(const Omni3Spec& spec, const Pose2D& pose) = 0;
  virtual Vehicle* add_diffdrive(const DiffDriveSpec& spec, const Pose2D& pose) = 0;
  virtual Body* add_mote(const MoteSpec& spec, const Pose2D& pose) = 0;

  // Distance along the ray from `origin` in direction `direction` (unit) to the first surface,
  // ignoring the ground and the parts of `ignore`; `max_range` if nothing is nearer.
  virtual double cast_ray(const Vec3& origin, const Vec3& direction, double max_range, const Body* ignore) const = 0;
  struct Ray {
    Vec3 origin, direction;
  };
  // The rays of one sensor at once, each answered as cast_ray answers it; an engine may find the
  // things near all of them once instead of once per ray.
  virtual std::vector<double> cast_rays(const std::vector<Ray>& rays, double max_range, const Body* ignore) const;

  virtual void step(double dt) = 0;
  virtual std::size_t awake_body_count() const = 0;
  virtual double gravity() const = 0;  // m/s^2, pointing down
  // Returns once no step is under way (a world whose steps may run on another thread waits for
  // them): for state a step updates outside the engine, such as odometry.
  virtual void Settle() {}
  // The engine's messages since the last call (on the thread that steps).
  virtual std::vector<EngineMessage> TakeMessages() { return {}; }
};

std::unique_ptr<PhysicsWorld> CreateOdeWorld(const WorldSettings& settings);
std::unique_ptr<PhysicsWorld> CreateBox2dWorld(const WorldSettings& settings);
// The engine `settings` name.
std::unique_ptr<PhysicsWorld> CreatePhysicsWorld(const WorldSettings& settings);

}  // namespace sanet::physics
