#include "study/progress.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>

namespace sanet::study {
namespace {

double Now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

std::string Duration(double s) {
  char text[32];
  if (s < 90)
    std::snprintf(text, sizeof text, "%.0f s", s);
  else if (s < 5400)
    std::snprintf(text, sizeof text, "%.0f min", s / 60);
  else
    std::snprintf(text, sizeof text, "%.1f h", s / 3600);
  return text;
}

}  // namespace

Progress::Progress(bool quiet) : quiet_(quiet), terminal_(isatty(STDERR_FILENO)), started_(Now()) {}

Progress::~Progress() {
  if (drawn_) std::fputc('\n', stderr);
}

SweepEvents Progress::Events() {
  SweepEvents e;
  e.changed = [this](const SweepTally& t, int running, int queued) { Changed(t, running, queued); };
  e.ended = [this](const std::string& name, const std::string& status, double wall) { Ended(name, status, wall); };
  return e;
}

void Progress::Changed(const SweepTally& t, int running, int queued) {
  jobs_seen_ = std::max(jobs_seen_, running);
  if (quiet_ || !terminal_ || Now() - last_draw_ < 0.25) return;
  last_draw_ = Now();
  std::string eta = "";
  if (ended_ > 0 && queued + running > 0)  // runs left, at the pace seen, as many at a time as seen
    eta = ", about " + Duration(wall_sum_ / ended_ * (queued + running) / jobs_seen_) + " left";
  std::fprintf(stderr, "\r\033[K  %d of %d done, %d running, %d failed%s (%s)", t.completed + t.failed, t.total,
               running, t.failed, eta.c_str(), Duration(Now() - started_).c_str());
  std::fflush(stderr);
  drawn_ = true;
}

void Progress::Ended(const std::string& name, const std::string& status, double wall_s) {
  ++ended_;
  wall_sum_ += wall_s;
  if (quiet_ || (terminal_ && status == "completed")) return;
  std::fprintf(stderr, "%s  %s: %s (%.1f s)\n", terminal_ ? "\r\033[K" : "", name.c_str(), status.c_str(), wall_s);
}

}  // namespace sanet::study
