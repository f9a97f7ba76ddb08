// The world's walls in the radio: an ns-3 propagation loss model, chained after the scenario's
// path loss (PropagationLossModel::SetNext), that subtracts the loss of every obstacle the
// straight segment between the two antennas crosses (net/obstacle_crossings.h). An antenna sits
// at its node's position (the body's centre) raised by the radio's `antenna_height`; the height
// is used only here, the path loss keeps its own distances.
//
// A pair's loss is kept while neither end moves: motes and parked robots cost one lookup per
// frame, and a moving robot one walk through the grid per frame it is part of.
#pragma once

#include <ns3/mobility-model.h>
#include <ns3/propagation-loss-model.h>

#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include "net/obstacle_crossings.h"

namespace sanet::net {

class ObstacleLossModel : public ns3::PropagationLossModel {
 public:
  static ns3::TypeId GetTypeId();

  void SetObstacles(std::shared_ptr<const ObstacleCrossings> obstacles) { obstacles_ = std::move(obstacles); }
  // The antenna of node `node` (its ns-3 id) stands `height` m above the node's position.
  void SetAntennaHeight(std::uint32_t node, double height);
  // The loss (dB) between the antennas at these two nodes' positions now.
  double LossDb(ns3::Ptr<ns3::MobilityModel> a, ns3::Ptr<ns3::MobilityModel> b) const;

  struct Counters {
    std::uint64_t asked = 0;   // losses asked for
    std::uint64_t walked = 0;  // of them, computed through the grid (the others from the cache)
  };
  const Counters& counters() const { return counters_; }
  std::size_t walls() const { return obstacles_ ? obstacles_->size() : 0; }

 private:
  struct Kept {
    const void *from = nullptr, *to = nullptr;  // the pair's mobility models
    ns3::Vector a, b;                           // their positions when it was computed
    double height_a = 0, height_b = 0;          // their antennas' heights
    double loss_db = 0;
  };
  double DoCalcRxPower(double tx_power_dbm, ns3::Ptr<ns3::MobilityModel> a,
                       ns3::Ptr<ns3::MobilityModel> b) const override;
  int64_t DoAssignStreams(int64_t) override { return 0; }
  double AntennaHeight(const ns3::Ptr<ns3::MobilityModel>& mobility) const;

  std::shared_ptr<const ObstacleCrossings> obstacles_;
  std::vector<double> antenna_heights_;                   // by node id
  mutable std::unordered_map<std::uint64_t, Kept> kept_;  // by a hash of the pair
  mutable Counters counters_;
};

}  // namespace sanet::net
