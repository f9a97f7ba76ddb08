// Reads an MCAP file's data section record by record (trace.mcap, for `sanet view`'s Foxglove
// replay): the header's profile, each channel (with its schema) when the file first gives it, and
// each message in the file's order, from uncompressed or Zstandard chunks or outside chunks (the
// published specification, as trace/mcap_writer.h writes it). It holds one chunk at a time, so a
// file of any size replays in little memory. A file that is not MCAP, is cut short, or whose chunk
// is damaged throws std::runtime_error naming the file and the byte offset.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace sanet::trace {

struct McapChannel {
  std::uint16_t id = 0;
  std::string topic, message_encoding, schema_name, schema_encoding, schema;
};

struct McapMessage {
  std::uint64_t log_time = 0;
  std::uint16_t channel = 0;
  std::vector<std::uint8_t> data;
};

struct McapVisitor {
  std::function<void(const std::string& profile)> header;
  std::function<void(const McapChannel&)> channel;
  // Return false to stop reading.
  std::function<bool(const McapMessage&)> message;
};

// Visits the file; false if the visitor stopped it.
bool ReadMcap(const std::string& path, const McapVisitor& visit);

}  // namespace sanet::trace
