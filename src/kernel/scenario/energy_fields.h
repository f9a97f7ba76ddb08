// A node's `energy` in a scenario (docs/energy.md): its battery, the electronics' draw and the
// radio's currents, as a node, a grid item and a spawn class give it.
#pragma once

#include "energy/energy_spec.h"
#include "scenario/fields.h"
#include "scenario/yaml_reader.h"

namespace sanet::scenario {

const Fields<energy::EnergySpec>& EnergyFields();
// energy.radio as a mapping: a preset, and currents that change its figures.
const Fields<energy::EnergySpec>& RadioEnergyFields();
// Reads `energy`, checking what no single key can (the revive level above the cutoff).
energy::EnergySpec ReadEnergy(const Field& f);

}  // namespace sanet::scenario
