// A finished run's trace.mcap as a Foxglove stream (`sanet view RESULTS`): its channels advertised
// as they are in the file, and its messages in time order at `speed` times the simulated pace, with
// the `time` capability's time messages so that Foxglove's timeline plays it. The replay starts
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
  // Reads `path` whole (throws std::runtime_error naming what is wrong) and plays on its own thread.
  McapReplay(const std::string& path, FoxgloveHub& hub, double speed);
  ~McapReplay();
  std::size_t messages() const { return log_.messages.size(); }
  std::uint64_t plays() const { return plays_; }

 private:
  void Serve();
  bool Play();  // false when stopped or when every client left

  trace::McapContents log_;
  FoxgloveHub& hub_;
  double speed_;
  std::atomic<bool> stop_{false};
  std::atomic<std::uint64_t> plays_{0};
  std::thread thread_;
};

}  // namespace sanet::foxglove
