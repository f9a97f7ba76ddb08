// Each radio's own hardware: transmit power and noise figure off their nominal values by a
// Gaussian amount, drawn from the run's seed and the node's id, clipped at +-3 sigma
// (HardwareSpread). Zuniga and Krishnamachari ("Analyzing the transitional region in low power
// wireless links", SECON 2004) name this variance as the second cause of asymmetric links: a
// strong sender with a deaf receiver hears its partner less well than it is heard.
#pragma once

#include <cstdint>

#include "net/network_spec.h"

namespace sanet::net {

// dB added to node `node`'s transmit power.
double TxPowerOffsetDb(const NetworkSpec& spec, std::uint32_t node);
// dB added to node `node`'s receiver noise figure.
double NoiseFigureOffsetDb(const NetworkSpec& spec, std::uint32_t node);

}  // namespace sanet::net
