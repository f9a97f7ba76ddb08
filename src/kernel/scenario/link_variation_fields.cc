#include "scenario/link_variation_fields.h"

namespace sanet::scenario {

using net::NetworkSpec;

const Fields<NetworkSpec>& ShadowingFields() {
  static const Fields<NetworkSpec> fields = [] {
    Fields<NetworkSpec> f;
    f.Number(
        "sigma_db", [](NetworkSpec& n) -> double& { return n.shadowing.sigma_db; }, "dB", 0, 30,
        "deviation of the log-normal shadowing (`0`: none)");
    f.Number(
        "correlation_m", [](NetworkSpec& n) -> double& { return n.shadowing.correlation_m; }, "m", 0, 1e6,
        "decorrelation distance: moving an end by x keeps exp(-x / this) of the correlation", true);
    f.Number(
        "clip_sigmas", [](NetworkSpec& n) -> double& { return n.shadowing.clip_sigmas; }, "", 1, 10,
        "values are clipped at this many sigmas either way");
    f.Flag(
        "symmetric", [](NetworkSpec& n) -> bool& { return n.shadowing.symmetric; },
        "the same shadowing both ways of a link (`false`: each way drawn apart)");
    return f;
  }();
  return fields;
}

const Fields<NetworkSpec>& FadingFields() {
  static const Fields<NetworkSpec> fields = [] {
    Fields<NetworkSpec> f;
    f.Choice<net::FadingModel>(
        "model", [](NetworkSpec& n) -> net::FadingModel& { return n.fading.model; },
        {{"none", net::FadingModel::kNone},
         {"nakagami", net::FadingModel::kNakagami},
         {"rayleigh", net::FadingModel::kRayleigh}},
        "fading drawn per frame: Nakagami-m, or Rayleigh (Nakagami with m = 1)");
    f.Number(
        "m", [](NetworkSpec& n) -> double& { return n.fading.m; }, "", 0.5, 100,
        "Nakagami's shape: 1 is Rayleigh, larger fades less");
    return f;
  }();
  return fields;
}

const Fields<NetworkSpec>& HardwareSpreadFields() {
  static const Fields<NetworkSpec> fields = [] {
    Fields<NetworkSpec> f;
    f.Number(
        "tx_power_db", [](NetworkSpec& n) -> double& { return n.spread.tx_power_db; }, "dB", 0, 20,
        "deviation of each node's transmit power from its setting");
    f.Number(
        "noise_figure_db", [](NetworkSpec& n) -> double& { return n.spread.noise_figure_db; }, "dB", 0, 20,
        "deviation of each node's receiver noise figure from ns-3's (7 dB)");
    return f;
  }();
  return fields;
}

FieldInfo ShadowingEntry() {
  return {
      "shadowing", "mapping", "", "none", "see [shadowing](#shadowing)", "log-normal shadowing, correlated in space"};
}
FieldInfo FadingEntry() { return {"fading", "mapping", "", "none", "see [fading](#fading)", "fading per frame"}; }
FieldInfo HardwareSpreadEntry() {
  return {"hardware_spread",
          "mapping",
          "",
          "none",
          "see [hardware_spread](#hardware_spread)",
          "each radio's own transmit power and noise figure, drawn from the seed"};
}

void ReadShadowing(const Field& f, NetworkSpec& n) {
  ShadowingFields().Read(f, n);
  f.Require("sigma_db");  // without it the other keys would silently do nothing
}

void ReadFading(const Field& f, NetworkSpec& n) {
  FadingFields().Read(f, n);
  const auto m = f.Get("m");
  if (m && n.fading.model == net::FadingModel::kRayleigh && n.fading.m != 1)
    m->Fail("rayleigh is Nakagami with m = 1: write `model: nakagami` for another m");
  if (m && n.fading.model == net::FadingModel::kNone) m->Fail("applies to `model: nakagami` only");
  if (n.fading.model == net::FadingModel::kRayleigh) n.fading.m = 1;
}

void ReadHardwareSpread(const Field& f, NetworkSpec& n) { HardwareSpreadFields().Read(f, n); }

YAML::Node PrintShadowing(const NetworkSpec& n) {
  return n.shadowing.sigma_db > 0 ? ShadowingFields().Print(n) : YAML::Node();
}

YAML::Node PrintFading(const NetworkSpec& n) {
  if (n.fading.model == net::FadingModel::kNone) return YAML::Node();
  YAML::Node out = FadingFields().Print(n);
  if (n.fading.model == net::FadingModel::kRayleigh) out.remove("m");
  return out;
}

YAML::Node PrintHardwareSpread(const NetworkSpec& n) {
  return n.spread.tx_power_db > 0 || n.spread.noise_figure_db > 0 ? HardwareSpreadFields().Print(n) : YAML::Node();
}

}  // namespace sanet::scenario
