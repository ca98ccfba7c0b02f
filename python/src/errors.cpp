// C++ exceptions as Python exceptions, as the command line maps them to exit codes (docs/contract.md):
// bad input (Input_error, exit 2) is ValueError with the same message, an output file that cannot be
// written (Output_error) is OSError, anything else that escapes the C++ layers is a bug (exit 3) and
// becomes RuntimeError("internal error: ...").
#include <new>
#include <stdexcept>
#include <string>

#include "bindings.h"
#include "io/atomic_file.h"
#include "io/input_error.h"
#include "measure/exit_regions.h"

namespace py = pybind11;

namespace apollonius::python {

void bind_errors(py::module_& module) {
  py::register_local_exception_translator([](std::exception_ptr exception) {
    try {
      if (exception) std::rethrow_exception(exception);
    } catch (const Input_error& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const Unmeasurable_pair& e) {  // input beyond the measures' precision: exit 2 on the command line
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const Output_error& e) {
      PyErr_SetString(PyExc_OSError, e.what());
    } catch (const py::error_already_set&) {
      throw;  // a Python exception (KeyboardInterrupt, ...): pybind11 restores it
    } catch (const py::builtin_exception&) {
      throw;  // raised by the bindings as a Python exception
    } catch (const std::bad_alloc&) {
      throw;  // pybind11 makes it MemoryError
    } catch (const std::exception& e) {
      PyErr_SetString(PyExc_RuntimeError, (std::string("internal error: ") + e.what()).c_str());
    }
  });

  module.def(
      "_raise_for_testing",
      [](const std::string& kind) {
        if (kind == "input") throw Input_error("file.txt", 3, "reason");
        if (kind == "output") throw Output_error("cannot write out.txt: reason");
        if (kind == "internal") throw std::logic_error("broken invariant");
        if (kind == "memory") throw std::bad_alloc();
        throw py::value_error("kind must be input, output, internal or memory");
      },
      py::arg("kind"),
      "For the test suite only: raises what a C++ exception of this kind becomes in Python (input: Input_error,\n"
      "output: Output_error, internal: std::logic_error, memory: std::bad_alloc).");
}

}  // namespace apollonius::python
