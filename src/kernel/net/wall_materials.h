// What a wall of a given material costs a radio frame that passes through it: the loss (dB) of a
// homogeneous slab at normal incidence, from the electrical properties of building materials in
// Recommendation ITU-R P.2040-1 (07/2015), Table 3, and its single-layer slab method (§2.2.2.2).
// The loss is per wall crossed, as in the multi-wall model of COST 231 (Final Report, §4.7), and
// depends on the wall's thickness and the radio's frequency: 11 dB for 0.2 m of concrete at
// 2.4 GHz, 3.2 dB for 0.2 m of wood. Tabulated in docs/network.md#walls.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace sanet::net {

enum class Material { kNone, kConcrete, kBrick, kWood, kGlass, kMetal };

// "concrete", ...; the scenario's names.
const char* MaterialName(Material material);
std::optional<Material> MaterialNamed(const std::string& name);
std::vector<std::string> MaterialNames();

// Relative permittivity and conductivity (S/m) of the material at `frequency_hz` (P.2040 eq. 58, 59).
struct Electrical {
  double permittivity = 1, conductivity = 0;
};
Electrical ElectricalProperties(Material material, double frequency_hz);

// The loss (dB, ≥ 0) of a slab `thickness` m thick at normal incidence; `kNone` costs nothing.
// Metal's slab loss exceeds any radio's link budget: it is capped at kMaxSlabLossDb.
double SlabLossDb(Material material, double thickness, double frequency_hz);
constexpr double kMaxSlabLossDb = 200;

}  // namespace sanet::net
