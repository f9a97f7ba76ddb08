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
  const std::uint16_t channel = channels_.at(topic.id - 1);
  if (!channel) return;
  waiting_.emplace_hint(waiting_.upper_bound(time_ns), time_ns, std::make_pair(channel, cdr));
  if (time_ns > newest_) newest_ = time_ns;
  if (newest_ >= kReorder) WriteUntil(newest_ - kReorder);
}

void McapSink::WriteUntil(std::uint64_t time_ns) {
  auto end = waiting_.upper_bound(time_ns);
  for (auto it = waiting_.begin(); it != end; ++it)
    writer_.Write(it->second.first, it->first, it->first, it->second.second);
  waiting_.erase(waiting_.begin(), end);
}

}  // namespace sanet::ros2_presentation
