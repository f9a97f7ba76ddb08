// A run's camera pictures for the viewer: the compressed pictures trace.mcap records
// (/<robot>/camera/image_raw/compressed and named cameras' .../image_raw/compressed, PNG, at each
// camera's record_rate), read once, on the first ask, and kept by robot and time.
#pragma once

#include <cstdint>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace sanet::view {

class CameraFrames {
 public:
  explicit CameraFrames(std::string mcap_path) : path_(std::move(mcap_path)) {}
  // {robot: [times, s]} of the pictures there are; {} without trace.mcap or pictures.
  nlohmann::json Times();
  // The robot's latest picture at or before `t` (s): its format ("png") and bytes.
  std::optional<std::pair<std::string, std::vector<std::uint8_t>>> At(const std::string& robot, double t);

 private:
  struct Frame {
    double t;
    std::string format;
    std::vector<std::uint8_t> data;
  };
  void Load();  // under mutex_

  std::string path_;
  std::mutex mutex_;  // the server answers on several threads
  bool loaded_ = false;
  std::map<std::string, std::vector<Frame>> frames_;  // by robot, in time order
};

}  // namespace sanet::view
