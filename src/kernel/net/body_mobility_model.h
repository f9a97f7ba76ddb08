// An ns-3 mobility model whose position is the physics body's as it was at the last physics-step
// boundary. The run publishes the bodies that moved in each step (Publish), and ns-3 reads the
// published position whenever it asks (a frame sent or received). So the radio never reads a
// body while the physics thread integrates it, and all frames between two step boundaries see
// the same positions, whether the physics runs on a thread of its own or not.
//
// With a physics thread the run may reach a step boundary before that thread has finished the
// step: it then marks its feed `behind`, and the first position ns-3 asks for after that
// publishes the finished steps first (waiting for them if need be).
#pragma once

#include <ns3/mobility-model.h>

#include <functional>

namespace sanet::net {

struct PoseFeed {
  bool behind = false;             // steps that ended at a boundary already passed wait to be published
  std::function<void()> catch_up;  // publishes them and clears `behind`
};

class BodyMobilityModel : public ns3::MobilityModel {
 public:
  static ns3::TypeId GetTypeId();

  void Follow(PoseFeed* feed) { feed_ = feed; }
  // The body's position (m) and velocity (m/s) at the step boundary just reached.
  void Publish(const ns3::Vector& position, const ns3::Vector& velocity) {
    position_ = position;
    velocity_ = velocity;
  }

 private:
  void CatchUp() const {
    if (feed_ && feed_->behind) feed_->catch_up();
  }
  ns3::Vector DoGetPosition() const override { return CatchUp(), position_; }
  // Physics owns the position: ns-3 helpers that try to place the node are ignored.
  void DoSetPosition(const ns3::Vector&) override {}
  ns3::Vector DoGetVelocity() const override { return CatchUp(), velocity_; }

  PoseFeed* feed_ = nullptr;
  ns3::Vector position_, velocity_;
};

}  // namespace sanet::net
