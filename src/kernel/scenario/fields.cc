#include "scenario/fields.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace sanet::scenario {

// Plain decimals between 1e-4 and 1e5, "1e6" and "2.5e-7" outside.
std::string ShortNumber(double value) {
  if (std::isinf(value)) return value > 0 ? ".inf" : "-.inf";
  const double size = std::fabs(value);
  const bool exponent = size >= 1e5 || (size > 0 && size < 1e-4);
  char text[40];
  // Fixed notation of a number under 0.1 needs more decimals than 17 for 17 significant digits.
  for (int digits = 1; digits <= (exponent ? 17 : 22); ++digits) {
    std::snprintf(text, sizeof text, exponent ? "%.*e" : "%.*f", exponent ? digits - 1 : digits, value);
    if (std::strtod(text, nullptr) == value) break;
  }
  std::string out = text;
  if (exponent) {  // 1.0e+06 -> 1e6
    const auto e = out.find('e');
    std::string mantissa = out.substr(0, e), power = out.substr(e + 1);
    if (mantissa.find('.') != std::string::npos) mantissa.erase(mantissa.find_last_not_of('0') + 1);
    if (mantissa.back() == '.') mantissa.pop_back();
    const bool negative = power[0] == '-';
    power.erase(0, power.find_first_not_of("+-0"));
    return mantissa + "e" + (negative ? "-" : "") + (power.empty() ? "0" : power);
  }
  if (out.find('.') != std::string::npos) out.erase(out.find_last_not_of('0') + 1);
  if (out.back() == '.') out.pop_back();
  return out == "-0" ? "0" : out;
}

YAML::Node NumberNode(double value) {
  YAML::Node node(ShortNumber(value));
  return node;
}

std::string RangeText(double min, double max, bool min_exclusive) {
  if (std::isinf(min) && std::isinf(max)) return "any";
  return std::string(min_exclusive ? "(" : "[") + ShortNumber(min) + ", " + ShortNumber(max) + "]";
}

namespace {

std::string Cell(const std::string& text) { return text.empty() ? "—" : text; }

}  // namespace

std::string MarkdownTable(const std::vector<FieldInfo>& fields) {
  std::string out = "| Key | Type | Unit | Default | Range | Meaning |\n|---|---|---|---|---|---|\n";
  for (const FieldInfo& f : fields)
    out += "| `" + f.key + "` | " + Cell(f.type) + " | " + Cell(f.unit) + " | " + Cell(f.default_text) + " | " +
           Cell(f.range) + " | " + f.meaning + " |\n";
  return out;
}

}  // namespace sanet::scenario
