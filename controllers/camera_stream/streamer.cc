// A robot that streams its camera's pictures to another node while it drives ahead at `speed`:
// at each control step (give it the camera's rate) it takes the latest picture of its `camera`,
// deflates its pixels with zlib (as PNG does) and sends it as one message: a frame number, the
// picture's size, the distance driven so far, then the compressed bytes. A picture that
// compresses past one message (65,480 bytes) is skipped, and the log says so. Logs `sent FRAME
// BYTES DRIVEN` for each; metric `picture_bytes`.
#include <zlib.h>

#include <cmath>
#include <memory>

#include "camera_stream/pictures.h"
#include "controllers.h"

namespace sanet::controllers {
namespace {

class CameraStreamer : public Controller {
 public:
  explicit CameraStreamer(const Params& p)
      : to_(p.Text("to", "")),
        camera_(p.Text("camera", "camera")),
        speed_(p.Number("speed", 1.0, 0, 100)),
        level_(p.Integer("level", 6, 0, 9)) {}

  void Start(Node& node) override {
    target_ = node.Lookup(to_);
    if (!target_) node.Log("camera_streamer: no node named '" + to_ + "' (the `to` parameter): nothing is sent");
    if (const auto pose = node.GroundTruth()) origin_ = *pose;
  }

  void ControlStep(Node& node) override {
    node.Drive({speed_, 0, 0});
    const auto picture = node.SensorAs<ImageReading>(camera_);
    const auto pose = node.GroundTruth();
    if (!picture || !pose || !target_) return;
    const double driven = std::hypot(pose->x - origin_.x, pose->y - origin_.y);
    Bytes message = camera_stream::Header(frame_, picture->width, picture->height, driven, node.Now());
    uLongf size = compressBound(picture->data.size());
    const std::size_t head = message.size();
    message.resize(head + size);
    compress2(message.data() + head, &size, picture->data.data(), picture->data.size(), level_);
    message.resize(head + size);
    if (message.size() > camera_stream::kMostBytes) {
      node.Log("frame " + std::to_string(frame_) + " skipped: " + std::to_string(message.size()) +
               " bytes compressed, past one message");
    } else {
      node.Send(*target_, message);
      node.Metric("picture_bytes", static_cast<double>(message.size()));
      node.Log("sent " + std::to_string(frame_) + " " + std::to_string(message.size()) + " " + Fixed(driven));
    }
    ++frame_;
  }

 private:
  static std::string Fixed(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", v);
    return text;
  }

  std::string to_, camera_;
  double speed_;
  int level_;
  std::optional<NodeId> target_;
  Pose2D origin_;
  std::uint32_t frame_ = 0;
};

}  // namespace

ControllerInfo CameraStreamerInfo() {
  return {"camera_streamer",
          "drives ahead at `speed` and sends each picture of its `camera` (default camera), deflated with zlib at "
          "`level`, to node `to` as one message; logs `sent FRAME BYTES DRIVEN`; metric picture_bytes",
          [](const Params& p) { return std::make_unique<CameraStreamer>(p); }};
}

}  // namespace sanet::controllers
