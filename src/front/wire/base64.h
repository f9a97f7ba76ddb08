// Base64 (RFC 4648, with padding) through OpenSSL's EVP_EncodeBlock and EVP_DecodeBlock, for
// binary data on the robot protocol's text lines (a camera's picture).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace sanet::wire {

std::string Base64(const std::vector<std::uint8_t>& bytes);
// Nothing for text that is not base64 in whole groups of four.
std::optional<std::vector<std::uint8_t>> FromBase64(const std::string& text);

}  // namespace sanet::wire
