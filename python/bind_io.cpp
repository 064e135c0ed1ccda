/// Python bindings of io/: configuration schemas and loading.

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>

#include "geardyn/error.h"
#include "geardyn/io/config.h"
#include "geardyn/io/fe_rotor_io.h"
#include "geardyn/io/geometry_io.h"
#include "geardyn/io/hbm_io.h"
#include "geardyn/io/identify_io.h"
#include "geardyn/io/ltca_io.h"
#include "geardyn/io/rotor_io.h"
#include "geardyn/io/simulate_io.h"
#include "geardyn/io/stats_io.h"
#include "geardyn/io/stiffness_io.h"
#include "geardyn/io/sweep_io.h"

namespace py = pybind11;

namespace geardyn::python {
namespace {

/// The schema of a command; `rotor` files with [model] type = "fe_geared_rotor" use the FE one.
io::ConfigSchema schemaOf(const std::string& command, const std::string& path = "") {
  if (command == "geometry") return io::geometrySchema();
  if (command == "stiffness") return io::stiffnessSchema();
  if (command == "simulate") return io::simulateSchema();
  if (command == "stats") return io::statsSchema();
  if (command == "hbm") return io::hbmSchema();
  if (command == "rotor")
    return !path.empty() && io::peekConfigString(path, "model.type") == "fe_geared_rotor"
               ? io::feRotorSchema()
               : io::rotorSchema();
  if (command == "rotor_fe") return io::feRotorSchema();
  if (command == "spectrum") return io::spectrumSchema();
  if (command == "identify") return io::identifySchema();
  if (command == "ltca") return io::ltcaSchema();
  if (command == "sweep") return io::sweepSchema();
  throw InputError("command", command,
                   "one of geometry, stiffness, simulate, stats, hbm, rotor, rotor_fe, spectrum, "
                   "identify, ltca, sweep");
}

}  // namespace

void bindIo(py::module_& m) {
  m.def(
      "load_config",
      [](const std::string& command, const std::string& path,
         const std::vector<std::string>& overrides) {
        const auto config = io::loadConfigFile(path, schemaOf(command, path), overrides);
        return py::module_::import("json").attr("loads")(config.resolved().dump());
      },
      py::arg("command"), py::arg("path"), py::arg("overrides") = std::vector<std::string>{},
      "Load and validate a configuration file for a command; returns the fully resolved "
      "configuration (defaults filled in) as a dict. Raises ValueError naming the bad key.");
  m.def(
      "config_unit",
      [](const std::string& command, const std::string& key) -> std::optional<std::string> {
        for (const auto& schema : {schemaOf(command), schemaOf("rotor_fe")}) {
          if (const auto* spec = schema.findKey(key)) return spec->unit;
          if (command != "rotor") break;
        }
        return std::nullopt;
      },
      py::arg("command"), py::arg("key"),
      "The unit of configuration key `key` of `command` (\"\" or \"-\" when it has none), or "
      "None when the command has no such key.");
  m.def(
      "config_reference",
      [](const std::string& command) { return schemaOf(command).referenceMarkdown(); },
      py::arg("command"), "The configuration reference of a command, as Markdown.");
}

}  // namespace geardyn::python
