#include "terminal_progress.h"

#include <cstdio>

namespace sanet::cli {

TerminalProgress::~TerminalProgress() {
  if (drawn_) std::fprintf(stderr, "\r%78s\r", "");
}

std::function<void(const sim::RunProgress&)> TerminalProgress::Callback() {
  if (!show_) return nullptr;
  return [this](const sim::RunProgress& p) {
    std::fprintf(stderr, "\r  t = %.1f / %.1f s   %.1fx real time   ETA %.0f s   ", p.time, p.duration,
                 p.real_time_factor, p.eta);
    std::fflush(stderr);
    drawn_ = true;
  };
}

}  // namespace sanet::cli
