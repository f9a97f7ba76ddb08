// The run's ROS 2 messages into an MCAP file (trace.mcap, docs/mcap.md): one schema per type, one
// channel per topic, zstd chunks (trace/mcap_writer.h). The file is in time order, for streaming
// readers: messages may arrive late (a sensor's samples come with the physics step after them),
// so each waits until the run is kReorder past it and goes in order of time, then of arrival.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "ros2_presentation/message_sink.h"
#include "trace/mcap_writer.h"

namespace sanet::ros2_presentation {

class McapSink : public MessageSink {
 public:
  explicit McapSink(const std::string& path);
  void Advertise(const Topic& topic) override;
  void Publish(const Topic& topic, std::uint64_t time_ns, const std::vector<std::uint8_t>& cdr) override;
  void Close() {
    WriteUntil(UINT64_MAX);
    writer_.Close();
  }
  std::size_t left_out() const { return left_out_; }  // topics past the file's 65535 channels

 private:
  static constexpr std::uint64_t kReorder = 1'000'000'000;  // ns: far beyond a sample's lateness
  void WriteUntil(std::uint64_t time_ns);                   // the waiting messages at or before it

  trace::McapWriter writer_;
  std::multimap<std::uint64_t, std::pair<std::uint16_t, std::vector<std::uint8_t>>> waiting_;  // by time
  std::uint64_t newest_ = 0;
  std::map<std::string, std::uint16_t> schemas_;  // by type
  std::size_t left_out_ = 0;
  std::vector<std::uint16_t> channels_;  // by topic id - 1; 0: a topic past the file's 65535 channels
};

}  // namespace sanet::ros2_presentation
