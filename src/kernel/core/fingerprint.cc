#include "core/fingerprint.h"

#include <cstdio>

namespace sanet {

std::string Fingerprint::Hex() const {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash_));
  return text;
}

}  // namespace sanet
