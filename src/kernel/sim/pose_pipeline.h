// What the radios know of where the bodies are. With the physics on a second thread, the network
// runs ahead of the bodies: a radio must never read a body that a step is moving. So the radios
// read positions published at step boundaries (each ns-3 node's net::BodyMobilityModel holds
// its body's pose at the last boundary), and the steps that have ended are published lazily:
// when a radio next reads a position after a boundary passed (the feed is `behind`), the
// catch-up the stepper gave runs first. Poses are taken on the physics thread, after its step,
// and published on the network's.
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "physics/physics_world.h"
#include "sanet/geometry.h"
#include "sanet/message.h"

namespace sanet::net {
class BodyMobilityModel;
struct PoseFeed;
}  // namespace sanet::net

namespace sanet::sim {

struct RadioPose {
  NodeId node;
  physics::Vec3 position;  // m
  Twist2D velocity;
};

class PosePipeline {
 public:
  // `moved`: re-indexes the radios of the bodies that moved (the transport's Moved).
  explicit PosePipeline(std::function<void(const std::vector<NodeId>&)> moved);
  ~PosePipeline();

  // Node `pose.node`'s radio follows its mobility model from now on, starting at `pose`.
  void Add(net::BodyMobilityModel* mobility, const RadioPose& pose);
  static RadioPose Of(NodeId node, const physics::Body& body);
  // The radios learn these poses, and re-index the bodies that moved.
  void Publish(const std::vector<RadioPose>& poses);
  // Who publishes steps that have ended: after Behind, the radios call `catch_up` before they
  // next read a position. It calls CaughtUp first (publishing re-indexes the radios, which reads
  // positions again).
  void SetCatchUp(std::function<void()> catch_up);
  void Behind();
  void CaughtUp();

 private:
  void PublishOne(const RadioPose& pose);
  std::function<void(const std::vector<NodeId>&)> moved_;
  std::unique_ptr<net::PoseFeed> feed_;
  std::vector<net::BodyMobilityModel*> mobility_;  // per node; ns-3's nodes own them
  std::vector<NodeId> moved_scratch_;
};

}  // namespace sanet::sim
