// A finished run's trace.mcap as a Foxglove stream (`sanet view RESULTS`): its channels advertised
// as they are in the file, and its messages in time order at `speed` times the simulated pace, with
// the `time` capability's time messages so that Foxglove's timeline plays it (in the file's order,
// which is time order for sanet's logs). The replay starts
// when a client has connected (and had half a second to subscribe), plays to the end once, and
// starts again for the next client that connects once everyone has left.
#pragma once

#include <atomic>
#include <functional>
#include <string>
#include <thread>

#include "foxglove/foxglove_hub.h"
#include "trace/mcap_reader.h"

namespace sanet::foxglove {

class McapReplay {
 public:
  // Reads `path` through once (throws std::runtime_error naming what is wrong), advertises its
  // channels, and plays on its own thread, reading the file again at each play.
  McapReplay(const std::string& path, FoxgloveHub& hub, double speed);
  ~McapReplay();
  std::uint64_t messages() const { return messages_; }
  std::uint64_t plays() const { return plays_; }

 private:
  void Serve();
  bool Play();  // false when stopped or when every client left

  std::string path_;
  std::uint64_t messages_ = 0, first_ = 0, last_ = 0;  // ns
  FoxgloveHub& hub_;
  double speed_;
  std::atomic<bool> stop_{false};
  std::atomic<std::uint64_t> plays_{0};
  std::thread thread_;
};

}  // namespace sanet::foxglove
