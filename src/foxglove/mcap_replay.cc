#include "foxglove/mcap_replay.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

namespace sanet::foxglove {
namespace {

using Clock = std::chrono::steady_clock;
constexpr std::uint64_t kTimeEvery = 50000000;  // ns of simulated time between time messages

}  // namespace

McapReplay::McapReplay(const std::string& path, FoxgloveHub& hub, double speed)
    : log_(trace::ReadMcap(path)), hub_(hub), speed_(speed) {
  if (!(speed > 0)) throw std::invalid_argument("the replay's speed must be above 0");
  if (log_.profile != "ros2")
    throw std::runtime_error(path + " holds '" + log_.profile + "' messages, not ROS 2 ones (profile ros2)");
  std::stable_sort(log_.messages.begin(), log_.messages.end(),
                   [](const auto& a, const auto& b) { return a.log_time < b.log_time; });
  for (const auto& c : log_.channels)
    hub_.Advertise({c.id, c.topic, c.schema_name, c.schema, c.topic == "/tf_static" || c.topic == "/world"});
  thread_ = std::thread([this] { Serve(); });
}

McapReplay::~McapReplay() {
  stop_ = true;
  thread_.join();
}

void McapReplay::Serve() {
  const auto wait = [this](auto done) {
    while (!stop_ && !done()) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  };
  while (!stop_) {
    wait([this] { return hub_.clients() > 0; });
    std::this_thread::sleep_for(std::chrono::milliseconds(500));  // time to subscribe
    if (!stop_ && Play()) ++plays_;
    wait([this] { return hub_.clients() == 0; });
  }
}

bool McapReplay::Play() {
  if (log_.messages.empty()) return true;
  const std::uint64_t first = log_.messages.front().log_time;
  const Clock::time_point start = Clock::now();
  std::uint64_t next_time = first;
  for (const auto& m : log_.messages) {
    const auto due = start + std::chrono::nanoseconds(static_cast<std::int64_t>((m.log_time - first) / speed_));
    while (Clock::now() < due) {
      if (stop_ || hub_.clients() == 0) return false;
      std::this_thread::sleep_until(std::min(due, Clock::now() + std::chrono::milliseconds(20)));
    }
    if (m.log_time >= next_time) {
      hub_.Time(m.log_time);
      next_time = m.log_time + kTimeEvery;
    }
    hub_.Publish(m.channel, m.log_time, m.data);
  }
  hub_.Time(log_.messages.back().log_time);
  return true;
}

}  // namespace sanet::foxglove
