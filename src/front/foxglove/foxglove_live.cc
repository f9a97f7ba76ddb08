#include "foxglove/foxglove_live.h"

#include <cmath>

#include "sim/snapshot.h"

namespace sanet::foxglove {

void FoxgloveLive::Observe(sim::RunBus& bus, ros2_presentation::RunPresentation& presentation) {
  presentation.AddSink(*this);
  step_ended_ =
      bus.On<sim::StepEnded>(sim::RunStage::kObserve, [this](const sim::StepEnded& e) { AfterStep(e.world); });
}

void FoxgloveLive::AfterStep(const sim::WorldSnapshot& snapshot) {
  const double t = snapshot.time();
  if (last_time_ >= 0 && t - last_time_ < 0.05) return;
  last_time_ = t;
  hub_.Time(static_cast<std::uint64_t>(std::llround(t * 1e9)));
}

}  // namespace sanet::foxglove
