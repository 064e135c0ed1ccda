/// The compiled part of the Python package: `geardyn._geardyn`. One bind_<module>.cpp per
/// library module (STYLE.md); the pure-Python layer in python/geardyn/ re-exports it.

#include <pybind11/pybind11.h>

#include <cerrno>

#include "geardyn/error.h"
#include "geardyn/version.h"

namespace py = pybind11;

namespace geardyn::python {
void bindGeometry(py::module_& m);
void bindContact(py::module_& m);
void bindIo(py::module_& m);
void bindRotor(py::module_& m);
void bindStiffness(py::module_& m);
void bindFeRotor(py::module_& m);
void bindAnalysis(py::module_& m);
void bindTrain(py::module_& m);
}  // namespace geardyn::python

PYBIND11_MODULE(_geardyn, m) {
  m.doc() = "geardyn: gear-pair and geared-rotor dynamics (compiled core)";
  m.attr("__version__") = geardyn::kVersion;
  // InputError (bad input: a configuration key or an argument) becomes geardyn.ConfigError, a
  // ValueError carrying .key, .value and .allowed; IoError (a file that cannot be read or
  // written) becomes OSError.
  static py::handle config_error =
      py::exception<geardyn::InputError>(m, "ConfigError", PyExc_ValueError).release();
  config_error.attr("__doc__") =
      "Bad input: a configuration key or argument. A ValueError with .key (dotted key or "
      "argument name), .value (as given) and .allowed (what would be accepted).";
  py::register_exception_translator([](std::exception_ptr error) {
    try {
      if (error) std::rethrow_exception(error);
    } catch (const geardyn::IoError& io_error) {
      PyErr_SetString(PyExc_OSError, io_error.what());
    } catch (const geardyn::InputError& input_error) {
      // A configuration file that cannot be read is an OSError in Python terms (the CLI
      // counts it as bad input, exit code 2): FileNotFoundError, PermissionError.
      if (input_error.key() == "config") {
        const std::string& why = input_error.allowed();
        const bool missing = why == "no such configuration file";
        if (missing || why == "cannot be opened for reading" || why == "is not a regular file") {
          py::object type = py::module_::import("builtins")
                                .attr(missing         ? "FileNotFoundError"
                                      : why[0] == 'c' ? "PermissionError"
                                                      : "IsADirectoryError");
          py::object instance = type(missing ? ENOENT : (why[0] == 'c' ? EACCES : EISDIR),
                                     input_error.what(), input_error.value());
          PyErr_SetObject(type.ptr(), instance.ptr());
          return;
        }
      }
      py::object instance = config_error(py::str(input_error.what()));
      instance.attr("key") = py::str(input_error.key());
      instance.attr("value") = py::str(input_error.value());
      instance.attr("allowed") = py::str(input_error.allowed());
      PyErr_SetObject(config_error.ptr(), instance.ptr());
    }
  });
  geardyn::python::bindGeometry(m);
  geardyn::python::bindContact(m);
  geardyn::python::bindIo(m);
  geardyn::python::bindRotor(m);
  geardyn::python::bindStiffness(m);
  geardyn::python::bindFeRotor(m);
  geardyn::python::bindAnalysis(m);
  geardyn::python::bindTrain(m);
}
