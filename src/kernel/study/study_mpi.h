// Sweeps under MPI (`mpirun -n K sanet sweep ...`, or Slurm's srun): rank 0 plans the study,
// keeps its database and runs its share; every other rank asks rank 0 for runs, runs each from
// a copy of its effective scenario in a temporary folder, and sends the results folder back to
// rank 0, which files it as its own runs' (no shared file system needed). Without MPI, a sweep
// runs its runs as child processes of this one.
#pragma once

#include <memory>
#include <string>

#include "study/executor.h"

namespace sanet::study {

// Started by mpirun or srun (their environment says so).
bool UnderMpi();
// Rank 0, or no MPI at all.
bool IsMpiCoordinator();
// A rank other than 0: runs what rank 0 sends, `jobs` at a time, until it says the study is
// over. Returns the exit code.
int ServeAsMpiWorker(int jobs);
// `jobs` child processes here, and under MPI the other ranks' too.
std::unique_ptr<Executor> MakeExecutor(int jobs);
// "2 at a time", "on 3 MPI ranks (1 at a time each)".
std::string Describe(const Executor& executor);

}  // namespace sanet::study
