/// Python bindings of io/: configuration schemas and loading.

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>

#include "geardyn/analysis/analyses.h"
#include "geardyn/analysis/geometry_results.h"
#include "geardyn/analysis/hbm_results.h"
#include "geardyn/analysis/identify_results.h"
#include "geardyn/analysis/ltca_results.h"
#include "geardyn/analysis/rotor_results.h"
#include "geardyn/analysis/simulate_results.h"
#include "geardyn/analysis/stats_results.h"
#include "geardyn/analysis/stiffness_results.h"
#include "geardyn/analysis/sweep_results.h"
#include "geardyn/config/config.h"
#include "geardyn/config/fe_rotor_config.h"
#include "geardyn/config/geometry_config.h"
#include "geardyn/config/hbm_config.h"
#include "geardyn/config/identify_config.h"
#include "geardyn/config/ltca_config.h"
#include "geardyn/config/rotor_config.h"
#include "geardyn/config/simulate_config.h"
#include "geardyn/config/stats_config.h"
#include "geardyn/config/stiffness_config.h"
#include "geardyn/config/sweep_config.h"
#include "geardyn/error.h"

namespace py = pybind11;

namespace geardyn::python {
namespace {

/// The schema of a command; `rotor` files with [model] type = "fe_geared_rotor" use the FE one.
config::ConfigSchema schemaOf(const std::string& command, const std::string& path = "") {
  if (command == "rotor")
    return !path.empty() && config::peekConfigString(path, "model.type") == "fe_geared_rotor"
               ? config::feRotorSchema()
               : config::rotorSchema();
  if (command == "rotor_fe") return config::feRotorSchema();
  if (command == "sweep") return config::sweepSchema();
  for (const auto& a : analysis::analysisCommands())
    if (command == a.name) return a.schema();
  std::string names;
  for (const auto& a : analysis::analysisCommands()) names += std::string(a.name) + ", ";
  throw InputError("command", command, "one of " + names + "rotor_fe, sweep");
}

}  // namespace

void bindIo(py::module_& m) {
  m.def(
      "load_config",
      [](const std::string& command, const std::string& path,
         const std::vector<std::string>& overrides) {
        const auto config = config::loadConfigFile(path, schemaOf(command, path), overrides);
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
