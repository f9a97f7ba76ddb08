// The camera's kernel part: a picture at each sample, rendered where the robot stands then
// (sensors/camera/camera.h).
#include "sensors/camera/camera.h"

#include <algorithm>
#include <cmath>

#include "sensors/camera/offscreen_renderer.h"
#include "sensors/sampling_sensor.h"
#include "sensors/sensor_registry.h"

namespace sanet::sensors {
namespace {

class Camera : public SamplingSensor {
 public:
  Camera(CameraSettings settings, Mount mount)
      : SamplingSensor(settings.rate, mount.world),
        settings_(settings),
        mount_(mount),
        renderer_(settings.width, settings.height) {}

 private:
  SensorReading Sample(double /*period*/) override {
    const Pose2D pose = mount_.model.body().pose();
    const double c = std::cos(pose.theta), s = std::sin(pose.theta);
    CameraView view;
    view.eye = {pose.x + c * settings_.mount_x - s * settings_.mount_y,
                pose.y + s * settings_.mount_x + c * settings_.mount_y, settings_.mount_z};
    view.yaw = pose.theta, view.pitch = settings_.pitch, view.fov = settings_.fov;
    view.near = settings_.near, view.far = settings_.far;
    view.width = settings_.width, view.height = settings_.height;
    const Scenery& scenery = mount_.surroundings.scenery;
    if (scenery.bodies) scenery.bodies(bodies_);
    ImageReading picture;
    renderer_.Render(view, scenery, bodies_, mount_.self, settings_.depth, picture);
    if (settings_.noise > 0) AddNoise(picture.data);
    return picture;
  }

  // A sensor's read noise: each channel of each pixel off by a Gaussian draw, rounded and kept
  // within [0, 255].
  void AddNoise(std::vector<std::uint8_t>& channels) {
    for (std::uint8_t& c : channels) {
      const double v = std::round(c + mount_.random.Gaussian(0, settings_.noise));
      c = static_cast<std::uint8_t>(std::clamp(v, 0.0, 255.0));
    }
  }

  CameraSettings settings_;
  Mount mount_;
  OffscreenRenderer renderer_;
  std::vector<SceneBody> bodies_;  // reused
};

class Cameras : public SensorKind {
 public:
  const SensorInfo& Info() const override {
    static const SensorInfo info{"camera",
                                 "a camera: pictures of the world in its flat colours, and depth, rendered headless",
                                 "ImageReading",
                                 "rgb8 pixels, rows top to bottom; depth in m along the optical axis (+Inf: nothing)",
                                 "sensor_msgs/msg/Image and CameraInfo",
                                 "camera/image_raw"};
    return info;
  }
  std::any DefaultSettings(const robots::ModelSpec& model) const override {
    CameraSettings s;
    const robots::BodyShape shape = model.model().Shape(model);
    s.mount_x = robots::FrontX(model);  // at the front of the body, just above it
    s.mount_z = std::round((shape.base + shape.height + 0.05) * 1000) / 1000;  // mm, so that it prints short
    return s;
  }
  bool SamplesOnItsOwn() const override { return true; }
  std::unique_ptr<SensorInstance> Create(const std::any& settings, Mount mount) const override {
    return std::make_unique<Camera>(std::any_cast<CameraSettings>(settings), mount);
  }
};

}  // namespace

const SensorKind& CameraKind() {
  static const Cameras kind;
  return kind;
}

}  // namespace sanet::sensors
