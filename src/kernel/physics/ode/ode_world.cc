#include "physics/ode/ode_world.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <limits>
#include <mutex>

namespace sanet::physics {

std::unique_ptr<PhysicsWorld> CreateOdeWorld(const WorldSettings& settings) {
  return std::make_unique<ode::OdeWorld>(settings);
}

namespace ode {
namespace {

constexpr int kMaxContactsPerPair = 4;

// ODE prints its messages (dMessage: "LCP internal error" when bodies start inside each other)
// to stderr from whichever thread steps; they are kept here, process-wide as ODE's handler is,
// until the world that steps takes them.
std::mutex g_messages_mutex;
std::vector<std::pair<std::string, std::string>> g_messages;  // (format, text)

void KeepMessage(int number, const char* format, va_list args) {
  char text[512];
  std::vsnprintf(text, sizeof text, format, args);
  const std::lock_guard<std::mutex> lock(g_messages_mutex);
  if (g_messages.size() < 10000) g_messages.emplace_back(format, "ODE message " + std::to_string(number) + ": " + text);
}

void InitOdeOnce() {
  static std::once_flag once;
  std::call_once(once, [] {
    dInitODE2(0);
    dSetMessageHandler(&KeepMessage);
  });
}

// ODE keeps data per thread for collision detection: a thread that steps or casts rays (the
// physics thread of a run with two) needs its own.
void PrepareThread() {
  thread_local bool prepared = false;
  if (!prepared) prepared = dAllocateODEDataForThread(dAllocateMaskAll) != 0;
}

const GeomInfo& InfoOf(dGeomID g) { return *static_cast<const GeomInfo*>(dGeomGetData(g)); }

bool Moving(dBodyID body) { return body && dBodyIsEnabled(body); }

}  // namespace

// ---- bodies ------------------------------------------------------------------------------

Pose2D OdeBody::pose() const {
  const Vec3 p = position3();
  const dReal* r = dBodyGetRotation(main_);
  return {p.x, p.y, std::atan2(r[4], r[0])};
}

Vec3 OdeBody::position3() const {
  dVector3 world;
  dBodyGetRelPointPos(main_, reference_offset_.x, reference_offset_.y, reference_offset_.z, world);
  return {world[0], world[1], world[2]};
}

Twist2D OdeBody::velocity() const {
  dVector3 v;
  dBodyGetRelPointVel(main_, reference_offset_.x, reference_offset_.y, reference_offset_.z, v);
  return {v[0], v[1], dBodyGetAngularVel(main_)[2]};
}

void OdeVehicle::set_wheel_speed(std::size_t wheel, double rad_per_s) {
  dJointSetHingeParam(wheels_.at(wheel).hinge, dParamVel, rad_per_s);
}

void OdeVehicle::add_wheel(dBodyID body, dJointID hinge, double max_torque, double radius, double weight_n) {
  dJointSetHingeParam(hinge, dParamFMax, max_torque);
  dJointSetHingeParam(hinge, dParamVel, 0);
  Wheel& w = wheels_.emplace_back();
  w.body = body, w.hinge = hinge, w.radius = radius, w.last_raw = dJointGetHingeAngle(hinge);
  dJointSetFeedback(hinge, w.feedback.get());
  weights_n_.push_back(weight_n);
}

// The hinge's anchor is the wheel's centre and its other constraints act across the axis, so the
// torque it applied to the wheel along the axis is the motor's alone.
void OdeVehicle::update_wheels() {
  for (std::size_t i = 0; i < wheels_.size(); ++i) {
    Wheel& w = wheels_[i];
    const double raw = dJointGetHingeAngle(w.hinge);
    const double turn = WrapAngle(raw - w.last_raw);
    w.angle += turn;
    w.last_raw = raw;
    dVector3 axis;
    dJointGetHingeAxis(w.hinge, axis);
    const dReal* t = w.feedback->t1;  // on body 1, the wheel
    const double torque = t[0] * axis[0] + t[1] * axis[1] + t[2] * axis[2];
    tally_.motor_work_j += std::max(0.0, torque * turn);
    tally_.weight_rolled_j += weights_n_[i] * std::abs(turn) * w.radius;
  }
}

// ---- world -------------------------------------------------------------------------------

OdeWorld::OdeWorld(const WorldSettings& settings) : settings_(settings) {
  InitOdeOnce();
  // The quick-step solver shuffles constraints with ODE's own (process-wide) generator; start it
  // from the same seed in every world so that a run never depends on what ran before it.
  dRandSetSeed(0);
  world_ = dWorldCreate();
  // ODE's default stepping scheduler is shared by every world: one of its own lets worlds step
  // on different threads at once (a run's physics thread, tests beside it).
  threading_ = dThreadingAllocateSelfThreadedImplementation();
  dWorldSetStepThreadingImplementation(world_, dThreadingImplementationGetFunctions(threading_), threading_);
  dWorldSetGravity(world_, 0, 0, -settings.gravity);
  dWorldSetQuickStepNumIterations(world_, settings.solver_iterations);
  dWorldSetERP(world_, 0.2);
  dWorldSetCFM(world_, 1e-5);
  dWorldSetContactSurfaceLayer(world_, 0.001);
  dWorldSetContactMaxCorrectingVel(world_, 1.0);
  moving_ = dHashSpaceCreate(nullptr);
  still_ = dHashSpaceCreate(nullptr);
  resting_ = dHashSpaceCreate(nullptr);
  contacts_ = dJointGroupCreate(0);
  dGeomID ground = dCreatePlane(still_, 0, 0, 1, 0);
  dGeomSetData(ground, make_info({Part::kGround, nullptr, nullptr, settings.ground_friction, 0}));
}

OdeWorld::~OdeWorld() {
  if (ray_) dGeomDestroy(ray_);
  dJointGroupDestroy(contacts_);
  dSpaceDestroy(moving_);  // spaces destroy their geoms (cleanup mode is on by default)
  dSpaceDestroy(still_);
  dSpaceDestroy(resting_);
  dWorldDestroy(world_);  // and the world its bodies and joints
  dThreadingFreeImplementation(threading_);
}

GeomInfo* OdeWorld::make_info(GeomInfo info) {
  infos_.push_back(std::make_unique<GeomInfo>(info));
  return infos_.back().get();
}

void OdeWorld::add_static_box(const StaticBox& box) {
  dGeomID g = dCreateBox(still_, box.size.x, box.size.y, box.size.z);
  dGeomSetPosition(g, box.center.x, box.center.y, box.center.z);
  dMatrix3 r;
  dRFromAxisAndAngle(r, 0, 0, 1, box.yaw);
  dGeomSetRotation(g, r);
  dGeomSetData(g, make_info({Part::kStatic, nullptr, nullptr, settings_.ground_friction, 0, static_boxes_++}));
}

Pose2D OdeMote::pose() const {
  const dReal* p = dGeomGetPosition(geom_);
  const dReal* r = dGeomGetRotation(geom_);
  return {p[0], p[1], std::atan2(r[4], r[0])};
}

Vec3 OdeMote::position3() const {
  const dReal* p = dGeomGetPosition(geom_);
  return {p[0], p[1], p[2]};
}

Twist2D OdeMote::velocity() const {
  if (!body_) return {};
  const dReal* v = dBodyGetLinearVel(body_);
  return {v[0], v[1], dBodyGetAngularVel(body_)[2]};
}

void OdeMote::Wake(dWorldID world) {
  if (body_) return;  // ODE itself enables a resting body that a moving one touches
  body_ = dBodyCreate(world);
  const dReal* p = dGeomGetPosition(geom_);
  dBodySetPosition(body_, p[0], p[1], p[2]);
  dBodySetRotation(body_, dGeomGetRotation(geom_));
  dMass mass;
  dMassSetBoxTotal(&mass, spec_.mass, spec_.size, spec_.size, spec_.size);
  dBodySetMass(body_, &mass);
  // Goes back to rest once it has been still for 20 steps.
  dBodySetAutoDisableFlag(body_, 1);
  dBodySetAutoDisableSteps(body_, 20);
  dGeomSetBody(geom_, body_);
}

void OdeMote::Rest() {
  dGeomSetBody(geom_, nullptr);  // the geom keeps the body's last position and rotation
  dBodyDestroy(body_);
  body_ = nullptr;
}

Body* OdeWorld::add_mote(const MoteSpec& spec, const Pose2D& pose) {
  dGeomID g = dCreateBox(resting_, spec.size, spec.size, spec.size);
  dGeomSetPosition(g, pose.x, pose.y, spec.size / 2);
  dMatrix3 r;
  dRFromAxisAndAngle(r, 0, 0, 1, pose.theta);
  dGeomSetRotation(g, r);
  motes_.push_back(std::make_unique<OdeMote>(g, spec));
  GeomInfo* info =
      make_info({Part::kMote, motes_.back().get(), nullptr, kMoteFriction, 0, static_cast<int>(motes_.size() - 1)});
  dGeomSetData(g, info);
  mote_geoms_.push_back(g);
  mote_awake_.push_back(false);
  mote_done_.push_back(false);
  mote_cell_.emplace_back();
  max_mote_reach_ = std::max(max_mote_reach_, spec.size * 0.87);  // half the cube's diagonal
  PlaceInGrid(static_cast<int>(mote_geoms_.size() - 1));
  return motes_.back().get();
}

void OdeWorld::NearCallback(void* data, dGeomID a, dGeomID b) { static_cast<OdeWorld*>(data)->Collide(a, b); }

void OdeWorld::Collide(dGeomID a, dGeomID b) {
  if (a == b) return;
  dBodyID ba = dGeomGetBody(a), bb = dGeomGetBody(b);
  if (!Moving(ba) && !Moving(bb)) return;  // nothing to do between things at rest
  const GeomInfo& ia = InfoOf(a);
  const GeomInfo& ib = InfoOf(b);
  if (ia.owner && ia.owner == ib.owner) return;  // parts of one robot
  if (ba && bb && dAreConnected(ba, bb)) return;

  dContact contact[kMaxContactsPerPair];
  const int n = dCollide(a, b, kMaxContactsPerPair, &contact[0].geom, sizeof(dContact));
  if (n == 0) return;
  if (listing_) return List(ia, ib);
  for (const GeomInfo* info : {&ia, &ib})
    if (info->part == Part::kMote) WakeMote(info->index);
  ba = dGeomGetBody(a);  // a mote touched just now has a body from here on
  bb = dGeomGetBody(b);

  const GeomInfo* omni = ia.part == Part::kOmniWheel ? &ia : ib.part == Part::kOmniWheel ? &ib : nullptr;
  const bool caster = ia.part == Part::kCaster || ib.part == Part::kCaster;
  for (int i = 0; i < n; ++i) {
    dSurfaceParameters& s = contact[i].surface;
    s.mode = dContactApprox1 | dContactSoftERP | dContactSoftCFM;
    s.soft_erp = 0.2;
    s.soft_cfm = 1e-4;
    s.mu = caster ? 0.0 : std::min(ia.friction, ib.friction);
    if (omni) {
      // Grip along the rolling direction (perpendicular to the hinge axis, in the contact
      // plane); slip along the axis, where a Swedish wheel's rollers turn freely.
      dVector3 axis;
      dJointGetHingeAxis(omni->hinge, axis);
      const dReal* nrm = contact[i].geom.normal;
      dVector3 roll = {axis[1] * nrm[2] - axis[2] * nrm[1], axis[2] * nrm[0] - axis[0] * nrm[2],
                       axis[0] * nrm[1] - axis[1] * nrm[0], 0};
      const double len = std::sqrt(roll[0] * roll[0] + roll[1] * roll[1] + roll[2] * roll[2]);
      if (len > 1e-9) {
        s.mode |= dContactMu2 | dContactFDir1;
        for (int k = 0; k < 3; ++k) contact[i].fdir1[k] = roll[k] / len;
        s.mu = omni->friction;
        s.mu2 = omni->slip_friction;
      }
    }
    dJointID joint = dJointCreateContact(world_, contacts_, &contact[i]);
    dJointAttach(joint, ba, bb);
  }
}

void OdeWorld::WakeMote(int index) {
  motes_[index]->Wake(world_);
  if (mote_awake_[index]) return;
  mote_awake_[index] = true;
  awake_motes_.push_back(index);
}

std::int64_t OdeWorld::CellOf(double x, double y) {
  const auto cx = static_cast<std::int64_t>(std::floor(x / kMoteCell));
  const auto cy = static_cast<std::int64_t>(std::floor(y / kMoteCell));
  return CellKey(cx, cy);
}

// Two cell coordinates in one key (the bits of cx above those of cy; shifted as unsigned, since
// shifting a negative value is undefined).
std::int64_t OdeWorld::CellKey(std::int64_t cx, std::int64_t cy) {
  return static_cast<std::int64_t>((static_cast<std::uint64_t>(cx) << 32) ^
                                   (static_cast<std::uint64_t>(cy) & 0xFFFFFFFFu));
}

void OdeWorld::PlaceInGrid(int mote) {
  const dReal* p = dGeomGetPosition(mote_geoms_[mote]);
  const std::int64_t cell = CellOf(p[0], p[1]);
  if (mote_cell_[mote] && *mote_cell_[mote] == cell) return;
  if (mote_cell_[mote]) {
    auto& old = mote_grid_[*mote_cell_[mote]];
    old.erase(std::find(old.begin(), old.end(), mote));
  }
  auto& members = mote_grid_[cell];
  members.insert(std::upper_bound(members.begin(), members.end(), mote), mote);  // sorted: a fixed order
  mote_cell_[mote] = cell;
}

// Collides `geom` with the motes whose grid cells its bounding box touches (except `self` and
// motes whose own pass has run this step), so that resting motes cost nothing far from anything.
void OdeWorld::CollideWithMotes(dGeomID geom, int self) {
  dReal box[6];
  dGeomGetAABB(geom, box);
  const double m = max_mote_reach_;
  const auto x0 = static_cast<std::int64_t>(std::floor((box[0] - m) / kMoteCell));
  const auto x1 = static_cast<std::int64_t>(std::floor((box[1] + m) / kMoteCell));
  const auto y0 = static_cast<std::int64_t>(std::floor((box[2] - m) / kMoteCell));
  const auto y1 = static_cast<std::int64_t>(std::floor((box[3] + m) / kMoteCell));
  for (auto cx = x0; cx <= x1; ++cx)
    for (auto cy = y0; cy <= y1; ++cy) {
      auto it = mote_grid_.find(CellKey(cx, cy));
      if (it == mote_grid_.end()) continue;
      for (int other : it->second)
        if (other != self && !mote_done_[other]) Collide(geom, mote_geoms_[other]);
    }
}

void OdeWorld::step(double dt) {
  PrepareThread();
  dSpaceCollide(moving_, this, &NearCallback);
  dSpaceCollide2(reinterpret_cast<dGeomID>(moving_), reinterpret_cast<dGeomID>(still_), this, &NearCallback);
  if (!motes_.empty())
    for (int i = 0, n = dSpaceGetNumGeoms(moving_); i < n; ++i) CollideWithMotes(dSpaceGetGeom(moving_, i), -1);
  // Motes that are awake (or were touched just now) meet the ground, obstacles and other motes;
  // the list may grow while we go through it when one mote pushes another.
  for (std::size_t i = 0; i < awake_motes_.size(); ++i) {
    const int mote = awake_motes_[i];
    dGeomID g = mote_geoms_[mote];
    dSpaceCollide2(g, reinterpret_cast<dGeomID>(still_), this, &NearCallback);
    CollideWithMotes(g, mote);
    mote_done_[mote] = true;
  }
  for (int mote : awake_motes_) mote_done_[mote] = false;
  if (settings_.solver == Solver::kExact)
    dWorldStep(world_, dt);
  else
    dWorldQuickStep(world_, dt);
  dJointGroupEmpty(contacts_);
  for (auto& v : vehicles_) v->update_wheels();
  // Motes that have come to rest again leave the awake list (in a stable order).
  std::size_t kept = 0;
  for (int index : awake_motes_) {
    PlaceInGrid(index);  // it may have moved
    if (motes_[index]->awake()) {
      awake_motes_[kept++] = index;
    } else {
      motes_[index]->Rest();
      mote_awake_[index] = false;
    }
  }
  awake_motes_.resize(kept);
}

// A pair in contact, while ContactsNow lists them (the ground does not count).
void OdeWorld::List(const GeomInfo& a, const GeomInfo& b) {
  if (a.part == Part::kGround || b.part == Part::kGround) return;
  const GeomInfo& body = a.owner ? a : b;
  const GeomInfo& other = a.owner ? b : a;
  EngineMessage::Contact c{body.owner, other.owner, other.owner ? -1 : other.index};
  for (const EngineMessage::Contact& seen : listed_)
    if (seen.a == c.a && seen.b == c.b && seen.obstacle == c.obstacle) return;
  listed_.push_back(c);
}

// The pairs touching now, found as a step finds them but creating no contact joints.
std::vector<EngineMessage::Contact> OdeWorld::ContactsNow() {
  listing_ = true;
  listed_.clear();
  dSpaceCollide(moving_, this, &NearCallback);
  dSpaceCollide2(reinterpret_cast<dGeomID>(moving_), reinterpret_cast<dGeomID>(still_), this, &NearCallback);
  if (!motes_.empty())
    for (int i = 0, n = dSpaceGetNumGeoms(moving_); i < n; ++i) CollideWithMotes(dSpaceGetGeom(moving_, i), -1);
  for (int mote : awake_motes_) {
    dSpaceCollide2(mote_geoms_[mote], reinterpret_cast<dGeomID>(still_), this, &NearCallback);
    CollideWithMotes(mote_geoms_[mote], mote);
  }
  listing_ = false;
  return std::move(listed_);
}

// The first message of each kind comes with the pairs in contact just after it.
std::vector<EngineMessage> OdeWorld::TakeMessages() {
  std::vector<std::pair<std::string, std::string>> raw;
  {
    const std::lock_guard<std::mutex> lock(g_messages_mutex);
    raw.swap(g_messages);
  }
  std::vector<EngineMessage> messages;
  for (auto& [kind, text] : raw) {
    messages.push_back({kind, std::move(text), {}});
    if (kinds_seen_.insert(kind).second) messages.back().contacts = ContactsNow();
  }
  return messages;
}

std::size_t OdeWorld::awake_body_count() const { return vehicles_.size() + awake_motes_.size(); }

namespace {

struct RayQuery {
  const Body* ignore;
  double nearest;
};

void RayCallback(void* data, dGeomID ray, dGeomID other) {
  auto* q = static_cast<RayQuery*>(data);
  const GeomInfo& info = InfoOf(other);
  if (info.part == Part::kGround) return;
  if (q->ignore && info.owner == q->ignore) return;
  dContactGeom hit;
  if (dCollide(ray, other, 1, &hit, sizeof hit) > 0) q->nearest = std::min(q->nearest, double(hit.depth));
}

}  // namespace

double OdeWorld::cast_ray(const Vec3& origin, const Vec3& direction, double max_range, const Body* ignore) const {
  PrepareThread();
  if (!ray_) {
    ray_ = dCreateRay(nullptr, max_range);
    dGeomSetData(ray_, const_cast<OdeWorld*>(this)->make_info({Part::kStatic, nullptr, nullptr, 0, 0}));
  }
  dGeomRaySetLength(ray_, max_range);
  dGeomRaySet(ray_, origin.x, origin.y, origin.z, direction.x, direction.y, direction.z);
  RayQuery query{ignore, max_range};
  for (dSpaceID space : {moving_, still_, resting_})
    dSpaceCollide2(ray_, reinterpret_cast<dGeomID>(space), &query, &RayCallback);
  return query.nearest;
}

}  // namespace ode
}  // namespace sanet::physics
