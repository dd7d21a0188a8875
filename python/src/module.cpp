// The native module of `import penumbra` (docs/python.md). Bad input raises
// penumbra.InputError (a ValueError) whose file, location and message are those the
// command line prints; long computations release the GIL.

#include <malloc.h>

#include <cstdlib>
#include <exception>

#include <pybind11/pybind11.h>

#include "bindings.h"
#include "penumbra/base/input_error.h"
#include "penumbra/geometry/geometry_error.h"

namespace py = pybind11;

namespace {

// Exact arithmetic allocates and frees millions of small numbers. Dask's nannies start their
// workers with MALLOC_TRIM_THRESHOLD_=65536 (to hand memory back to the system sooner), with
// which glibc returns the top of the heap at every free that empties 64 KiB of it: a system
// call each time, and a sun-hours task ran 2.3 times slower (docs/performance.md, "Dask").
// When that variable is set, the module raises the threshold to 256 MiB (glibc's default
// adapts up to 32 MiB; a set variable turns the adaptation off, and so does mallopt).
void relax_malloc_trimming() {
  const char* given = std::getenv("MALLOC_TRIM_THRESHOLD_");
  if (given != nullptr && std::strtoll(given, nullptr, 10) < (256 << 20))
    mallopt(M_TRIM_THRESHOLD, 256 << 20);
}

}  // namespace

PYBIND11_MODULE(_penumbra, module) {
  module.doc() =
      "Native part of penumbra: exact shadows, illuminance and sun studies (docs/python.md). "
      "Use the package penumbra, which wraps it.";
  static py::exception<penumbra::InputError> input_error(module, "InputError", PyExc_ValueError);
  input_error.doc() =
      "Bad input: a scene, a photometric file, a date or an argument that cannot be used. "
      "Attributes: file (the file, '' for an argument), location (a JSON path such as "
      "'objects[3].convex', 'line 12', or an option such as '--date'), message.";
  py::register_exception_translator([](std::exception_ptr pointer) {
    try {
      if (pointer) std::rethrow_exception(pointer);
    } catch (const penumbra::InputError& error) {
      py::object value = py::handle(input_error.ptr())(error.what());
      value.attr("file") = error.file();
      value.attr("location") = error.location();
      value.attr("message") = error.message();
      PyErr_SetObject(input_error.ptr(), value.ptr());
    } catch (const penumbra::GeometryError& error) {
      PyErr_SetString(PyExc_ValueError, error.what());
    }
  });
  relax_malloc_trimming();
  penumbra::python::bind_scene(module);
  penumbra::python::bind_studies(module);
}
