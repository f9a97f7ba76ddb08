#include "net/path_loss.h"

#include <ns3/double.h>

namespace sanet::net {
namespace {

ns3::Ptr<ns3::PropagationLossModel> Model(const NetworkSpec& spec, double frequency_hz) {
  switch (spec.loss) {
    case LossModel::kFriis: {
      auto friis = ns3::CreateObject<ns3::FriisPropagationLossModel>();
      friis->SetAttribute("Frequency", ns3::DoubleValue(frequency_hz));
      return friis;
    }
    case LossModel::kTwoRayGround: {
      auto two_ray = ns3::CreateObject<ns3::TwoRayGroundPropagationLossModel>();
      two_ray->SetAttribute("Frequency", ns3::DoubleValue(frequency_hz));
      two_ray->SetAttribute("HeightAboveZ", ns3::DoubleValue(spec.antenna_height));
      return two_ray;
    }
    case LossModel::kLogDistance:
      break;
  }
  auto log_distance = ns3::CreateObject<ns3::LogDistancePropagationLossModel>();
  log_distance->SetAttribute("Exponent", ns3::DoubleValue(spec.exponent));
  log_distance->SetAttribute("ReferenceDistance", ns3::DoubleValue(spec.reference_distance));
  log_distance->SetAttribute("ReferenceLoss", ns3::DoubleValue(spec.reference_loss));
  return log_distance;
}

}  // namespace

ns3::Ptr<ns3::PropagationLossModel> PathLoss(const NetworkSpec& spec) {
  return PathLoss(spec, FrequencyHz(spec.standard));
}

ns3::Ptr<ns3::PropagationLossModel> PathLoss(const NetworkSpec& spec, double frequency_hz) {
  ns3::Ptr<ns3::PropagationLossModel> chain = Model(spec, frequency_hz);
  if (spec.max_range > 0) {
    auto range = ns3::CreateObject<ns3::RangePropagationLossModel>();
    range->SetAttribute("MaxRange", ns3::DoubleValue(spec.max_range));
    chain->SetNext(range);
  }
  return chain;
}

ns3::Ptr<ns3::PropagationLossModel> LastOf(ns3::Ptr<ns3::PropagationLossModel> chain) {
  while (chain->GetNext()) chain = chain->GetNext();
  return chain;
}

}  // namespace sanet::net
