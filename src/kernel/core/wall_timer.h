// Adds the wall time of a scope to a running total (the run's profile: each stage, each trace
// file's writing).
#pragma once

#include <chrono>

namespace sanet {

class WallTimer {
 public:
  explicit WallTimer(double& total) : total_(total), start_(std::chrono::steady_clock::now()) {}
  ~WallTimer() { total_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }
  WallTimer(const WallTimer&) = delete;
  WallTimer& operator=(const WallTimer&) = delete;

 private:
  double& total_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace sanet
