// An ns-3 mobility model whose position is the physics body's, read at the moment ns-3 asks
// (when a frame is sent or received). Nothing copies positions each step.
#pragma once

#include <ns3/mobility-model.h>

#include <functional>

namespace sanet::net {

class BodyMobilityModel : public ns3::MobilityModel {
 public:
  static ns3::TypeId GetTypeId();

  // `position` and `velocity` return the body's current state in metres and m/s.
  void Bind(std::function<ns3::Vector()> position, std::function<ns3::Vector()> velocity);

 private:
  ns3::Vector DoGetPosition() const override;
  // Physics owns the position: ns-3 helpers that try to place the node are ignored.
  void DoSetPosition(const ns3::Vector& position) override;
  ns3::Vector DoGetVelocity() const override;

  std::function<ns3::Vector()> position_;
  std::function<ns3::Vector()> velocity_;
};

}  // namespace sanet::net
