// The scenario's path loss as a chain of ns-3 propagation loss models: log-distance, Friis or
// two-ray ground, then the range cut-off if one is set. The world's walls (ObstacleLossModel) are
// chained after it by the wireless network; the indexed channel computes its search ranges from
// a wall-free chain, since walls only ever add loss.
#pragma once

#include <ns3/propagation-loss-model.h>

#include "net/network_spec.h"

namespace sanet::net {

ns3::Ptr<ns3::PropagationLossModel> PathLoss(const NetworkSpec& spec);  // at the 802.11 standard's frequency
ns3::Ptr<ns3::PropagationLossModel> PathLoss(const NetworkSpec& spec, double frequency_hz);
// The chain's last model, to chain another after it.
ns3::Ptr<ns3::PropagationLossModel> LastOf(ns3::Ptr<ns3::PropagationLossModel> chain);

}  // namespace sanet::net
