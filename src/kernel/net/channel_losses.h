// The loss models of the channel, chained as ns-3 chains them (PropagationLossModel::SetNext):
//
//   mean   = path loss (log-distance, Friis or two-ray ground; the range cut-off)
//            -> walls (ObstacleLossModel, when an obstacle costs) -> shadowing (when sigma > 0)
//   frames = mean, with fading on top (FadingLossModel, when fading is on); else mean itself
//   range  = the path loss alone, for the indexed channel's search ranges, which add
//            `range_margin_db`, the most shadowing and fading can ever add (walls only subtract)
//
// Without walls, shadowing and fading, `frames` and `mean` are the very chain sanet always built.
#pragma once

#include <ns3/propagation-loss-model.h>

#include "net/network_spec.h"
#include "net/obstacle_loss_model.h"

namespace sanet::net {

class ShadowingLossModel;

struct ChannelLosses {
  ns3::Ptr<ns3::PropagationLossModel> frames, mean, range;
  ns3::Ptr<ShadowingLossModel> shadowing;  // when sigma > 0
  double range_margin_db = 0;
};

// For the 802.11 radios.
ChannelLosses BuildChannelLosses(const NetworkSpec& spec, ns3::Ptr<ObstacleLossModel> walls);
// At `frequency_hz`, for radios that take no frame weaker than `untaken_below_dbm` (the 802.15.4
// radios: their sensitivity).
ChannelLosses BuildChannelLosses(const NetworkSpec& spec, ns3::Ptr<ObstacleLossModel> walls, double frequency_hz,
                                 double untaken_below_dbm);

}  // namespace sanet::net
