#include "view/camera_frames.h"

#include <algorithm>
#include <filesystem>
#include <map>

#include "ros2msg/codec.h"
#include "trace/mcap_reader.h"

namespace sanet::view {
namespace {

constexpr const char* kSuffix = "/image_raw/compressed";
constexpr std::size_t kMostBytes = std::size_t{512} << 20;  // of pictures kept: later ones are left out

// "/rover/camera/image_raw/compressed" -> "rover" (the robot's name as the log writes it).
std::string RobotOf(const std::string& topic) { return topic.substr(1, topic.find('/', 1) - 1); }

}  // namespace

void CameraFrames::Load() {
  loaded_ = true;
  if (!std::filesystem::exists(path_)) return;
  std::map<std::uint16_t, std::string> robots;  // channel -> robot
  trace::McapVisitor visit;
  visit.channel = [&](const trace::McapChannel& c) {
    const std::size_t n = c.topic.size(), k = std::string(kSuffix).size();
    if (c.schema_name == "sensor_msgs/msg/CompressedImage" && n > k && c.topic.compare(n - k, k, kSuffix) == 0)
      robots[c.id] = RobotOf(c.topic);
  };
  std::size_t kept = 0;
  visit.message = [&](const trace::McapMessage& m) {
    const auto robot = robots.find(m.channel);
    if (robot == robots.end()) return true;
    if (auto picture = ros2msg::Decode<ros2msg::sensor_msgs::CompressedImage>(m.data)) {
      kept += picture->data.size();
      frames_[robot->second].push_back({m.log_time / 1e9, picture->format, std::move(picture->data)});
    }
    return kept < kMostBytes;
  };
  try {
    trace::ReadMcap(path_, visit);
  } catch (const std::exception&) {
    // A file cut short (a run killed): the pictures before the cut are shown.
  }
  for (auto& [robot, frames] : frames_)
    std::stable_sort(frames.begin(), frames.end(), [](const Frame& a, const Frame& b) { return a.t < b.t; });
}

nlohmann::json CameraFrames::Times() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!loaded_) Load();
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [robot, frames] : frames_) {
    nlohmann::json times = nlohmann::json::array();
    for (const Frame& f : frames) times.push_back(f.t);
    out[robot] = times;
  }
  return out;
}

std::optional<std::pair<std::string, std::vector<std::uint8_t>>> CameraFrames::At(const std::string& robot, double t) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!loaded_) Load();
  const auto it = frames_.find(robot);
  if (it == frames_.end()) return std::nullopt;
  const auto after = std::upper_bound(it->second.begin(), it->second.end(), t + 1e-9,
                                      [](double time, const Frame& f) { return time < f.t; });
  if (after == it->second.begin()) return std::nullopt;
  const Frame& f = *std::prev(after);
  return std::make_pair(f.format, f.data);
}

}  // namespace sanet::view
