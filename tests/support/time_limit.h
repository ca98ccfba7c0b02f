// A time limit for one test input: if the work it guards runs past the limit, a watchdog thread names the
// input on stderr and ends the test program with exit code 124, so that a hang fails the run (ctest reports
// it) instead of stalling it, and the input can be rerun. It also measures the time the work took.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <string>
#include <thread>

namespace apollonius::testing {

class Input_time_limit {
 public:
  Input_time_limit(double seconds, std::string input) : input_(std::move(input)), start_(Clock::now()) {
    watchdog_ = std::thread([this, seconds] {
      std::unique_lock<std::mutex> lock(mutex_);
      if (!done_changed_.wait_for(lock, std::chrono::duration<double>(seconds), [this] { return done_; })) {
        std::fprintf(stderr, "time limit: %s ran for more than %g s\n", input_.c_str(), seconds);
        std::fflush(stderr);
        std::_Exit(124);
      }
    });
  }
  Input_time_limit(const Input_time_limit&) = delete;
  Input_time_limit& operator=(const Input_time_limit&) = delete;
  ~Input_time_limit() { stop(); }

  // Ends the watch; returns the seconds since construction.
  double stop() {
    if (watchdog_.joinable()) {
      {
        std::lock_guard<std::mutex> lock(mutex_);
        done_ = true;
      }
      done_changed_.notify_one();
      watchdog_.join();
      seconds_ = std::chrono::duration<double>(Clock::now() - start_).count();
    }
    return seconds_;
  }

 private:
  using Clock = std::chrono::steady_clock;
  std::string input_;
  Clock::time_point start_;
  std::mutex mutex_;
  std::condition_variable done_changed_;
  bool done_ = false;
  double seconds_ = 0;
  std::thread watchdog_;
};

// Seconds from the environment variable `name`, or `default_seconds`.
inline double seconds_from_environment(const char* name, double default_seconds) {
  if (const char* env = std::getenv(name)) return std::strtod(env, nullptr);
  return default_seconds;
}

}  // namespace apollonius::testing
