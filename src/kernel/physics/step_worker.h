// A second thread that runs work in the order it was launched, for the thread that launches it
// (the physics steps, while ns-3 processes the network on the launching thread). Or, with one
// thread, the same work run at once on the launching thread: the results are the same either
// way, since the launching thread waits for the work before it touches anything the work
// touches.
//
// Up to `depth` pieces may be queued, so that the launching thread can run ahead through a
// stretch where it has little to do while the worker catches up, and the worker through one
// where the launching thread is busy. The hand-off has to cost about a microsecond (on the
// help-request scenario a physics step is about 7 µs of work every 5 ms of simulated time, some
// 20 µs of wall time): both sides spin on atomics while the other is about to answer, and sleep
// on a condition variable once they have waited a little longer than that, so that a run on a
// machine without a free core for each thread does not spin its partner's time away.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace sanet::physics {

class StepWorker {
 public:
  // `threaded`: run the work on a thread of its own; otherwise at once, in Launch.
  StepWorker(bool threaded, std::size_t depth);
  ~StepWorker();
  StepWorker(const StepWorker&) = delete;
  StepWorker& operator=(const StepWorker&) = delete;

  bool threaded() const { return thread_.joinable(); }

  // Queues `work` behind what is queued (waiting first while `depth` pieces are) and returns its
  // number: 1 for the first piece, then 2, 3 ...
  std::uint64_t Launch(std::function<void()> work);
  // Returns once every launched piece is done, rethrowing (once) what one threw. At once on the
  // worker's own thread (where the work itself may touch what Wait guards).
  void Wait() { WaitFor(launched_.load(std::memory_order_relaxed)); }
  // Returns once piece `number` and those before it are done.
  void WaitFor(std::uint64_t number);
  // Wall time the launching thread has spent waiting for the worker (s).
  double waited() const { return waited_; }

 private:
  void Loop();
  // Waits until `counter` reaches `below`, spinning for `spin` seconds (which it adapts) and then
  // announcing sleep in `asleep` and sleeping; false when the worker is to stop (only with
  // `stop_on_request`).
  bool AwaitChange(const std::atomic<std::uint64_t>& counter, std::uint64_t below, std::atomic<bool>& asleep,
                   bool stop_on_request, double& spin);
  void Wake(const std::atomic<bool>& asleep);

  std::vector<std::function<void()>> slots_;  // piece n in slots_[(n - 1) % depth]
  std::exception_ptr error_;                  // written by the worker before failed_
  std::atomic<bool> failed_{false};
  bool reported_ = false;  // the launcher has rethrown it
  std::atomic<std::uint64_t> launched_{0}, finished_{0};
  std::atomic<bool> worker_asleep_{false}, launcher_asleep_{false};
  bool stopping_ = false;  // guarded by mutex_
  std::mutex mutex_;
  std::condition_variable changed_;
  double waited_ = 0;
  double launcher_spin_ = 200e-6;  // s, the launcher's current spin before sleeping
  std::thread thread_;
};

}  // namespace sanet::physics
