// A node's `energy` in a scenario (docs/energy.md): its battery, the electronics' draw and the
// radio's currents, as a node, a grid item and a spawn class give it.
#pragma once

#include "energy/energy_spec.h"
#include "net/network_spec.h"
#include "scenario/fields.h"
#include "scenario/yaml_reader.h"

namespace sanet::scenario {

const Fields<energy::EnergySpec>& EnergyFields();
// energy.radio as a mapping: a preset, and currents that change its figures.
const Fields<energy::EnergySpec>& RadioEnergyFields();
const Fields<energy::EnergySpec>& LrWpanRadioEnergyFields();  // energy.lr_wpan_radio as a mapping
const Fields<energy::WirelessCharger>& WirelessChargerFields();
// Reads `energy`, checking what no single key can (the revive level above the cutoff); a node
// that `has_drive` gets its drive's costs (docs/energy.md#motion), which a mote's refuses; a node
// with an 802.15.4 radio gets that radio's currents (`lr_wpan_radio`), which others refuse.
energy::EnergySpec ReadEnergy(const Field& f, bool has_drive, net::Radios radios);

}  // namespace sanet::scenario
