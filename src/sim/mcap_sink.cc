#include "sim/mcap_sink.h"

#include "core/version.h"

namespace sanet::sim {

McapSink::McapSink(const std::string& path)
    : writer_(path, "ros2", std::string("sanet ") + SanetVersion(), trace::McapWriter::Compression::kZstd) {}

void McapSink::Advertise(const Topic& topic) {
  auto schema = schemas_.find(topic.type);
  if (schema == schemas_.end())
    schema = schemas_.emplace(topic.type, writer_.AddSchema(topic.type, "ros2msg", topic.definition)).first;
  channels_[topic.id] = writer_.AddChannel(schema->second, topic.name, "cdr");
}

void McapSink::Publish(const Topic& topic, std::uint64_t time_ns, const std::vector<std::uint8_t>& cdr) {
  writer_.Write(channels_.at(topic.id), time_ns, time_ns, cdr);
}

}  // namespace sanet::sim
