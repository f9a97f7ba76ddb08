#include "sim/pose_pipeline.h"

#include <algorithm>

#include "net/body_mobility_model.h"

namespace sanet::sim {

PosePipeline::PosePipeline(std::function<void(const std::vector<NodeId>&)> moved)
    : moved_(std::move(moved)), feed_(std::make_unique<net::PoseFeed>()) {}

PosePipeline::~PosePipeline() = default;

void PosePipeline::Add(net::BodyMobilityModel* mobility, const RadioPose& pose) {
  mobility_.resize(std::max<std::size_t>(mobility_.size(), pose.node + 1), nullptr);
  mobility_[pose.node] = mobility;
  mobility->Follow(feed_.get());
  PublishOne(pose);
}

RadioPose PosePipeline::Of(NodeId node, const physics::Body& body) { return {node, body.position3(), body.velocity()}; }

void PosePipeline::PublishOne(const RadioPose& p) {
  mobility_.at(p.node)->Publish(ns3::Vector(p.position.x, p.position.y, p.position.z),
                                ns3::Vector(p.velocity.vx, p.velocity.vy, 0));
}

void PosePipeline::Publish(const std::vector<RadioPose>& poses) {
  moved_scratch_.clear();
  for (const RadioPose& p : poses) {
    PublishOne(p);
    moved_scratch_.push_back(p.node);
  }
  moved_(moved_scratch_);
}

void PosePipeline::SetCatchUp(std::function<void()> catch_up) { feed_->catch_up = std::move(catch_up); }
void PosePipeline::Behind() { feed_->behind = true; }
void PosePipeline::CaughtUp() { feed_->behind = false; }

}  // namespace sanet::sim
