// A run's progress on a terminal: one line, redrawn, with simulated time, real-time factor and
// ETA (sim prints nothing itself; it calls RunOptions::progress). The line is cleared at the end.
#pragma once

#include <functional>

#include "sim/world.h"

namespace sanet::cli {

class TerminalProgress {
 public:
  // Shows nothing unless `show` (not quiet, not --no-progress, stderr a terminal).
  explicit TerminalProgress(bool show) : show_(show) {}
  ~TerminalProgress();  // clears the line
  // For RunOptions::progress; nullptr when nothing is shown.
  std::function<void(const sim::RunProgress&)> Callback();

 private:
  bool show_, drawn_ = false;
};

}  // namespace sanet::cli
