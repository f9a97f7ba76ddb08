#include "physics/step_worker.h"

#include <pthread.h>

#include <chrono>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define SANET_CPU_RELAX() _mm_pause()
#else
#define SANET_CPU_RELAX() std::this_thread::yield()
#endif

namespace sanet::physics {
namespace {

thread_local bool t_on_worker = false;

// How long a side spins before it yields (the launcher) or sleeps (the worker): a few physics
// steps' worth of wall time, so that a run's hand-offs never sleep while both sides are busy.
constexpr auto kSpin = std::chrono::microseconds(200);

// Spins on `done` until it holds, for kSpin, then yields the processor between checks.
template <typename Done>
void SpinUntil(Done done) {
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; !done(); ++i) {
    if (i < 64 || std::chrono::steady_clock::now() - start < kSpin)
      SANET_CPU_RELAX();
    else
      std::this_thread::yield();
  }
}

}  // namespace

StepWorker::StepWorker(bool threaded, std::size_t depth) : slots_(depth < 1 ? 1 : depth) {
  if (threaded) thread_ = std::thread([this] { Loop(); });
}

StepWorker::~StepWorker() {
  if (!threaded()) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_one();
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
  // The worker announces sleep before it checks launched_ a last time under the lock, so either
  // it sees this launch or this thread sees it sleeping (both sides use seq_cst).
  if (sleeping_.load(std::memory_order_seq_cst)) {
    std::lock_guard<std::mutex> lock(mutex_);
    wake_.notify_one();
  }
  return number;
}

void StepWorker::WaitFor(std::uint64_t number) {
  if (t_on_worker) return;
  if (finished_.load(std::memory_order_acquire) < number) {
    const auto start = std::chrono::steady_clock::now();
    SpinUntil([&] { return finished_.load(std::memory_order_acquire) >= number; });
    waited_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  if (failed_.load(std::memory_order_acquire)) std::rethrow_exception(error_);
}

// Spins a while for the next launch, then sleeps until it comes; false when stopping.
bool StepWorker::AwaitLaunch(std::uint64_t seen) {
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; launched_.load(std::memory_order_acquire) == seen; ++i) {
    if (i < 64 || std::chrono::steady_clock::now() - start < kSpin) {
      SANET_CPU_RELAX();
      continue;
    }
    std::unique_lock<std::mutex> lock(mutex_);
    sleeping_.store(true, std::memory_order_seq_cst);
    wake_.wait(lock, [&] { return stopping_ || launched_.load(std::memory_order_seq_cst) != seen; });
    sleeping_.store(false, std::memory_order_relaxed);
    if (stopping_) return false;
  }
  return true;
}

void StepWorker::Loop() {
  t_on_worker = true;
  pthread_setname_np(pthread_self(), "sanet-physics");  // as top and perf show it
  for (std::uint64_t done = 0; AwaitLaunch(done);) {
    std::function<void()>& work = slots_[done % slots_.size()];
    // After a failure the rest is skipped: the launching thread rethrows it at its next wait.
    if (!failed_.load(std::memory_order_relaxed)) try {
        work();
      } catch (...) {
        error_ = std::current_exception();
        failed_.store(true, std::memory_order_release);
      }
    work = nullptr;
    finished_.store(++done, std::memory_order_release);
  }
}

}  // namespace sanet::physics
