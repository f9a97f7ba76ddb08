#include "physics/step_worker.h"

#include <pthread.h>

#include <algorithm>
#include <chrono>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define SANET_CPU_RELAX() _mm_pause()
#else
#define SANET_CPU_RELAX() std::this_thread::yield()
#endif

namespace sanet::physics {
namespace {

thread_local const StepWorker* t_worker = nullptr;  // the worker whose thread this is

// How long a side spins before it sleeps adapts between these: a wait that its spin saw through
// doubles the next spin, a wait that had to sleep halves it. With a free core for each thread
// the waits are short and the hand-offs cost no system call; when the partner is not running
// (fewer free cores than threads, a busy machine) a side soon stops spinning its time away.
constexpr double kSpinMin = 10e-6, kSpinMax = 200e-6;  // s

}  // namespace

// Both sides wait alike: spin on the atomic for a while, then announce sleep and sleep on the
// condition variable. The announcing side re-checks under the lock after announcing; the other
// side changes the atomic before it reads the announcement (both seq_cst), so a wake-up is never
// lost.
bool StepWorker::AwaitChange(const std::atomic<std::uint64_t>& counter, std::uint64_t below, std::atomic<bool>& asleep,
                             bool stop_on_request, double& spin) {
  const auto start = std::chrono::steady_clock::now();
  const auto budget = std::chrono::duration<double>(spin);
  for (int i = 0; counter.load(std::memory_order_acquire) < below; ++i) {
    if (i < 64 || std::chrono::steady_clock::now() - start < budget) {
      SANET_CPU_RELAX();
      continue;
    }
    spin = std::max(kSpinMin, spin / 2);
    std::unique_lock<std::mutex> lock(mutex_);
    asleep.store(true, std::memory_order_seq_cst);
    changed_.wait(lock,
                  [&] { return (stop_on_request && stopping_) || counter.load(std::memory_order_seq_cst) >= below; });
    asleep.store(false, std::memory_order_relaxed);
    if (stop_on_request && stopping_) return false;
    return true;
  }
  spin = std::min(kSpinMax, spin * 2);
  return true;
}

void StepWorker::Wake(const std::atomic<bool>& asleep) {
  if (!asleep.load(std::memory_order_seq_cst)) return;
  std::lock_guard<std::mutex> lock(mutex_);
  changed_.notify_all();
}

StepWorker::StepWorker(bool threaded, std::size_t depth) : slots_(depth < 1 ? 1 : depth) {
  if (threaded) thread_ = std::thread([this] { Loop(); });
}

StepWorker::~StepWorker() {
  if (!threaded()) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

std::uint64_t StepWorker::Launch(std::function<void()> work) {
  const std::uint64_t number = launched_.load(std::memory_order_relaxed) + 1;
  if (!threaded()) {
    work();
    launched_.store(number, std::memory_order_relaxed);
    finished_.store(number, std::memory_order_relaxed);
    return number;
  }
  if (number > slots_.size()) WaitFor(number - slots_.size());  // its slot's previous piece
  slots_[(number - 1) % slots_.size()] = std::move(work);
  launched_.store(number, std::memory_order_seq_cst);
  Wake(worker_asleep_);
  return number;
}

void StepWorker::WaitFor(std::uint64_t number) {
  if (t_worker == this) return;
  if (finished_.load(std::memory_order_acquire) < number) {
    const auto start = std::chrono::steady_clock::now();
    AwaitChange(finished_, number, launcher_asleep_, false, launcher_spin_);
    waited_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  // Once: the waits after it (a run tearing down) must not throw again.
  if (failed_.load(std::memory_order_acquire) && !reported_) {
    reported_ = true;
    std::rethrow_exception(error_);
  }
}

void StepWorker::Loop() {
  t_worker = this;
  pthread_setname_np(pthread_self(), "sanet-physics");  // as top and perf show it
  double spin = kSpinMax;
  for (std::uint64_t done = 0; AwaitChange(launched_, done + 1, worker_asleep_, true, spin);) {
    std::function<void()>& work = slots_[done % slots_.size()];
    // After a failure the rest is skipped: the launching thread rethrows it at its next wait.
    if (!failed_.load(std::memory_order_relaxed)) try {
        work();
      } catch (...) {
        error_ = std::current_exception();
        failed_.store(true, std::memory_order_release);
      }
    work = nullptr;
    finished_.store(++done, std::memory_order_seq_cst);
    Wake(launcher_asleep_);
  }
}

}  // namespace sanet::physics
