// Runs a long computation without the GIL, so that other Python threads run meanwhile, and lets Ctrl-C
// stop it. The computation runs on a thread of its own; the calling thread waits without the GIL and,
// every 50 ms, takes it to let Python handle signals (PyErr_CheckSignals, which acts in the main thread
// only). When a signal handler raises (KeyboardInterrupt for Ctrl-C), the computation's Cancellation is
// requested, the call waits for it to stop (the algorithms check it often: diagram/cancellation.h), drops
// whatever it produced, and raises the handler's exception. No state outlives the call either way.
#pragma once

#include <pybind11/pybind11.h>

#include <chrono>
#include <exception>
#include <future>
#include <optional>
#include <thread>
#include <type_traits>
#include <utility>

#include "diagram/cancellation.h"

namespace apollonius::python {

// compute(const Cancellation&) must not touch Python objects: it runs without the GIL. Its exceptions
// reach the caller (errors.cpp translates them).
template <class Compute>
auto interruptible_call(Compute compute) -> std::invoke_result_t<Compute&, const Cancellation&> {
  using Result = std::invoke_result_t<Compute&, const Cancellation&>;
  namespace py = pybind11;
  Cancellation cancellation;
  std::promise<Result> promise;
  std::future<Result> result = promise.get_future();
  std::optional<py::error_already_set> interruption;
  {
    py::gil_scoped_release release;
    std::thread worker([&] {
      try {
        promise.set_value(compute(cancellation));
      } catch (...) {
        promise.set_exception(std::current_exception());
      }
    });
    while (result.wait_for(std::chrono::milliseconds(50)) != std::future_status::ready) {
      py::gil_scoped_acquire acquire;
      if (PyErr_CheckSignals() != 0) {
        interruption.emplace();  // takes the exception that the handler raised
        break;
      }
    }
    if (interruption) cancellation.request();
    worker.join();
  }
  if (interruption) throw std::move(*interruption);
  return result.get();
}

}  // namespace apollonius::python
