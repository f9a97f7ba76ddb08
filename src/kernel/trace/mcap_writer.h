// An MCAP file (the container of ROS 2 bags, Foxglove and PlotJuggler), written from the published
// specification (mcap.dev, "MCAP File Format Specification", major version 0): magic, header,
// messages in uncompressed chunks with a message index per channel after each, the data end with
// the data section's CRC32, then a summary (schemas, channels, chunk indexes, statistics) grouped
// by opcode with summary offsets, and the footer, so that readers seek by time and topic.
// Chunks may be compressed with Zstandard (the spec's "zstd", Debian's libzstd), which every MCAP
// reader supports. No MCAP library is packaged in Debian; CRC32 is zlib's.
#pragma once

#include <cstdint>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace sanet::trace {

class McapWriter {
 public:
  using Bytes = std::vector<std::uint8_t>;
  enum class Compression { kNone, kZstd };
  // Opens `path` and writes the magic and the header (`profile`: "ros2" for ROS 2 messages in
  // CDR). Messages gather in chunks of about `chunk_bytes` (before compression). Throws
  // std::runtime_error.
  McapWriter(const std::string& path, const std::string& profile, const std::string& library,
             Compression compression = Compression::kNone, std::size_t chunk_bytes = 1 << 20);
  ~McapWriter();
  McapWriter(const McapWriter&) = delete;
  McapWriter& operator=(const McapWriter&) = delete;

  // Ids start at 1. `encoding`: "ros2msg" for a ROS 2 message definition.
  std::uint16_t AddSchema(const std::string& name, const std::string& encoding, const std::string& data);
  // `message_encoding`: "cdr" for ROS 2 messages. Throws std::length_error past 65535 channels.
  std::uint16_t AddChannel(std::uint16_t schema, const std::string& topic, const std::string& message_encoding,
                           const std::map<std::string, std::string>& metadata = {});
  // Log and publish time in nanoseconds (sanet: simulated time). Times may go back; chunk and
  // file start and end times are the smallest and largest.
  void Write(std::uint16_t channel, std::uint64_t log_time, std::uint64_t publish_time, const Bytes& data);
  // Writes the last chunk, the summary and the footer. Called by the destructor if not before.
  void Close();
  std::uint64_t messages() const { return message_count_; }

 private:
  struct Schema {
    std::uint16_t id;
    std::string name, encoding, data;
  };
  struct Channel {
    std::uint16_t id, schema;
    std::string topic, encoding;
    std::map<std::string, std::string> metadata;
  };
  void Put(const Bytes& bytes);
  void ChunkNewDefinitions();
  void FlushChunk();
  void WriteSummary(std::uint64_t summary_start);

  std::ofstream out_;
  std::uint64_t offset_ = 0;    // bytes written so far
  std::uint32_t data_crc_ = 0;  // CRC32 of the data section so far
  Compression compression_;
  std::size_t chunk_bytes_;
  std::vector<Schema> schemas_;
  std::vector<Channel> channels_;
  Bytes chunk_;  // records of the chunk being gathered
  std::uint64_t chunk_start_ = 0, chunk_end_ = 0;
  std::map<std::uint16_t, std::vector<std::pair<std::uint64_t, std::uint64_t>>> chunk_index_;  // time, offset
  std::size_t schemas_written_ = 0, channels_written_ = 0;  // those already in a chunk
  Bytes chunk_indexes_;                                     // Chunk Index records, for the summary
  std::uint32_t chunk_count_ = 0;
  std::uint64_t message_count_ = 0, first_ = 0, last_ = 0;
  std::vector<std::uint64_t> per_channel_;  // messages, by channel id - 1
  std::vector<std::uint32_t> sequence_;     // the next message's sequence number, by channel id - 1
  bool closed_ = false;
};

}  // namespace sanet::trace
