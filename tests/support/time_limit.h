// A time limit for one test input: if the work it guards spends more than the limit in CPU time (of the
// whole process, every thread), a watchdog thread names the input on stderr and ends the test program with
// exit code 124, so that a hang fails the run (ctest reports it) instead of stalling it, and the input can
// be rerun. CPU time, because long differential runs share the machine with builds and each other: a wall
// limit stopped inputs of 0.1 s that waited at nice 19. A guarded work that blocks without spending CPU
// (a deadlock) is stopped by a wall limit of kWallFactor times the limit. It also measures the time the work
// took, in wall and CPU seconds.
#pragma once

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <mutex>
#include <string>
#include <thread>

namespace apollonius::testing {

// CPU seconds of the whole process so far.
inline double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

class Input_time_limit {
 public:
  static constexpr double kWallFactor = 10;

  Input_time_limit(double seconds, std::string input)
      : input_(std::move(input)), start_(Clock::now()), cpu_start_(process_cpu_seconds()) {
    watchdog_ = std::thread([this, seconds] {
      std::unique_lock<std::mutex> lock(mutex_);
      const Clock::time_point wall_deadline = start_ + to_duration(kWallFactor * seconds);
      // Terminates: each wait ends at the wall deadline at the latest, and past it the loop exits.
      while (!done_) {
        const double cpu = process_cpu_seconds() - cpu_start_;
        const Clock::time_point now = Clock::now();
        if (cpu > seconds) expire("CPU time", seconds);
        if (now >= wall_deadline) expire("wall time", kWallFactor * seconds);
        // The CPU time grows at most as fast as wall time times the threads: half the CPU time left is
        // a short enough wait for two threads, and 1 ms at least keeps the watch cheap.
        const Clock::time_point wake = std::min(wall_deadline, now + to_duration(std::max((seconds - cpu) / 2, 1e-3)));
        done_changed_.wait_until(lock, wake, [this] { return done_; });
      }
    });
  }
  Input_time_limit(const Input_time_limit&) = delete;
  Input_time_limit& operator=(const Input_time_limit&) = delete;
  ~Input_time_limit() { stop(); }

  // Ends the watch; returns the wall seconds since construction.
  double stop() {
    if (watchdog_.joinable()) {
      {
        std::lock_guard<std::mutex> lock(mutex_);
        done_ = true;
      }
      done_changed_.notify_one();
      watchdog_.join();
      seconds_ = std::chrono::duration<double>(Clock::now() - start_).count();
      cpu_seconds_ = process_cpu_seconds() - cpu_start_;
    }
    return seconds_;
  }
  // The process's CPU seconds between construction and stop().
  double cpu_seconds() const { return cpu_seconds_; }

 private:
  using Clock = std::chrono::steady_clock;
  static Clock::duration to_duration(double seconds) {
    return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(std::min(seconds, 1e9)));
  }
  [[noreturn]] void expire(const char* what, double limit) const {
    std::fprintf(stderr, "time limit: %s ran for more than %g s of %s\n", input_.c_str(), limit, what);
    std::fflush(stderr);
    std::_Exit(124);
  }

  std::string input_;
  Clock::time_point start_;
  double cpu_start_;
  std::mutex mutex_;
  std::condition_variable done_changed_;
  bool done_ = false;
  double seconds_ = 0, cpu_seconds_ = 0;
  std::thread watchdog_;
};

// Seconds from the environment variable `name`, or `default_seconds`.
inline double seconds_from_environment(const char* name, double default_seconds) {
  if (const char* env = std::getenv(name)) return std::strtod(env, nullptr);
  return default_seconds;
}

}  // namespace apollonius::testing
