#include "foxglove/mcap_replay.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <stdexcept>

namespace sanet::foxglove {
namespace {

using Clock = std::chrono::steady_clock;
constexpr std::uint64_t kTimeEvery = 50000000;  // ns of simulated time between time messages

}  // namespace

McapReplay::McapReplay(const std::string& path, FoxgloveHub& hub, double speed)
    : path_(path), hub_(hub), speed_(speed) {
  if (!(speed > 0)) throw std::invalid_argument("the replay's speed must be above 0");
  std::string profile;
  trace::McapVisitor visit;
  visit.header = [&](const std::string& p) { profile = p; };
  visit.channel = [&](const trace::McapChannel& c) {
    if (c.message_encoding != "cdr" || c.schema_encoding != "ros2msg")
      throw std::runtime_error(path + ": channel " + c.topic + " is not ROS 2 CDR with a ros2msg schema");
    hub_.Advertise({c.id, c.topic, c.schema_name, c.schema, c.topic == "/tf_static" || c.topic == "/world"});
  };
  visit.message = [&](const trace::McapMessage& m) {
    if (messages_++ == 0) first_ = m.log_time;
    last_ = std::max(last_, m.log_time);
    return true;
  };
  trace::ReadMcap(path, visit);
  if (profile != "ros2") throw std::runtime_error(path + " holds '" + profile + "' messages, not ROS 2 ones");
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
    hub_.ForgetLatched();  // the play sends /tf_static and /world itself, at their times
    std::this_thread::sleep_for(std::chrono::milliseconds(500));  // time to subscribe
    if (!stop_ && Play()) ++plays_;
    wait([this] { return hub_.clients() == 0; });
  }
}

bool McapReplay::Play() {
  const Clock::time_point start = Clock::now();
  std::uint64_t next_time = first_;
  trace::McapVisitor visit;
  visit.message = [&](const trace::McapMessage& m) {
    const std::uint64_t since = m.log_time > first_ ? m.log_time - first_ : 0;
    const auto due = start + std::chrono::nanoseconds(static_cast<std::int64_t>(since / speed_));
    while (Clock::now() < due) {
      if (stop_ || hub_.clients() == 0) return false;
      std::this_thread::sleep_until(std::min(due, Clock::now() + std::chrono::milliseconds(20)));
    }
    if (m.log_time >= next_time) {
      hub_.Time(m.log_time);
      next_time = m.log_time + kTimeEvery;
    }
    hub_.Publish(m.channel, m.log_time, m.data);
    return !stop_;
  };
  try {
    if (!trace::ReadMcap(path_, visit)) return false;
  } catch (const std::runtime_error&) {  // the file changed since it was checked: end this play
    return false;
  }
  hub_.Time(last_);
  return true;
}

}  // namespace sanet::foxglove
