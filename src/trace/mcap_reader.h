// Reads an MCAP file's data section whole (trace.mcap, for `sanet view`'s Foxglove replay): the
// header's profile, the schemas and channels, and every message in the file's order, from
// uncompressed or Zstandard chunks or outside chunks (the published specification, as
// trace/mcap_writer.h writes it). A file that is not MCAP, or is cut short, or whose chunk is
// damaged, throws std::runtime_error naming the file and the byte offset.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace sanet::trace {

struct McapContents {
  struct Channel {
    std::uint16_t id = 0;
    std::string topic, message_encoding, schema_name, schema_encoding, schema;
  };
  struct Message {
    std::uint64_t log_time = 0;
    std::uint16_t channel = 0;
    std::vector<std::uint8_t> data;
  };
  std::string profile;
  std::vector<Channel> channels;  // in the order the file gives them
  std::vector<Message> messages;  // in the file's order
};

McapContents ReadMcap(const std::string& path);

}  // namespace sanet::trace
