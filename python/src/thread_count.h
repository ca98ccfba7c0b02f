// The threads argument of the computations, checked as the command line's --threads.
#pragma once

#include <pybind11/pybind11.h>

#include <string>

namespace apollonius::python {

inline void check_thread_count(int threads) {
  if (threads < 1 || threads > 1024)
    throw pybind11::value_error("threads: needs an integer from 1 to 1024, not " + std::to_string(threads));
}

}  // namespace apollonius::python
