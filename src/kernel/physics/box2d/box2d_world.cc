#include "physics/box2d/box2d_world.h"

#include <algorithm>
#include <cmath>

namespace sanet::physics::box2d {
namespace {

constexpr int kVelocityIterations = 8;  // Box2D's recommended values
constexpr int kPositionIterations = 3;
constexpr float kChassisFriction = 0.3f;  // robots slide along walls rather than stick (as in 3D)

const Body* OwnerOf(b2Body* body) { return reinterpret_cast<const Body*>(body->GetUserData().pointer); }

// The nearest fixture along a ray, skipping those of one body.
class NearestHit : public b2RayCastCallback {
 public:
  explicit NearestHit(const Body* ignore) : ignore_(ignore) {}
  float ReportFixture(b2Fixture* fixture, const b2Vec2&, const b2Vec2&, float fraction) override {
    if (ignore_ && OwnerOf(fixture->GetBody()) == ignore_) return -1;  // as if it were not there
    nearest_ = std::min(nearest_, fraction);
    return fraction;  // only nearer hits matter from now on
  }
  float nearest() const { return nearest_; }

 private:
  const Body* ignore_;
  float nearest_ = 1;
};

// The fixtures whose boxes overlap a region, but those of one body; gives up past `limit`.
class FixturesIn : public b2QueryCallback {
 public:
  FixturesIn(const Body* ignore, std::size_t limit) : ignore_(ignore), limit_(limit) {}
  bool ReportFixture(b2Fixture* fixture) override {
    if (ignore_ && OwnerOf(fixture->GetBody()) == ignore_) return true;
    found_.push_back(fixture);
    return found_.size() <= limit_;
  }
  const std::vector<b2Fixture*>& found() const { return found_; }
  bool too_many() const { return found_.size() > limit_; }

 private:
  const Body* ignore_;
  std::size_t limit_;
  std::vector<b2Fixture*> found_;
};

// A ray along the ground: from the origin, its length max_range times the horizontal part of
// its direction. False for a vertical ray, which meets nothing.
bool FlatRay(const PhysicsWorld::Ray& r, double max_range, b2RayCastInput& input) {
  if (std::hypot(r.direction.x, r.direction.y) < 1e-9 || max_range <= 0) return false;
  input.p1.Set(static_cast<float>(r.origin.x), static_cast<float>(r.origin.y));
  input.p2.Set(static_cast<float>(r.origin.x + r.direction.x * max_range),
               static_cast<float>(r.origin.y + r.direction.y * max_range));
  input.maxFraction = 1;
  return true;
}

}  // namespace

Pose2D Box2dBody::pose() const {
  const b2Vec2 p = body_->GetPosition();
  return {p.x, p.y, body_->GetAngle()};
}

Vec3 Box2dBody::position3() const {
  const b2Vec2 p = body_->GetPosition();
  return {p.x, p.y, height_};
}

Twist2D Box2dBody::velocity() const {
  const b2Vec2 v = body_->GetLinearVelocityFromLocalPoint(b2Vec2(0, 0));
  return {v.x, v.y, body_->GetAngularVelocity()};
}

Box2dWorld::Box2dWorld(const WorldSettings& settings) : settings_(settings), world_(b2Vec2(0, 0)) {
  world_.SetContactListener(this);
}

b2Body* Box2dWorld::MakeBody(b2BodyType type, const Pose2D& pose) {
  b2BodyDef def;
  def.type = type;
  def.position.Set(static_cast<float>(pose.x), static_cast<float>(pose.y));
  def.angle = static_cast<float>(pose.theta);
  return world_.CreateBody(&def);
}

void Box2dWorld::add_static_box(const StaticBox& box) {
  b2Body* body = MakeBody(b2_staticBody, {box.center.x, box.center.y, box.yaw});
  b2PolygonShape shape;
  shape.SetAsBox(static_cast<float>(box.size.x / 2), static_cast<float>(box.size.y / 2));
  b2FixtureDef fixture;
  fixture.shape = &shape;
  fixture.friction = static_cast<float>(settings_.ground_friction);
  body->CreateFixture(&fixture);
}

Body* Box2dWorld::add_mote(const MoteSpec& spec, const Pose2D& pose) {
  b2Body* body = MakeBody(b2_staticBody, pose);
  b2PolygonShape shape;
  shape.SetAsBox(static_cast<float>(spec.size / 2), static_cast<float>(spec.size / 2));
  b2FixtureDef fixture;
  fixture.shape = &shape;
  fixture.friction = 0.5f;
  body->CreateFixture(&fixture);
  motes_.push_back(std::make_unique<Box2dBody>(body, spec.size / 2));
  body->GetUserData().pointer = reinterpret_cast<uintptr_t>(static_cast<const Body*>(motes_.back().get()));
  return motes_.back().get();
}

Vehicle* Box2dWorld::AddVehicle(b2Body* body, double height, std::vector<Wheel> wheels) {
  for (b2Fixture* f = body->GetFixtureList(); f; f = f->GetNext()) f->SetFriction(kChassisFriction);
  vehicles_.push_back(std::make_unique<Box2dVehicle>(body, height, std::move(wheels)));
  body->GetUserData().pointer = reinterpret_cast<uintptr_t>(static_cast<const Body*>(vehicles_.back().get()));
  return vehicles_.back().get();
}

void Box2dWorld::BeginContact(b2Contact* contact) {
  contact->SetFriction(std::min(contact->GetFixtureA()->GetFriction(), contact->GetFixtureB()->GetFriction()));
}

// Rays run in the plane: a ray's length along the ground is its length times the horizontal
// part of its direction; a vertical ray meets nothing (the ground is not a body here).
double Box2dWorld::cast_ray(const Vec3& origin, const Vec3& direction, double max_range, const Body* ignore) const {
  b2RayCastInput input;
  if (!FlatRay({origin, direction}, max_range, input)) return max_range;
  NearestHit hit(ignore);
  world_.RayCast(&hit, input.p1, input.p2);
  return hit.nearest() * max_range;
}

// A sensor's rays usually span a small box with a few things in it: those are found once, and
// each ray is tested against them alone (the fraction a fixture reports does not depend on the
// order in which they are tried, so this is what cast_ray answers). Where the box holds many,
// the rays go through the world's tree one by one.
std::vector<double> Box2dWorld::cast_rays(const std::vector<Ray>& rays, double max_range, const Body* ignore) const {
  constexpr std::size_t kFewFixtures = 16;
  std::vector<b2RayCastInput> inputs(rays.size());
  std::vector<bool> flat(rays.size());
  b2AABB box;
  bool any = false;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    flat[i] = FlatRay(rays[i], max_range, inputs[i]);
    if (!flat[i]) continue;
    const b2Vec2 low = b2Min(inputs[i].p1, inputs[i].p2), high = b2Max(inputs[i].p1, inputs[i].p2);
    box.lowerBound = any ? b2Min(box.lowerBound, low) : low;
    box.upperBound = any ? b2Max(box.upperBound, high) : high;
    any = true;
  }
  FixturesIn near(ignore, kFewFixtures);
  if (any) world_.QueryAABB(&near, box);
  if (near.too_many()) return PhysicsWorld::cast_rays(rays, max_range, ignore);
  std::vector<double> ranges(rays.size(), max_range);
  for (std::size_t i = 0; i < rays.size(); ++i) {
    if (!flat[i]) continue;
    float nearest = 1;
    for (b2Fixture* fixture : near.found()) {
      b2RayCastOutput output;
      if (fixture->RayCast(&output, inputs[i], 0)) nearest = std::min(nearest, output.fraction);
    }
    ranges[i] = nearest * max_range;
  }
  return ranges;
}

void Box2dWorld::step(double dt) {
  for (auto& v : vehicles_)
    if (v->awake()) v->DriveWheels(dt);
  world_.Step(static_cast<float>(dt), kVelocityIterations, kPositionIterations);
  for (auto& v : vehicles_)
    if (v->awake()) v->RollWheels(dt);
}

std::size_t Box2dWorld::awake_body_count() const {
  return static_cast<std::size_t>(
      std::count_if(vehicles_.begin(), vehicles_.end(), [](const auto& v) { return v->awake(); }));
}

}  // namespace sanet::physics::box2d

namespace sanet::physics {

std::unique_ptr<PhysicsWorld> CreateBox2dWorld(const WorldSettings& settings) {
  return std::make_unique<box2d::Box2dWorld>(settings);
}

}  // namespace sanet::physics
