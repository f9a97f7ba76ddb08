// The MCAP format's constants that both its writer and its reader use (mcap.dev, "MCAP File
// Format Specification", major version 0): the magic at both ends of a file and the opcodes of
// the records sanet writes or reads.
#pragma once

#include <cstdint>

namespace sanet::trace::mcap {

constexpr std::uint8_t kMagic[] = {0x89, 'M', 'C', 'A', 'P', 0x30, '\r', '\n'};
enum Op : std::uint8_t {
  kHeader = 0x01,
  kFooter = 0x02,
  kSchema = 0x03,
  kChannel = 0x04,
  kMessage = 0x05,
  kChunk = 0x06,
  kMessageIndex = 0x07,
  kChunkIndex = 0x08,
  kStatistics = 0x0B,
  kSummaryOffset = 0x0E,
  kDataEnd = 0x0F,
};
constexpr const char* kZstd = "zstd";  // a chunk's compression, as the specification names it

}  // namespace sanet::trace::mcap
