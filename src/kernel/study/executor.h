// Where a study's runs execute: child processes on this machine (LocalExecutor) or, under MPI,
// on other ranks too (study/mpi_executor.h). Each run is `sanet run ...` in its own process, so
// that a crash or an ns-3 abort takes only that run, and ns-3's process-wide state starts fresh.
#pragma once

#include <sys/types.h>

#include <map>
#include <string>
#include <vector>

#include "core/host_time.h"

namespace sanet::study {

struct RunJob {
  std::string name;
  std::string folder;              // runs/<name>, where its results end up
  std::vector<std::string> args;   // `sanet` arguments: run FILE --set ... -o FOLDER -q
  std::string effective_scenario;  // for ranks that run it from a copy (no shared files needed)
  std::string log;                 // where its output goes (logs/<name>.txt)
};

struct JobEnd {
  std::string name;
  bool completed = false;    // exit status 0
  bool interrupted = false;  // stopped by a signal: to run again
  std::string error;         // when not completed: the end of its output
  std::string host, started_utc, finished_utc;
  double wall_s = 0;
  int rank = 0;
};

class Executor {
 public:
  virtual ~Executor() = default;
  virtual int Free() const = 0;  // runs it can start now
  virtual void Start(const RunJob& job) = 0;
  virtual std::vector<JobEnd> Poll() = 0;  // runs that ended since the last call
  virtual int Running() const = 0;
  virtual void StopAll() = 0;  // stops the running ones; they end as interrupted
};

// Up to `jobs` child processes of this program at once. Children die with their parent.
class LocalExecutor : public Executor {
 public:
  explicit LocalExecutor(int jobs, int rank = 0);
  ~LocalExecutor() override;
  int Free() const override { return jobs_ - Running(); }
  void Start(const RunJob& job) override;
  std::vector<JobEnd> Poll() override;
  int Running() const override { return static_cast<int>(running_.size()); }
  void StopAll() override;
  // Kills the running ones (they end as interrupted, their results unwritten): for a stop that
  // must be over within mpirun's second of grace.
  void StopNow();

 private:
  struct Child {
    RunJob job;
    std::string started_utc;
    double started = 0;  // s, steady clock
  };
  int jobs_, rank_;
  bool stopping_ = false;
  std::map<pid_t, Child> running_;
};

// The last lines of a text file (a failed run's output, for the database).
std::string Tail(const std::string& path, std::size_t bytes = 800);

}  // namespace sanet::study
