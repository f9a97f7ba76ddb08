// What a run throws when it cannot go on (a controller failed, a world built twice).
#pragma once

#include <stdexcept>

namespace sanet::sim {

class WorldError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace sanet::sim
