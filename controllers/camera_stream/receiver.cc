// The other end of camera_streamer: inflates each picture it receives and checks that it holds a
// whole picture. Logs `frame FRAME BYTES DRIVEN DELAY whole|cut`; metrics `delivered` (1 a
// picture) and `delay` (s from sending to arrival).
#include <zlib.h>

#include <cstdio>
#include <memory>

#include "camera_stream/pictures.h"
#include "controllers.h"

namespace sanet::controllers {
namespace {

class PictureReceiver : public Controller {
 public:
  explicit PictureReceiver(const Params& /*p*/) {}

  void ControlStep(Node& /*node*/) override {}

  void OnMessage(Node& node, const Message& m) override {
    const auto head = camera_stream::ReadHeader(m.payload);
    if (!head) return;
    std::vector<std::uint8_t> pixels(static_cast<std::size_t>(head->width) * head->height * 3);
    uLongf size = pixels.size();
    const bool whole = uncompress(pixels.data(), &size, m.payload.data() + camera_stream::kHeaderBytes,
                                  m.payload.size() - camera_stream::kHeaderBytes) == Z_OK &&
                       size == pixels.size();
    const double delay = node.Now() - head->sent;
    node.Metric("delivered", 1);
    node.Metric("delay", delay);
    char line[128];
    std::snprintf(line, sizeof line, "frame %u %zu %.2f %.4f %s", head->frame, m.payload.size(), head->driven, delay,
                  whole ? "whole" : "cut");
    node.Log(line);
  }
};

}  // namespace

ControllerInfo PictureReceiverInfo() {
  return {"picture_receiver",
          "receives camera_streamer's pictures: inflates each and checks it is whole; logs `frame FRAME BYTES DRIVEN "
          "DELAY whole|cut`; metrics delivered, delay",
          [](const Params& p) { return std::make_unique<PictureReceiver>(p); }};
}

}  // namespace sanet::controllers
