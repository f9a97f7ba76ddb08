// The camera's keys in a scenario.
#include <cmath>

#include "scenario/sensor_fields.h"
#include "sensors/camera/camera.h"

namespace sanet::scenario {
namespace {

using sensors::CameraSettings;

const Fields<CameraSettings>& CameraFields() {
  static const Fields<CameraSettings> fields = [] {
    Fields<CameraSettings> f;
    f.Whole<int>("width", Member(&CameraSettings::width), "pixels", 1, 4096, "of the picture");
    f.Whole<int>("height", Member(&CameraSettings::height), "pixels", 1, 4096, "of the picture");
    f.Number("fov", Member(&CameraSettings::fov), "rad", 0, 3.1, "horizontal field of view (square pixels)", true);
    f.Number("rate", Member(&CameraSettings::rate), "Hz", 0, 1000, "pictures a second, on the simulated clock", true);
    f.Number("mount_x", Member(&CameraSettings::mount_x), "m", -10, 10,
             "the optical centre ahead of the reference point")
        .DefaultSaid("the front of the body (0.18 on a diffdrive, 0.19 on an omni3)");
    f.Number("mount_y", Member(&CameraSettings::mount_y), "m", -10, 10,
             "the optical centre left of the reference point");
    f.Number("mount_z", Member(&CameraSettings::mount_z), "m", 0, 100, "the optical centre above the ground")
        .DefaultSaid("5 cm above the body (0.32 on a diffdrive, 0.27 on an omni3)");
    f.Number("pitch", Member(&CameraSettings::pitch), "rad", -1.5707963267948966, 1.5707963267948966,
             "down from level");
    f.Number("near", Member(&CameraSettings::near), "m", 0, 10, "nothing nearer is drawn", true);
    f.Number("far", Member(&CameraSettings::far), "m", 0, 1e5, "nothing farther is drawn", true);
    f.Flag("depth", Member(&CameraSettings::depth), "also a depth image (m along the optical axis)");
    f.Number("noise", Member(&CameraSettings::noise), "levels", 0, 255,
             "standard deviation of each channel of each pixel (of 255), as a sensor's read noise");
    f.Number("record_rate", Member(&CameraSettings::record_rate), "Hz", 0, 1000,
             "pictures a second in trace.mcap (compressed, PNG); `0`: every picture; must divide `rate`");
    return f;
  }();
  return fields;
}

// The keys, and the clipping planes in order.
class CameraKeys : public DeclaredKeys<CameraSettings> {
 public:
  CameraKeys() : DeclaredKeys(CameraFields()) {}
  void Read(const Field& field, std::any& settings) const override {
    DeclaredKeys::Read(field, settings);
    const auto& s = std::any_cast<const CameraSettings&>(settings);
    if (s.record_rate > 0) {
      const double every = s.rate / s.record_rate;  // pictures per recorded one
      if (std::fabs(every - std::round(every)) > 1e-9 || every < 1)
        field.Require("record_rate")
            .Fail("must divide `rate` (" + ShortNumber(s.rate) +
                  " Hz) a whole number of times, so that the "
                  "recorded pictures are taken ones");
    }
    if (s.far <= s.near) {
      const auto far = field.Get("far");
      (far ? *far : field.Require("near")).Fail("`far` must be beyond `near` (" + ShortNumber(s.near) + " m)");
    }
  }
};

}  // namespace

const SensorFields& CameraSensorFields() {
  static const CameraKeys keys;
  return keys;
}

}  // namespace sanet::scenario
