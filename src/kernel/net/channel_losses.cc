#include "net/channel_losses.h"

#include "net/link_loss_models.h"
#include "net/path_loss.h"

namespace sanet::net {

ChannelLosses BuildChannelLosses(const NetworkSpec& spec, ns3::Ptr<ObstacleLossModel> walls) {
  ChannelLosses losses;
  losses.mean = PathLoss(spec);
  losses.range = PathLoss(spec);
  if (walls) LastOf(losses.mean)->SetNext(walls);
  if (spec.shadowing.sigma_db > 0) {
    const ShadowingField field(spec.seed, spec.shadowing);
    auto shadowing = ns3::CreateObject<ShadowingLossModel>();
    shadowing->SetField(field);
    LastOf(losses.mean)->SetNext(shadowing);
    losses.range_margin_db += field.MaxGainDb();
  }
  losses.frames = losses.mean;
  if (spec.fading.model != FadingModel::kNone) {
    const NakagamiFading fading(spec.seed, spec.fading);
    auto faded = ns3::CreateObject<FadingLossModel>();
    faded->Set(losses.mean, fading);
    losses.frames = faded;
    losses.range_margin_db += fading.MaxGainDb();
  }
  return losses;
}

}  // namespace sanet::net
