// time_limit.h: the watch counts CPU time, so that work which waits for the processor is not stopped, stops
// work that spins past its limit, and stops work that blocks past its wall limit. Each case runs in a child
// process, since the watchdog ends the program it watches.
#include <doctest/doctest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <functional>
#include <thread>

#include "support/time_limit.h"

using apollonius::testing::Input_time_limit;
using apollonius::testing::process_cpu_seconds;

namespace {

// The exit code of `work` run in a child process (0 when it returns), or -1 if the child was killed.
int exit_code_of(const std::function<void()>& work) {
  std::fflush(nullptr);
  const pid_t child = fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    work();
    std::_Exit(0);
  }
  int status = 0;
  REQUIRE(waitpid(child, &status, 0) == child);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Spins until the process has spent `seconds` of CPU time since the call.
void spin_for(double seconds) {
  const double start = process_cpu_seconds();
  volatile double sink = 0;
  while (process_cpu_seconds() - start < seconds) sink = sink + 1;
}

}  // namespace

TEST_CASE("a time limit stops work that spends more CPU time than allowed") {
  CHECK(exit_code_of([] {
          Input_time_limit limit(0.2, "spinning for 5 s");
          spin_for(5);
        }) == 124);
}

TEST_CASE("a time limit lets work that waits without spending CPU time run past the limit in wall time") {
  CHECK(exit_code_of([] {
          Input_time_limit limit(0.2, "sleeping for 0.6 s");
          std::this_thread::sleep_for(std::chrono::milliseconds(600));
          limit.stop();
          if (!(limit.stop() >= 0.6 && limit.cpu_seconds() < 0.2)) std::_Exit(1);
        }) == 0);
}

TEST_CASE("a time limit stops work that blocks past its wall limit") {
  CHECK(exit_code_of([] {
          Input_time_limit limit(0.05, "sleeping for 5 s");  // wall limit 0.5 s
          std::this_thread::sleep_for(std::chrono::seconds(5));
        }) == 124);
}

TEST_CASE("work within its limit ends the watch at once and reports its CPU time") {
  const auto start = std::chrono::steady_clock::now();
  Input_time_limit limit(60, "spinning for 0.1 s");
  spin_for(0.1);
  const double wall = limit.stop();
  CHECK(limit.cpu_seconds() >= 0.1);
  CHECK(wall >= limit.cpu_seconds() * 0.5);  // one thread spun: its CPU time is at most about the wall time
  // Not the 30 s of the watch's first wait: stop() wakes it.
  CHECK(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < 5);
}
