// JSON as text, whatever bytes its strings hold: names, log lines and paths come from users and
// controllers and need not be valid UTF-8, and a result must never be lost to that (nlohmann's
// dump throws on invalid UTF-8 by default). Invalid bytes become U+FFFD.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace sanet {

template <typename Json>
std::string JsonText(const Json& j, int indent = -1) {
  return j.dump(indent, ' ', false, Json::error_handler_t::replace);
}

}  // namespace sanet
