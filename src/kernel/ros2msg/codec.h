// Encoding and decoding whole ROS 2 messages: the serialized payload DDS carries (and MCAP
// stores), from and into the generated types of ros2msg/messages.h.
#pragma once

#include <optional>
#include <string>

#include "ros2msg/messages.h"

namespace sanet::ros2msg {

template <typename Message>
Bytes Encode(const Message& m) {
  CdrWriter w;
  Write(w, m);
  return w.Take();
}

// The message, or nothing with `error` naming the field that failed and why.
template <typename Message>
std::optional<Message> Decode(const std::uint8_t* data, std::size_t size, std::string* error = nullptr) {
  CdrReader r(data, size);
  Message m;
  if (r.ok() && Read(r, m)) return m;
  if (error) *error = r.error();
  return std::nullopt;
}

template <typename Message>
std::optional<Message> Decode(const Bytes& bytes, std::string* error = nullptr) {
  return Decode<Message>(bytes.data(), bytes.size(), error);
}

}  // namespace sanet::ros2msg
