#include "net/channel_losses.h"

#include "net/link_loss_models.h"
#include "net/ns3_attributes.h"
#include "net/path_loss.h"

namespace sanet::net {
namespace {

// Under this (dBm, before the receiver's antenna gain) no radio takes a frame: every PHY has
// WifiPhy's sensitivity and gain as network.ns3 left them (YansWifiChannel drops such frames
// before the PHY sees them, as does the indexed channel).
double UntakenBelowDbm() { return WifiPhyDefault("RxSensitivity") - WifiPhyDefault("RxGain"); }

}  // namespace

ChannelLosses BuildChannelLosses(const NetworkSpec& spec, ns3::Ptr<ObstacleLossModel> walls) {
  return BuildChannelLosses(spec, walls, FrequencyHz(spec.standard), UntakenBelowDbm());
}

ChannelLosses BuildChannelLosses(const NetworkSpec& spec, ns3::Ptr<ObstacleLossModel> walls, double frequency_hz,
                                 double untaken_below_dbm) {
  ChannelLosses losses;
  losses.mean = PathLoss(spec, frequency_hz);
  losses.range = PathLoss(spec, frequency_hz);
  if (walls) LastOf(losses.mean)->SetNext(walls);
  if (spec.shadowing.sigma_db > 0) {
    const ShadowingField field(spec.seed, spec.shadowing);
    auto shadowing = ns3::CreateObject<ShadowingLossModel>();
    shadowing->SetField(field);
    LastOf(losses.mean)->SetNext(shadowing);
    losses.shadowing = shadowing;
    losses.range_margin_db += field.MaxGainDb();
  }
  losses.frames = losses.mean;
  if (spec.fading.model != FadingModel::kNone) {
    const NakagamiFading fading(spec.seed, spec.fading);
    auto faded = ns3::CreateObject<FadingLossModel>();
    faded->Set(losses.mean, fading, untaken_below_dbm);
    losses.frames = faded;
    losses.range_margin_db += fading.MaxGainDb();
  }
  return losses;
}

}  // namespace sanet::net
