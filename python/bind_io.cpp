/// Python bindings of io/: configuration schemas and loading.

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "geardyn/error.h"
#include "geardyn/io/config.h"
#include "geardyn/io/geometry_io.h"
#include "geardyn/io/stiffness_io.h"

namespace py = pybind11;

namespace geardyn::python {
namespace {

io::ConfigSchema schemaOf(const std::string& command) {
  if (command == "geometry") return io::geometrySchema();
  if (command == "stiffness") return io::stiffnessSchema();
  throw InputError("command", command, "must be one of: geometry, stiffness");
}

}  // namespace

void bindIo(py::module_& m) {
  m.def(
      "load_config",
      [](const std::string& command, const std::string& path,
         const std::vector<std::string>& overrides) {
        const auto config = io::loadConfigFile(path, schemaOf(command), overrides);
        return py::module_::import("json").attr("loads")(config.resolved().dump());
      },
      py::arg("command"), py::arg("path"), py::arg("overrides") = std::vector<std::string>{},
      "Load and validate a configuration file for a command; returns the fully resolved "
      "configuration (defaults filled in) as a dict. Raises ValueError naming the bad key.");
  m.def(
      "config_reference",
      [](const std::string& command) { return schemaOf(command).referenceMarkdown(); },
      py::arg("command"), "The configuration reference of a command, as Markdown.");
}

}  // namespace geardyn::python
