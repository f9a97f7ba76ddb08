#include "study/grid.h"

#include <map>
#include <set>
#include <sstream>

#include "core/fingerprint.h"

namespace sanet::study {
namespace {

// Splits at commas outside brackets and braces.
std::vector<std::string> SplitValues(const std::string& text) {
  std::vector<std::string> values(1);
  int depth = 0;
  for (char c : text) {
    if (c == '[' || c == '{') ++depth;
    if (c == ']' || c == '}') --depth;
    if (c == ',' && depth == 0) {
      values.emplace_back();
      continue;
    }
    values.back() += c;
  }
  return values;
}

// A value as it may stand in a folder name.
std::string Clean(const std::string& text) {
  std::string out;
  for (unsigned char c : text)
    out += (std::isalnum(c) || c == '.' || c == '-' || c == '+' || c == '_') ? static_cast<char>(c) : '_';
  return out.empty() ? "_" : out;
}

// Short names for the parameters: the last key of each path, or the whole path where two share it.
std::vector<std::string> ShortNames(const std::vector<Parameter>& parameters) {
  std::map<std::string, int> uses;
  for (const Parameter& p : parameters) ++uses[ShortName(p.path)];
  std::vector<std::string> names;
  for (const Parameter& p : parameters)
    names.push_back(Clean(uses[ShortName(p.path)] > 1 ? p.path : ShortName(p.path)));
  return names;
}

std::string Hash8(const RunPoint& run) {
  Fingerprint f;
  for (const auto& [path, value] : run.values) f.Add(path + "=" + value + "\n");
  f.Add(run.seed);
  return f.Hex().substr(0, 8);
}

}  // namespace

std::optional<double> NumberIn(const std::string& text) {
  char* end = nullptr;
  const double d = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0') return std::nullopt;
  return d;
}

std::string ShortName(const std::string& path) {
  const std::string key = path.substr(path.rfind('.') + 1);
  const auto colons = key.rfind("::");
  return colons == std::string::npos ? key : key.substr(colons + 2);
}

Parameter ParseVary(const std::string& text) {
  const auto equals = text.find('=');
  if (equals == std::string::npos || equals == 0)
    throw GridError("--vary " + text + ": expected PATH=V1,V2,..., e.g. --vary network.tx_power=16,20,25");
  Parameter p{text.substr(0, equals), SplitValues(text.substr(equals + 1))};
  if (p.path == "seed") throw GridError("--vary seed=...: give the seeds with --seeds (e.g. --seeds 1-10)");
  std::set<std::string> seen;
  for (const std::string& v : p.values) {
    if (v.empty()) throw GridError("--vary " + text + ": an empty value (two commas, or one at an end)");
    if (!seen.insert(v).second) throw GridError("--vary " + text + ": the value '" + v + "' is given twice");
  }
  return p;
}

std::vector<std::uint64_t> ParseSeeds(const std::string& text) {
  std::vector<std::uint64_t> seeds;
  std::stringstream parts(text);
  for (std::string part; std::getline(parts, part, ',');) {
    const auto dash = part.find('-');
    try {
      std::size_t used = 0;
      const std::uint64_t first = std::stoull(part.substr(0, dash), &used);
      if (used != (dash == std::string::npos ? part.size() : dash)) throw std::invalid_argument(part);
      const std::uint64_t last = dash == std::string::npos ? first : std::stoull(part.substr(dash + 1), &used);
      if (dash != std::string::npos && used != part.size() - dash - 1) throw std::invalid_argument(part);
      if (last < first || last - first > 100000) throw std::invalid_argument(part);
      for (std::uint64_t s = first; s <= last; ++s) seeds.push_back(s);
    } catch (const std::exception&) {
      throw GridError("--seeds: '" + part + "' is not a seed or a range like 1-10");
    }
  }
  if (seeds.empty()) throw GridError("--seeds: give at least one seed");
  std::set<std::uint64_t> unique(seeds.begin(), seeds.end());
  if (unique.size() != seeds.size()) throw GridError("--seeds " + text + ": a seed is given twice");
  return seeds;
}

std::vector<std::string> RunPoint::Sets() const {
  std::vector<std::string> sets;
  for (const auto& [path, value] : values) sets.push_back(path + "=" + value);
  return sets;
}

std::vector<RunPoint> Grid(const std::vector<Parameter>& parameters, const std::vector<std::uint64_t>& seeds) {
  std::set<std::string> paths;
  for (const Parameter& p : parameters)
    if (!paths.insert(p.path).second) throw GridError("--vary " + p.path + " is given twice");
  std::vector<std::vector<std::pair<std::string, std::string>>> combinations(1);
  for (const Parameter& p : parameters) {
    std::vector<std::vector<std::pair<std::string, std::string>>> longer;
    for (const auto& c : combinations)
      for (const std::string& v : p.values) {
        longer.push_back(c);
        longer.back().emplace_back(p.path, v);
      }
    combinations = std::move(longer);
  }
  const std::vector<std::string> keys = ShortNames(parameters);
  std::vector<RunPoint> runs;
  std::set<std::string> names;
  for (const auto& c : combinations)
    for (std::uint64_t seed : seeds) {
      RunPoint run{c, seed, ""};
      for (std::size_t i = 0; i < c.size(); ++i) run.name += keys[i] + "=" + Clean(c[i].second) + ",";
      run.name += "seed=" + std::to_string(seed);
      // Values that differ only in characters a folder name cannot hold get a hash to tell them apart.
      if (run.name.size() > 120 || !names.insert(run.name).second)
        run.name = run.name.substr(0, 100) + "-" + Hash8(run);
      runs.push_back(run);
    }
  return runs;
}

}  // namespace sanet::study
