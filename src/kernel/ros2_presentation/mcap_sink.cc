#include "ros2_presentation/mcap_sink.h"

#include <stdexcept>

#include "core/version.h"

namespace sanet::ros2_presentation {

McapSink::McapSink(const std::string& path)
    : writer_(path, "ros2", std::string("sanet ") + SanetVersion(), trace::McapWriter::Compression::kZstd) {}

void McapSink::Advertise(const Topic& topic) {
  auto schema = schemas_.find(topic.type);
  if (schema == schemas_.end())
    schema = schemas_.emplace(topic.type, writer_.AddSchema(topic.type, "ros2msg", topic.definition)).first;
  if (channels_.size() < topic.id) channels_.resize(topic.id, 0);
  try {
    channels_[topic.id - 1] = writer_.AddChannel(schema->second, topic.name, "cdr");
  } catch (const std::length_error&) {  // a swarm of thousands: the file keeps the first topics
    ++left_out_;
  }
}

void McapSink::Publish(const Topic& topic, std::uint64_t time_ns, const std::vector<std::uint8_t>& cdr) {
  if (const std::uint16_t channel = channels_.at(topic.id - 1)) writer_.Write(channel, time_ns, time_ns, cdr);
}

}  // namespace sanet::ros2_presentation
