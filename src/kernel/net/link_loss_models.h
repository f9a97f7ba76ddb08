// Shadowing and fading as ns-3 propagation loss models, so that everything that asks the channel
// (YansWifiChannel, the indexed channel, signal-strength queries) meets them alike:
//
// - ShadowingLossModel, chained after the path loss and the walls (SetNext), adds the link's
//   shadowing at the two nodes' positions (net/shadowing.h). A link's value is kept while neither
//   end moves (the table is emptied when it holds kMaxKept links: values computed again are the
//   same, since the field is a function of places).
// - FadingLossModel wraps that mean chain: a frame's power is the mean's plus the frame's fading
//   gain (net/fading.h). Signal strengths, the viewer and the range searches ask the mean chain
//   itself, without fading. A frame whose mean is so weak that even the capped fading gain leaves
//   it under every radio's sensitivity is not drawn for: no radio would take it, whatever the draw.
//
// Nodes are known by their ns-3 ids (sanet's node ids); a mobility model on no node (the indexed
// channel's probes) gets no shadowing and no fading.
#pragma once

#include <ns3/mobility-model.h>
#include <ns3/propagation-loss-model.h>

#include <cstdint>
#include <optional>
#include <unordered_map>

#include "net/fading.h"
#include "net/shadowing.h"

namespace sanet::net {

class ShadowingLossModel : public ns3::PropagationLossModel {
 public:
  static ns3::TypeId GetTypeId();
  ShadowingLossModel() : field_(0, Shadowing{}) {}
  void SetField(const ShadowingField& field) {
    field_ = field;
    symmetric_ = field.symmetric();
    kept_.clear();
  }
  struct Counters {
    std::uint64_t asked = 0;     // links' values asked for
    std::uint64_t computed = 0;  // of them, computed (the others were kept)
  };
  const Counters& counters() const { return counters_; }

 private:
  struct Kept {
    double ax = 0, ay = 0, bx = 0, by = 0;  // where the two ends stood
    double gain_db = 0;
  };
  static constexpr std::size_t kMaxKept = 1 << 20;  // links (some 60 MB)
  double DoCalcRxPower(double tx_power_dbm, ns3::Ptr<ns3::MobilityModel> a,
                       ns3::Ptr<ns3::MobilityModel> b) const override;
  int64_t DoAssignStreams(int64_t) override { return 0; }

  ShadowingField field_;
  bool symmetric_ = true;
  mutable std::unordered_map<std::uint64_t, Kept> kept_;  // by (from, to), or (lower, higher) if symmetric
  mutable Counters counters_;
};

class FadingLossModel : public ns3::PropagationLossModel {
 public:
  static ns3::TypeId GetTypeId();
  FadingLossModel() : fading_(0, Fading{}) {}
  // Frames under `dbm` before the receiver's gain are taken by no radio (the lowest sensitivity
  // less the highest antenna gain).
  void Set(ns3::Ptr<ns3::PropagationLossModel> mean, const NakagamiFading& fading, double untaken_below_dbm) {
    mean_ = std::move(mean);
    fading_ = fading;
    untaken_below_dbm_ = untaken_below_dbm;
  }

 private:
  double DoCalcRxPower(double tx_power_dbm, ns3::Ptr<ns3::MobilityModel> a,
                       ns3::Ptr<ns3::MobilityModel> b) const override;
  int64_t DoAssignStreams(int64_t) override { return 0; }

  ns3::Ptr<ns3::PropagationLossModel> mean_;
  NakagamiFading fading_;
  double untaken_below_dbm_ = -1e9;
};

// The ns-3 id of the node a mobility model moves, if it is on one.
std::optional<std::uint32_t> NodeOf(const ns3::Ptr<ns3::MobilityModel>& mobility);

}  // namespace sanet::net
