// camera_streamer's messages: a picture's header, then its pixels deflated with zlib.
#pragma once

#include <cstdint>
#include <optional>

#include "sanet/codec.h"

namespace sanet::controllers::camera_stream {

constexpr std::size_t kMostBytes = 65480;  // one message: one UDP datagram less sanet's header
constexpr std::uint8_t kPicture = 0x70;
constexpr std::size_t kHeaderBytes = 1 + 4 + 2 + 2 + 8 + 8;

struct PictureHeader {
  std::uint32_t frame = 0;
  std::uint16_t width = 0, height = 0;
  double driven = 0;  // m the sender had driven when it took the picture
  double sent = 0;    // s, simulated
};

inline Bytes Header(std::uint32_t frame, int width, int height, double driven, double sent) {
  return Writer()
      .U8(kPicture)
      .U32(frame)
      .U16(static_cast<std::uint16_t>(width))
      .U16(static_cast<std::uint16_t>(height))
      .F64(driven)
      .F64(sent)
      .bytes();
}

// Nothing for a message that is not a picture.
inline std::optional<PictureHeader> ReadHeader(const Bytes& message) {
  Reader r(Bytes(message.begin(), message.begin() + std::min(message.size(), kHeaderBytes)));
  if (r.U8() != kPicture) return std::nullopt;
  PictureHeader h;
  h.frame = r.U32(), h.width = r.U16(), h.height = r.U16(), h.driven = r.F64(), h.sent = r.F64();
  if (!r.ok()) return std::nullopt;
  return h;
}

}  // namespace sanet::controllers::camera_stream
