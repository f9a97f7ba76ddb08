// What makes links vary in a scenario (docs/network.md#a-grey-zone): `network.propagation`'s
// `shadowing` and `fading`, and `network.hardware_spread`. Each prints only when it is on, so a
// scenario without them prints (and fingerprints) as before they existed.
#pragma once

#include "net/network_spec.h"
#include "scenario/fields.h"

namespace sanet::scenario {

const Fields<net::NetworkSpec>& ShadowingFields();
const Fields<net::NetworkSpec>& FadingFields();
const Fields<net::NetworkSpec>& HardwareSpreadFields();
// The three as entries of their sections' tables.
FieldInfo ShadowingEntry();
FieldInfo FadingEntry();
FieldInfo HardwareSpreadEntry();
void ReadShadowing(const Field& f, net::NetworkSpec& n);
void ReadFading(const Field& f, net::NetworkSpec& n);
void ReadHardwareSpread(const Field& f, net::NetworkSpec& n);
YAML::Node PrintShadowing(const net::NetworkSpec& n);
YAML::Node PrintFading(const net::NetworkSpec& n);
YAML::Node PrintHardwareSpread(const net::NetworkSpec& n);

}  // namespace sanet::scenario
