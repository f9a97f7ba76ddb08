#include "net/duty_cycle.h"

#include <cmath>

#include "core/counter_random.h"

namespace sanet::net {

CycleState CycleAt(const DutyCycle& cycle, double t) {
  const double since = t - cycle.phase;
  const double start = cycle.phase + std::floor(since / cycle.period) * cycle.period;  // of this period
  const double into = t - start;
  if (into < cycle.awake) return {false, start + cycle.awake};
  return {true, start + cycle.period};
}

double PhaseOf(const DutyCycle& cycle, std::uint64_t seed, std::uint64_t node) {
  constexpr std::uint64_t kDutyPhaseKey = 0x6475747950686173;  // "dutyPhas": draws of its own
  if (!cycle.random_phase) return cycle.phase;
  return cycle.period * CounterRandom(seed, {kDutyPhaseKey, node}).Uniform();
}

}  // namespace sanet::net
