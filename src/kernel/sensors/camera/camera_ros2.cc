// The camera as a ROS camera driver publishes it, under /<robot>/camera (or /<robot>/<instance>):
// image_raw (sensor_msgs/Image, rgb8), camera_info (sensor_msgs/CameraInfo: the pinhole's K and P,
// no distortion) and, with depth, depth/image_raw (32FC1, m along the optical axis, +Inf where
// nothing is), all in the optical frame <robot>/<instance>_optical (REP 103: z forward, x right,
// y down). /tf_static mounts <robot>/<instance> (the robot's axes, pitched down) on base_link and
// the optical frame on it. The run's record (trace.mcap, the Foxglove stream) takes the pictures
// at `record_rate` as image_transport's compressed topic does, image_raw/compressed
// (sensor_msgs/CompressedImage, PNG: lossless), with their camera_info and depth.
#include <cmath>
#include <cstring>

#include "ros2_presentation/sensor_messages.h"
#include "sensors/camera/camera.h"
#include "sensors/camera/png.h"

namespace sanet::ros2_presentation {
namespace {

using msg::sensor_msgs::CameraInfo;
using msg::sensor_msgs::CompressedImage;
using msg::sensor_msgs::Image;

enum Topic : std::size_t { kImage, kInfo, kCompressed, kDepth };

// The pinhole of square pixels over `fov`, its axis through the picture's middle (pixel centres at
// whole coordinates, as image_geometry counts them).
CameraInfo InfoOf(const sensors::CameraSettings& s) {
  CameraInfo info;
  info.width = static_cast<std::uint32_t>(s.width), info.height = static_cast<std::uint32_t>(s.height);
  info.distortion_model = "plumb_bob";
  info.d.assign(5, 0.0);
  const double f = s.width / 2.0 / std::tan(s.fov / 2), cx = (s.width - 1) / 2.0, cy = (s.height - 1) / 2.0;
  info.k = {f, 0, cx, 0, f, cy, 0, 0, 1};
  info.r = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  info.p = {f, 0, cx, 0, 0, f, cy, 0, 0, 0, 1, 0};
  return info;
}

// The picture as image_transport's compressed topic carries it, PNG.
CompressedImage Png(const msg::std_msgs::Header& header, const ImageReading& picture) {
  CompressedImage m;
  m.header = header;
  m.format = "png";
  m.data = sensors::EncodePng(picture);
  return m;
}

// Metres along the axis as 32FC1: little-endian floats, as this machine and ROS's tools keep them.
Image DepthImage(const Image& like, const ImageReading& picture) {
  Image depth;
  depth.header = like.header;
  depth.width = like.width, depth.height = like.height, depth.encoding = "32FC1", depth.step = like.width * 4;
  depth.data.resize(picture.depth.size() * 4);
  std::memcpy(depth.data.data(), picture.depth.data(), depth.data.size());
  return depth;
}

class CameraMessages : public SensorMessages {
 public:
  std::vector<SensorTopic> Topics(const std::string& instance, const std::any& settings) const override {
    std::vector<SensorTopic> topics = {FaceTopicFor<Image>(instance + "/image_raw"),
                                       TopicFor<CameraInfo>(instance + "/camera_info"),
                                       RecordTopicFor<CompressedImage>(instance + "/image_raw/compressed")};
    if (std::any_cast<const sensors::CameraSettings&>(settings).depth)
      topics.push_back(TopicFor<Image>(instance + "/depth/image_raw"));
    return topics;
  }
  std::vector<SensorMessage> Messages(const std::string& instance, const std::any& settings,
                                      const SensorReading& reading, const MessageContext& context) const override {
    const auto& picture = std::get<ImageReading>(reading);
    const auto& s = std::any_cast<const sensors::CameraSettings&>(settings);
    const double per_record = context.time * s.record_rate;
    if (context.recording && s.record_rate > 0 && std::fabs(per_record - std::round(per_record)) > 1e-6) return {};
    Image image;
    image.header.stamp = StampOf(context.time);
    image.header.frame_id = context.frames->Sensor(instance + "_optical");
    image.width = static_cast<std::uint32_t>(picture.width), image.height = static_cast<std::uint32_t>(picture.height);
    image.encoding = picture.encoding;
    image.step = image.width * 3;
    CameraInfo info = InfoOf(s);
    info.header = image.header;
    std::vector<SensorMessage> out = {MessageOn(kInfo, info)};
    if (context.recording) {
      out.push_back(MessageOn(kCompressed, Png(image.header, picture)));
    } else {
      image.data = picture.data;
      out.push_back(MessageOn(kImage, image));
    }
    if (s.depth && !picture.depth.empty()) out.push_back(MessageOn(kDepth, DepthImage(image, picture)));
    return out;
  }
  void Mounts(const std::string& instance, const std::any& settings, const RobotFrames& frames, double t,
              std::vector<msg::geometry_msgs::TransformStamped>& out) const override {
    const auto& s = std::any_cast<const sensors::CameraSettings&>(settings);
    auto mount = Transform(frames.base, frames.Sensor(instance), t, s.mount_x, s.mount_y, s.mount_z, 0);
    mount.transform.rotation.y = std::sin(s.pitch / 2), mount.transform.rotation.w = std::cos(s.pitch / 2);
    out.push_back(mount);
    auto optical = Transform(frames.Sensor(instance), frames.Sensor(instance + "_optical"), t, 0, 0, 0, 0);
    optical.transform.rotation.x = -0.5, optical.transform.rotation.y = 0.5;  // z ahead, x right, y down
    optical.transform.rotation.z = -0.5, optical.transform.rotation.w = 0.5;
    out.push_back(optical);
  }
};

}  // namespace

const SensorMessages& CameraSensorMessages() {
  static const CameraMessages messages;
  return messages;
}

}  // namespace sanet::ros2_presentation
