#include "net/wall_materials.h"

#include <algorithm>
#include <cmath>
#include <complex>

namespace sanet::net {
namespace {

// P.2040-1 Table 3: permittivity a·f^b and conductivity c·f^d, f in GHz. Its frequency ranges
// (1–10 GHz for brick, 1–100 GHz for concrete, glass 0.1–100, wood 0.001–100, metal 1–100)
// cover 802.11's 2.4 and 5 GHz bands.
struct Coefficients {
  Material material;
  const char* name;
  double a, b, c, d;
};
constexpr Coefficients kTable[] = {
    {Material::kNone, "none", 1, 0, 0, 0},
    {Material::kConcrete, "concrete", 5.31, 0, 0.0326, 0.8095},
    {Material::kBrick, "brick", 3.75, 0, 0.038, 0},
    {Material::kWood, "wood", 1.99, 0, 0.0047, 1.0718},
    {Material::kGlass, "glass", 6.27, 0, 0.0043, 1.1925},
    {Material::kMetal, "metal", 1, 0, 1e7, 0},
};

const Coefficients& Row(Material material) {
  for (const Coefficients& row : kTable)
    if (row.material == material) return row;
  return kTable[0];
}

constexpr double kLightSpeed = 299792458.0;  // m/s

}  // namespace

const char* MaterialName(Material material) { return Row(material).name; }

std::optional<Material> MaterialNamed(const std::string& name) {
  for (const Coefficients& row : kTable)
    if (name == row.name) return row.material;
  return std::nullopt;
}

std::vector<std::string> MaterialNames() {
  std::vector<std::string> names;
  for (const Coefficients& row : kTable) names.push_back(row.name);
  return names;
}

Electrical ElectricalProperties(Material material, double frequency_hz) {
  const Coefficients& row = Row(material);
  const double ghz = frequency_hz / 1e9;
  return {row.a * std::pow(ghz, row.b), row.c * std::pow(ghz, row.d)};
}

// P.2040's slab at normal incidence: the air-material interface reflects R' = (1 − √η)/(1 + √η)
// (both polarisations alike), the wave turns q = 2π d √η / λ through the slab, and the multiple
// reflections inside it sum to T = (1 − R'²) e^{−jq} / (1 − R'² e^{−j2q}). η is the complex
// relative permittivity ε − j σ/(2π f ε0) = ε − j 17.98 σ / f[GHz].
double SlabLossDb(Material material, double thickness, double frequency_hz) {
  if (material == Material::kNone || thickness <= 0) return 0;
  const Electrical e = ElectricalProperties(material, frequency_hz);
  const std::complex<double> eta(e.permittivity, -17.98 * e.conductivity / (frequency_hz / 1e9));
  const std::complex<double> root = std::sqrt(eta);
  const std::complex<double> r = (1.0 - root) / (1.0 + root);
  const std::complex<double> j(0, 1);
  const std::complex<double> q = 2 * M_PI * thickness * frequency_hz / kLightSpeed * root;
  // Far past the cap, e^{−jq} underflows to 0: the slab passes nothing.
  if (-q.imag() * 20 / std::log(10.0) > kMaxSlabLossDb * 2) return kMaxSlabLossDb;
  const std::complex<double> t = (1.0 - r * r) * std::exp(-j * q) / (1.0 - r * r * std::exp(-2.0 * j * q));
  return std::clamp(-20 * std::log10(std::abs(t)), 0.0, kMaxSlabLossDb);
}

}  // namespace sanet::net
