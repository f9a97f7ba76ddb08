// A physics world whose step may run on a second thread while the rest of the run goes on.
//
// It wraps an engine's world (ODE or Box2D) and hands out bodies that wrap the engine's. Steps
// started with StepAsync run in order on the StepWorker; every other call, on the world or on any
// of its bodies, first waits for them all. So whatever reads or drives a body (a sensor, a
// controller's command, a trajectory sample) sees the state at the end of the last step started,
// whether it ran on another thread or at once: one thread or two give the same results.
#pragma once

#include <functional>
#include <memory>
#include <unordered_map>
#include <vector>

#include "physics/physics_world.h"
#include "physics/step_worker.h"

namespace sanet::physics {

class PipelinedWorld : public PhysicsWorld {
 public:
  // `threaded`: StepAsync runs on a thread of its own, up to `depth` steps ahead of the caller;
  // otherwise at once.
  PipelinedWorld(std::unique_ptr<PhysicsWorld> engine, bool threaded, std::size_t depth);
  ~PipelinedWorld() override;

  // Queues `work` (which steps this world, through it, and may read its bodies) behind the steps
  // already started; returns its number (1, 2, ...).
  std::uint64_t StepAsync(std::function<void()> work) { return worker_.Launch(std::move(work)); }
  // Waits for every step started (a no-op on the steps' own thread).
  void Settle() override { worker_.Wait(); }
  // Waits for step `number` (and those before it) only.
  void SettleStep(std::uint64_t number) { worker_.WaitFor(number); }
  double waited() const { return worker_.waited(); }  // s the caller spent waiting in Settle

  void add_static_box(const StaticBox& box) override;
  Vehicle* add_omni3(const Omni3Spec& spec, const Pose2D& pose) override;
  Vehicle* add_diffdrive(const DiffDriveSpec& spec, const Pose2D& pose) override;
  Body* add_mote(const MoteSpec& spec, const Pose2D& pose) override;
  double cast_ray(const Vec3& origin, const Vec3& direction, double max_range, const Body* ignore) const override;
  std::vector<double> cast_rays(const std::vector<Ray>& rays, double max_range, const Body* ignore) const override;
  void step(double dt) override;
  std::size_t awake_body_count() const override;
  double gravity() const override { return engine_->gravity(); }
  // The engine's messages, their bodies the ones handed out here.
  std::vector<EngineMessage> TakeMessages() override;

 private:
  class GatedBody;
  class GatedVehicle;
  void SettleConst() const { const_cast<StepWorker&>(worker_).Wait(); }
  const Body* Inner(const Body* body) const;
  Vehicle* Gate(Vehicle* engine_vehicle);  // the gated vehicle handed out for the engine's

  std::unique_ptr<PhysicsWorld> engine_;
  std::vector<std::unique_ptr<Body>> bodies_;
  std::unordered_map<const Body*, const Body*> outer_;  // the engine's body -> the one handed out
  StepWorker worker_;                                   // last: it stops before the engine goes
};

}  // namespace sanet::physics
