// The runs of a study: every combination of the varied parameters' values, each with every
// seed, in a fixed order, each with a name that is its folder's (runs/<name>/).
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace sanet::study {

class GridError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// One --vary: a scenario path (as --set takes it) and its values as text.
struct Parameter {
  std::string path;
  std::vector<std::string> values;
};

// "path=v1,v2,v3"; commas inside [] or {} belong to a value ("size=[1,2],[3,4]").
Parameter ParseVary(const std::string& text);
// The number a value's whole text is ("25", "0.5", "1e3"), or nothing ("20ms", "[1, 2]", "").
std::optional<double> NumberIn(const std::string& text);

// The last key of a path; of an ns-3 attribute name, the attribute ("NodeTraversalTime").
std::string ShortName(const std::string& path);
// "1-10", "1,4,7", "1-3,8".
std::vector<std::uint64_t> ParseSeeds(const std::string& text);

struct RunPoint {
  std::vector<std::pair<std::string, std::string>> values;  // path -> value, in --vary order
  std::uint64_t seed = 0;
  std::string name;  // e.g. "tx_power=25,speed=0.5,seed=3"

  // The --set options that make this run from the scenario.
  std::vector<std::string> Sets() const;
};

// Every combination (the first parameter varies slowest), each with every seed.
std::vector<RunPoint> Grid(const std::vector<Parameter>& parameters, const std::vector<std::uint64_t>& seeds);

}  // namespace sanet::study
