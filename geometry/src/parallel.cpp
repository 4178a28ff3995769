#include "kerf/geometry/parallel.h"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace kerf::geometry {
namespace {

/// Set while a thread runs a piece of runBesideWhenIdle's: a parallelFor there runs serially (the
/// kept threads it would use are the ones that run such pieces).
thread_local bool besideWhenIdle = false;

/// Threads kept for parallelFor while a ParallelScope lives: a check calls it a score of times,
/// and a thread made and ended for each call cost more than some of the calls' work (and moved the
/// caller between cores). One call at a time uses them; a call made while they are busy (from
/// inside a body, or from another thread) makes threads of its own.
class Helpers {
 public:
  /// Pieces of work the kept threads take while no call needs them (runBesideWhenIdle): one at a
  /// time, each to its end, so that a call waits for a helper at most one piece.
  struct Background {
    Background(const std::function<void(std::size_t)>& work, std::size_t count) : piece(work), pieces(count) {}
    const std::function<void(std::size_t)>& piece;
    const std::size_t pieces;
    std::atomic<std::size_t> next{0};
    std::atomic<bool> failed{false};
    std::mutex failureMutex;
    std::exception_ptr failure;  // the first piece's exception, guarded by failureMutex
    /// Takes and runs one piece; false when none is left or one has thrown.
    bool runOne() {
      if (failed.load(std::memory_order_relaxed)) return false;
      const std::size_t k = next.fetch_add(1, std::memory_order_relaxed);
      if (k >= pieces) return false;
      try {
        piece(k);
      } catch (...) {
        failed.store(true, std::memory_order_relaxed);
        const std::lock_guard<std::mutex> lock(failureMutex);
        if (!failure) failure = std::current_exception();
      }
      return true;
    }
    [[nodiscard]] bool left() const {
      return !failed.load(std::memory_order_relaxed) && next.load(std::memory_order_relaxed) < pieces;
    }
  };

  explicit Helpers(std::size_t count) {
    threads_.reserve(count);
    try {
      for (std::size_t i = 1; i <= count; ++i) threads_.emplace_back([this, i] { serve(i); });
    } catch (...) {  // fewer threads than asked: calls that need more make their own
    }
  }
  Helpers(const Helpers&) = delete;
  Helpers& operator=(const Helpers&) = delete;
  ~Helpers() {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
      ++generation_;
    }
    wake_.notify_all();
    for (std::thread& t : threads_) t.join();
  }

  [[nodiscard]] std::size_t size() const { return threads_.size(); }

  /// Runs task(0) here and task(1) .. task(workers - 1) on the kept threads; false (nothing run)
  /// when they are busy or too few.
  bool run(std::size_t workers, const std::function<void(std::size_t)>& task) {
    if (workers - 1 > threads_.size()) return false;
    bool idle = false;
    if (!busy_.compare_exchange_strong(idle, true)) return false;  // a call from inside a body
    struct Release {
      std::atomic<bool>& flag;
      ~Release() { flag.store(false); }
    } release{busy_};
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      task_ = &task;
      active_ = workers - 1;
      pending_ = workers - 1;
      ++generation_;
    }
    wake_.notify_all();
    task(0);
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [&] { return pending_ == 0; });
    task_ = nullptr;
    return true;
  }

  /// The kept threads take background's pieces while no call needs them, until stopBackground.
  /// One background at a time: false (nothing started) when another is on.
  bool startBackground(Background& background) {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      if (background_ != nullptr) return false;
      background_ = &background;
    }
    wake_.notify_all();
    return true;
  }
  /// No piece starts on the kept threads after this; returns once the ones running have ended.
  void stopBackground() {
    std::unique_lock<std::mutex> lock(mutex_);
    background_ = nullptr;
    backgroundDone_.wait(lock, [&] { return inBackground_ == 0; });
  }

 private:
  void serve(std::size_t index) {
    std::uint64_t seen = 0;
    for (;;) {
      const std::function<void(std::size_t)>* task = nullptr;
      Background* background = nullptr;
      {
        std::unique_lock<std::mutex> lock(mutex_);
        wake_.wait(lock,
                   [&] { return stop_ || generation_ != seen || (background_ != nullptr && background_->left()); });
        if (stop_) return;
        if (generation_ != seen) {
          seen = generation_;
          if (index > active_) continue;
          task = task_;
        } else {
          background = background_;
          ++inBackground_;
        }
      }
      if (background != nullptr) {
        besideWhenIdle = true;  // a parallelFor inside a piece runs here, serially
        (void)background->runOne();
        besideWhenIdle = false;
        const std::lock_guard<std::mutex> lock(mutex_);
        if (--inBackground_ == 0) backgroundDone_.notify_all();
        continue;
      }
      if (task == nullptr) continue;
      (*task)(index);
      const std::lock_guard<std::mutex> lock(mutex_);
      if (--pending_ == 0) done_.notify_one();
    }
  }

  std::vector<std::thread> threads_;
  std::atomic<bool> busy_{false};  // one call at a time
  std::mutex mutex_;               // what follows
  std::condition_variable wake_, done_, backgroundDone_;
  const std::function<void(std::size_t)>* task_ = nullptr;
  std::size_t active_ = 0, pending_ = 0;
  std::uint64_t generation_ = 0;
  bool stop_ = false;
  Background* background_ = nullptr;
  std::size_t inBackground_ = 0;  // kept threads inside a background piece
};

// The scope's threads, made at the first call that needs them (a short program needs none); calls
// take a share of them for as long as they use them.
std::mutex scopeMutex;
bool scopeOpen = false;                 // guarded by scopeMutex
std::shared_ptr<Helpers> scopeHelpers;  // guarded by scopeMutex

std::shared_ptr<Helpers> currentHelpers() {
  const std::lock_guard<std::mutex> lock(scopeMutex);
  if (scopeOpen && !scopeHelpers) {
    try {
      scopeHelpers = std::make_shared<Helpers>(workerCount() - 1);
    } catch (...) {  // no threads to keep: the calls make their own
      scopeOpen = false;
    }
  }
  return scopeHelpers;
}

}  // namespace

unsigned workerCount() {
  if (const char* env = std::getenv("KERF_THREADS")) {
    char* end = nullptr;
    const long v = std::strtol(env, &end, 10);
    if (end != env && *end == '\0' && v >= 1) return static_cast<unsigned>(std::min(v, 256L));
  }
  // The cores once: libstdc++ asks the system each time (glibc reads /sys/devices/system/cpu/online,
  // three system calls), and a check calls this before each of its parallel passes, 50 times on a
  // long program (about 0.3 ms, most of it on the main thread between the passes).
  static const unsigned cores = std::clamp(std::thread::hardware_concurrency(), 1u, 16u);
  return cores;
}

void parallelFor(std::size_t n, std::size_t minChunk, const std::function<void(std::size_t, std::size_t)>& body) {
  const std::size_t chunk = std::max<std::size_t>(minChunk, 1);
  const std::size_t workers = besideWhenIdle ? 1 : std::min<std::size_t>(workerCount(), n / chunk);
  if (workers <= 1) {
    if (n > 0) body(0, n);
    return;
  }
  // Contiguous, nearly equal ranges: one per worker, the calling thread taking the first.
  std::exception_ptr failure;
  std::mutex failureMutex;
  auto run = [&](std::size_t w) {
    const std::size_t begin = n * w / workers, end = n * (w + 1) / workers;
    try {
      body(begin, end);
    } catch (...) {
      const std::lock_guard<std::mutex> lock(failureMutex);
      if (!failure) failure = std::current_exception();
    }
  };
  if (const std::shared_ptr<Helpers> kept = currentHelpers(); kept && kept->run(workers, run)) {
    if (failure) std::rethrow_exception(failure);
    return;
  }
  std::vector<std::thread> threads;
  threads.reserve(workers - 1);
  try {
    for (std::size_t w = 1; w < workers; ++w) threads.emplace_back(run, w);
  } catch (...) {  // no thread to be had: what was not started runs here
    for (std::size_t w = threads.size() + 1; w < workers; ++w) run(w);
  }
  run(0);
  for (std::thread& t : threads) t.join();
  if (failure) std::rethrow_exception(failure);
}

void parallelForBalanced(std::size_t n, std::size_t minChunk,
                         const std::function<void(std::size_t, std::size_t)>& body) {
  const std::size_t chunk = std::max<std::size_t>(minChunk, 1);
  const std::size_t workers = besideWhenIdle ? 1 : std::min<std::size_t>(workerCount(), n / chunk);
  if (workers <= 1) {
    if (n > 0) body(0, n);
    return;
  }
  constexpr std::size_t kPiecesPerWorker = 4;
  const std::size_t pieces = std::min(n / chunk, workers * kPiecesPerWorker);
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  // One call of parallelFor's body a worker; each takes pieces until none is left. After a
  // piece throws, the others take no more (parallelFor rethrows the first).
  parallelFor(workers, 1, [&](std::size_t, std::size_t) {
    while (!failed.load(std::memory_order_relaxed)) {
      const std::size_t piece = next.fetch_add(1, std::memory_order_relaxed);
      if (piece >= pieces) return;
      try {
        body(n * piece / pieces, n * (piece + 1) / pieces);
      } catch (...) {
        failed.store(true, std::memory_order_relaxed);
        throw;
      }
    }
  });
}

ParallelScope::ParallelScope() {
  const std::lock_guard<std::mutex> lock(scopeMutex);
  if (scopeOpen || scopeHelpers || workerCount() < 2) return;  // an outer scope, or no threads needed
  scopeOpen = true;
  owner_ = true;
}

ParallelScope::~ParallelScope() {
  std::shared_ptr<Helpers> last;
  {
    const std::lock_guard<std::mutex> lock(scopeMutex);
    if (!owner_) return;
    scopeOpen = false;
    last.swap(scopeHelpers);
  }
  // The threads end here, or when the last call using them returns.
}

void parallelInvoke(const std::function<void()>& first, const std::function<void()>& second) {
  const std::function<void()>* tasks[] = {&first, &second};
  parallelFor(2, 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) (*tasks[k])();
  });
}

void runBesideWhenIdle(const std::function<void()>& main, std::size_t pieces,
                       const std::function<void(std::size_t)>& piece) {
  Helpers::Background background(piece, pieces);
  auto takeHere = [&] {
    const bool was = besideWhenIdle;
    besideWhenIdle = true;
    while (background.runOne()) {
    }
    besideWhenIdle = was;
  };
  auto rethrowPiece = [&] {
    if (background.failure) std::rethrow_exception(background.failure);
  };
  // One piece is not worth a thread: a short program (the summary of fewer than 4,096 moves) makes none.
  const std::shared_ptr<Helpers> kept = workerCount() >= 2 && pieces > 1 ? currentHelpers() : nullptr;
  if (kept && kept->size() > 0 && kept->startBackground(background)) {
    std::exception_ptr mainFailure;
    try {
      main();
    } catch (...) {
      mainFailure = std::current_exception();
      background.failed.store(true, std::memory_order_relaxed);
    }
    if (!mainFailure) takeHere();
    kept->stopBackground();
    if (mainFailure) std::rethrow_exception(mainFailure);
    rethrowPiece();
    return;
  }
  // No kept threads (outside a ParallelScope, or one worker): main, then the pieces, here.
  main();
  takeHere();
  rethrowPiece();
}

}  // namespace kerf::geometry
