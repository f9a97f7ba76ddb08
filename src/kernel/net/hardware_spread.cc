#include "net/hardware_spread.h"

#include <algorithm>

#include "core/counter_random.h"

namespace sanet::net {
namespace {

constexpr std::uint64_t kTxPowerKey = 0x5458504f57ull, kNoiseFigureKey = 0x4e4f495345ull;  // "TXPOW", "NOISE"

double Offset(const NetworkSpec& spec, double sigma, std::uint64_t what, std::uint32_t node) {
  if (sigma <= 0) return 0;
  CounterRandom random(spec.seed, {what, node});
  const double clip = HardwareSpread::kClipSigmas * sigma;
  return std::clamp(sigma * random.StandardGaussian(), -clip, clip);
}

}  // namespace

double TxPowerOffsetDb(const NetworkSpec& spec, std::uint32_t node) {
  return Offset(spec, spec.spread.tx_power_db, kTxPowerKey, node);
}

double NoiseFigureOffsetDb(const NetworkSpec& spec, std::uint32_t node) {
  return Offset(spec, spec.spread.noise_figure_db, kNoiseFigureKey, node);
}

}  // namespace sanet::net
