// A radio's duty cycle (`radio.duty_cycle`): awake `awake` seconds of every `period`, the
// windows starting at `phase` + k * period; asleep (802.11 sleep, the sleep current) the rest.
// Low-power MACs and sensor-network deployments keep radios off most of the time so that motes
// live for months (e.g. Ye, Heidemann and Estrin, "An energy-efficient MAC protocol for wireless
// sensor networks" (S-MAC), INFOCOM 2002, a fixed listen/sleep schedule).
#pragma once

#include <cstdint>

namespace sanet::net {

struct DutyCycle {
  double period = 0;  // s
  double awake = 0;   // s, in (0, period]
  double phase = 0;   // s, in [0, period): when the first window starts
  // Each node's phase drawn uniformly in [0, period) from the run's seed: radios that wake
  // together and send what they queued at once collide at their receiver, every period.
  bool random_phase = false;
};

// The phase of `node`'s cycle: its own, or drawn from the seed.
double PhaseOf(const DutyCycle& cycle, std::uint64_t seed, std::uint64_t node);

struct CycleState {
  bool asleep = false;
  double next_change = 0;  // s: when the state changes next (after t)
};

// The cycle's state at time `t` (s).
CycleState CycleAt(const DutyCycle& cycle, double t);

}  // namespace sanet::net
