// sanet extension: SEN {Time t} {Type Camera} {Name camera} {Width w} {Height h} {Encoding png}
// {Data base64}, the picture as PNG (lossless) in base64 (wire/base64.h), for agents. USARSim serves pictures on an
// image server of its own, not in the robot protocol, so there is no USARSim line to follow. A
// picture whose line would pass kMostLine bytes is not sent (lower the resolution or the noise):
// the agent reads lines of up to 1 MiB, and the server drops a client more than 1 MiB behind.
// Depth does not travel.
#include <stb/stb_image.h>

#include "sensors/camera/camera.h"
#include "sensors/camera/png.h"
#include "wire/base64.h"
#include "wire/sensor_lines.h"

namespace sanet::wire {
namespace {

constexpr std::size_t kMostLine = 256 * 1024;

class CameraLines : public SensorLines {
 public:
  std::vector<ProtocolMessage> Write(const std::string& instance, const SensorReading& reading,
                                     const LineContext& context) const override {
    const auto& picture = std::get<ImageReading>(reading);
    std::string data = Base64(sensors::EncodePng(picture));
    if (data.size() > kMostLine) return {};
    ProtocolMessage line = SenLine(context.time, "Camera");
    line.Add("Name", WireName(instance, "camera", "Camera"))
        .Add("Width", std::to_string(picture.width))
        .Add("Height", std::to_string(picture.height))
        .Add("Encoding", "png")
        .Add("Data", std::move(data));
    return {line};
  }
  bool IsFrom(const ProtocolMessage& line, const std::string& instance) const override {
    return NamesInstance(line, "Camera", instance, "camera", "Camera");
  }
  std::optional<SensorReading> Read(const ProtocolMessage& line, const std::any& /*settings*/,
                                    const LineContext& /*context*/) const override {
    const std::string *encoding = line.Get("Encoding"), *data = line.Get("Data");
    const auto width = line.Count("Width", 4096), height = line.Count("Height", 4096);
    if (!encoding || *encoding != "png" || !data || !width || !height) return std::nullopt;
    const auto png = FromBase64(*data);
    if (!png || png->empty() || png->size() > kMostLine) return std::nullopt;
    int w = 0, h = 0, channels = 0;  // the size the PNG says, before decoding it
    if (!stbi_info_from_memory(png->data(), static_cast<int>(png->size()), &w, &h, &channels) ||
        static_cast<std::uint64_t>(w) != *width || static_cast<std::uint64_t>(h) != *height)
      return std::nullopt;
    stbi_uc* pixels = stbi_load_from_memory(png->data(), static_cast<int>(png->size()), &w, &h, &channels, 3);
    if (!pixels) return std::nullopt;
    ImageReading r;
    r.width = w, r.height = h, r.encoding = "rgb8";
    r.data.assign(pixels, pixels + static_cast<std::size_t>(w) * h * 3);
    stbi_image_free(pixels);
    return r;
  }
  bool Extension() const override { return true; }
};

}  // namespace

const SensorLines& CameraSensorLines() {
  static const CameraLines lines;
  return lines;
}

}  // namespace sanet::wire
