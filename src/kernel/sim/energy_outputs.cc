#include "sim/energy_outputs.h"

#include <algorithm>
#include <cstdio>

#include "trace/csv_sink.h"

namespace sanet::sim {

EnergyOutputs::EnergyOutputs(const RunNodes& nodes, RunBus& bus, trace::ResultsFolder& folder)
    : nodes_(nodes),
      folder_(folder),
      subscription_(bus.On<EnergySampled>(RunStage::kRecord, [this](const EnergySampled& e) { Sampled(e); })) {}

void EnergyOutputs::Sampled(const EnergySampled& e) {
  if (e.levels.empty()) return;
  if (!csv_) {
    csv_ = &folder_.Csv("energy.csv", "time,node,remaining_j,power_w");
    apart_ = e.levels.size() <= kNodesDrawnApart;  // the figure's form, from the first sample on
  }
  double least = 100, most = 0, sum = 0;
  for (const EnergyLevel& level : e.levels) {
    char numbers[96];
    std::snprintf(numbers, sizeof numbers, ",%.9g,%.9g", level.battery.remaining_j, level.battery.power_w);
    char time[32];
    std::snprintf(time, sizeof time, "%.6f,", e.t);
    csv_->Row(time + trace::CsvField(nodes_.NameOf(level.node)) + numbers);
    const double f = level.battery.fraction * 100;
    least = std::min(least, f), most = std::max(most, f), sum += f;
  }
  if (apart_) {
    for (std::size_t i = 0; i < e.levels.size(); ++i) {
      if (series_.size() <= i) series_.push_back({nodes_.NameOf(e.levels[i].node), {}});
      series_[i].points.emplace_back(e.t, e.levels[i].battery.fraction * 100);
    }
    return;
  }
  if (series_.empty()) series_ = {{"most charged", {}}, {"mean", {}}, {"least charged", {}}};
  series_[0].points.emplace_back(e.t, most);
  series_[1].points.emplace_back(e.t, sum / e.levels.size());
  series_[2].points.emplace_back(e.t, least);
}

void EnergyOutputs::AddTo(Fingerprint& fp) const {
  if (csv_) fp.Add(csv_->hash());
}

std::optional<std::string> EnergyOutputs::Figure(const std::string& run_name) const {
  if (series_.empty()) return std::nullopt;
  return trace::LinesSvg(run_name + ": battery charge", "time (s)", "charge (% of capacity)", series_);
}

}  // namespace sanet::sim
