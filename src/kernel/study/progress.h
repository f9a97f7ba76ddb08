// A sweep's progress on stderr: on a terminal one line, redrawn, with runs done, running, failed
// and the time left; otherwise a line per run that ends.
#pragma once

#include <string>

#include "study/sweep.h"

namespace sanet::study {

class Progress {
 public:
  explicit Progress(bool quiet);
  ~Progress();
  SweepEvents Events();

 private:
  void Changed(const SweepTally& t, int running, int queued);
  void Ended(const std::string& name, const std::string& status, double wall_s);
  bool quiet_, terminal_;
  double started_, last_draw_ = 0;
  double wall_sum_ = 0;  // of the runs ended in this sweep
  int ended_ = 0, jobs_seen_ = 1;
  bool drawn_ = false;
};

}  // namespace sanet::study
