// Shadowing and fading as ns-3 propagation loss models, so that everything that asks the channel
// (YansWifiChannel, the indexed channel, signal-strength queries) meets them alike:
//
// - ShadowingLossModel, chained after the path loss and the walls (SetNext), adds the link's
//   shadowing at the two nodes' positions (net/shadowing.h). A link's value is kept while neither
//   end moves, in a table of fixed size (a link that loses its slot is computed again: the same
//   value, since the field is a function of places).
// - FadingLossModel wraps that mean chain: a frame's power is the mean's plus the frame's fading
//   gain (net/fading.h). Signal strengths, the viewer and the range searches ask the mean chain
//   itself, without fading.
//
// Nodes are known by their ns-3 ids (sanet's node ids); a mobility model on no node (the indexed
// channel's probes) gets no shadowing and no fading.
#pragma once

#include <ns3/mobility-model.h>
#include <ns3/propagation-loss-model.h>

#include <cstdint>
#include <optional>
#include <vector>

#include "net/fading.h"
#include "net/shadowing.h"

namespace sanet::net {

class ShadowingLossModel : public ns3::PropagationLossModel {
 public:
  static ns3::TypeId GetTypeId();
  ShadowingLossModel() : field_(0, Shadowing{}) {}
  void SetField(const ShadowingField& field) { field_ = field; }

 private:
  struct Kept {
    std::uint32_t from = 0, to = 0;
    double ax = 0, ay = 0, bx = 0, by = 0;
    double gain_db = 0;
    bool used = false;
  };
  static constexpr std::size_t kSlots = 1 << 16;
  double DoCalcRxPower(double tx_power_dbm, ns3::Ptr<ns3::MobilityModel> a,
                       ns3::Ptr<ns3::MobilityModel> b) const override;
  int64_t DoAssignStreams(int64_t) override { return 0; }

  ShadowingField field_;
  mutable std::vector<Kept> kept_ = std::vector<Kept>(kSlots);
};

class FadingLossModel : public ns3::PropagationLossModel {
 public:
  static ns3::TypeId GetTypeId();
  FadingLossModel() : fading_(0, Fading{}) {}
  void Set(ns3::Ptr<ns3::PropagationLossModel> mean, const NakagamiFading& fading) {
    mean_ = std::move(mean);
    fading_ = fading;
  }

 private:
  double DoCalcRxPower(double tx_power_dbm, ns3::Ptr<ns3::MobilityModel> a,
                       ns3::Ptr<ns3::MobilityModel> b) const override;
  int64_t DoAssignStreams(int64_t) override { return 0; }

  ns3::Ptr<ns3::PropagationLossModel> mean_;
  NakagamiFading fading_;
};

// The ns-3 id of the node a mobility model moves, if it is on one.
std::optional<std::uint32_t> NodeOf(const ns3::Ptr<ns3::MobilityModel>& mobility);

}  // namespace sanet::net
