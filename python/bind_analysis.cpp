/// Python bindings of analysis/: every analysis in-process (`geardyn.run` in Python), its
/// result with numpy views of the result's own columns, configuration errors as
/// geardyn.ConfigError, progress and Ctrl-C while the analysis runs without the GIL.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <thread>

#include "geardyn/analysis/analyses.h"
#include "geardyn/analysis/run_estimates.h"
#include "geardyn/analysis/warning_groups.h"
#include "geardyn/config/config.h"
#include "geardyn/config/fe_rotor_config.h"
#include "geardyn/config/ltca_config.h"
#include "geardyn/error.h"
#include "geardyn/io/result_writer.h"

namespace py = pybind11;

namespace geardyn::python {
namespace {

using analysis::AnalysisResult;

/// Thrown by the progress callback when Python has a pending signal (Ctrl-C).
struct Interrupted {};

/// Seconds between two calls into Python from a running analysis (progress and signals).
constexpr double kCallbackInterval = 0.1;

/// A numeric column as a numpy array viewing the result's memory (`owner` keeps it alive);
/// text columns as a list of str.
py::object columnObject(const analysis::ResultColumn& column, py::handle owner) {
  if (const auto* reals = std::get_if<std::vector<double>>(&column)) {
    py::array_t<double> a(static_cast<py::ssize_t>(reals->size()), reals->data(), owner);
    py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
    return std::move(a);
  }
  if (const auto* ints = std::get_if<std::vector<std::int64_t>>(&column)) {
    py::array_t<std::int64_t> a(static_cast<py::ssize_t>(ints->size()), ints->data(), owner);
    py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
    return std::move(a);
  }
  return py::cast(std::get<std::vector<std::string>>(column));
}

std::shared_ptr<AnalysisResult> analyze(const std::string& name, const std::string& path,
                                        const std::string& text, const std::string& source,
                                        const std::string& model_type,
                                        const std::vector<std::string>& overrides, int threads,
                                        const py::object& progress, const py::object& warn) {
  // `train` reads its analysis file and the gearbox file it names; the others one file.
  std::optional<analysis::TrainInputs> train;
  std::optional<config::Config> config;
  if (name == "train") {
    // A dict's relative gearbox.file is relative to the working directory.
    train = path.empty() ? analysis::parseTrainInputs(text, source.empty() ? "(dict)" : source,
                                                      std::filesystem::current_path(), overrides)
                         : analysis::loadTrainInputs(path, overrides);
    if (train->analysis.boolean("gearbox.all_load_cases"))
      throw InputError("gearbox.all_load_cases", "true",
                       "one load case per in-process run: set gearbox.load_case, or run "
                       "`geardyn train` for every load case");
  } else {
    const std::string type =
        path.empty() ? model_type : config::peekConfigString(path, "model.type");
    const config::ConfigSchema schema = analysis::analysisSchema(name, type);
    // `ltca` on a mesh of a gearbox file (gearbox.file, gearbox.mesh): the pair is translated.
    const bool gearbox_mesh =
        name == "ltca" && !path.empty() && !config::peekConfigString(path, "gearbox.file").empty();
    config = path.empty()   ? config::parseConfig(text, source, schema, overrides)
             : gearbox_mesh ? config::loadLtcaOnGearboxMesh(path, schema, overrides)
                            : config::loadConfigFile(path, schema, overrides);
    if (!warn.is_none()) {
      for (const auto& note : config->notes()) warn(note);
    }
  }
  analysis::AnalysisContext context;
  context.config_source = path;
  context.threads = threads;
  // Progress and Ctrl-C: at most every kCallbackInterval the callback takes the GIL, lets
  // Python handle its signals (KeyboardInterrupt) and reports the stage's progress.
  // Only the calling thread throws (a solver's worker thread must not: Python handles signals
  // on its main thread only, and a KeyboardInterrupt left pending is raised on return).
  const std::thread::id caller = std::this_thread::get_id();
  context.progress = [&progress, caller](const std::string& label, const std::string& unit) {
    auto last = std::make_shared<std::atomic<double>>(-1.0);
    return ProgressCallback([label, unit, last, &progress, caller](double done, double total) {
      const double now =
          std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
              .count();
      double before = last->load();
      if (done < total && now - before < kCallbackInterval) return;
      if (!last->compare_exchange_strong(before, now) && done < total) return;
      py::gil_scoped_acquire gil;
      if (std::this_thread::get_id() == caller && PyErr_CheckSignals() != 0) {
        PyErr_Clear();
        throw Interrupted{};
      }
      if (!progress.is_none()) {
        try {
          progress(label, unit, done, total);
        } catch (py::error_already_set& e) {
          e.discard_as_unraisable("geardyn progress callback");
        }
      }
    });
  };
  // The resource check of the CLI: a run that would not fit is refused before it allocates
  // (InputError); a long one is announced as a Python warning.
  if (config) {
    context.check_budget = [&config, &warn, &name](const std::string& stage, long long size) {
      const std::string note =
          analysis::checkRunEstimate(analysis::estimateStage(stage, size, *config), name);
      if (!note.empty() && !warn.is_none()) {
        py::gil_scoped_acquire gil;
        warn(note);
      }
    };
  }
  std::shared_ptr<AnalysisResult> result;
  try {
    py::gil_scoped_release release;
    result =
        std::make_shared<AnalysisResult>(train ? analysis::trainAnalysis(*train, context)
                                               : analysis::runAnalysis(name, *config, context));
  } catch (const Interrupted&) {
    PyErr_SetNone(PyExc_KeyboardInterrupt);
    throw py::error_already_set();
  }
  return result;
}

}  // namespace

void bindAnalysis(py::module_& m) {
  py::class_<AnalysisResult, std::shared_ptr<AnalysisResult>>(
      m, "AnalysisResult",
      "The in-memory result of one analysis (geardyn.run wraps it in geardyn.Result).")
      .def_property_readonly("command", [](const AnalysisResult& r) { return r.summary.command; })
      .def_property_readonly("status", [](const AnalysisResult& r) { return r.summary.status; })
      .def_property_readonly(
          "report", [](const AnalysisResult& r) { return r.report; },
          "headline lines for a person (what the CLI prints)")
      .def_property_readonly(
          "warnings", [](const AnalysisResult& r) { return r.summary.warnings; },
          "design and numerical warnings")
      .def_property_readonly(
          "errors", [](const AnalysisResult& r) { return r.errors; }, "non-convergence messages")
      .def_property_readonly("numerical_failure",
                             [](const AnalysisResult& r) { return r.summary.numerical_failure; })
      .def_property_readonly(
          "wall_time_s", [](const AnalysisResult& r) { return r.summary.wall_time_s; },
          "wall time of the analysis [s]")
      .def_property_readonly("table_names", [](const AnalysisResult& r) { return r.table_names; })
      .def(
          "summary_json",
          [](const AnalysisResult& r) {
            std::vector<std::string> files = r.table_names;
            for (const auto& f : r.files) files.push_back(f.name);
            return io::summaryJson(r.summary, files).dump();
          },
          "summary.json of the result (version, resolved configuration, seed, status, "
          "warnings, results) as JSON text")
      .def(
          "columns",
          [](const std::shared_ptr<AnalysisResult>& r, const std::string& name) {
            const analysis::ResultTable& table = r->table(name);
            py::object owner = py::cast(r);
            py::dict out;
            for (std::size_t c = 0; c < table.names().size(); ++c) {
              out[py::str(table.names()[c])] = columnObject(table.columns()[c], owner);
            }
            return out;
          },
          py::arg("table"),
          "The columns of a table as {name: numpy array} (read-only views of the result's "
          "memory: no copy) or {name: list of str} for text columns.")
      .def(
          "save",
          [](const AnalysisResult& r, const std::string& folder) {
            io::ResultWriter writer(folder);
            analysis::writeAnalysisResult(r, writer);
            return writer.writeSummary(r.summary).string();
          },
          py::arg("folder"),
          "Writes the result folder as the CLI does (tables, summary.json; no plots); returns "
          "the path of summary.json.");

  m.def("analyze", &analyze, py::arg("command"), py::kw_only(), py::arg("path") = "",
        py::arg("text") = "", py::arg("source") = "<dict>", py::arg("model_type") = "",
        py::arg("overrides") = std::vector<std::string>{}, py::arg("threads") = 0,
        py::arg("progress") = py::none(), py::arg("warn") = py::none(),
        "Runs analysis `command` in-process on a configuration file (`path`) or TOML `text`; "
        "the GIL is released while it runs. `progress(label, unit, done, total)` is called at "
        "most every 0.1 s; Ctrl-C raises KeyboardInterrupt. Returns an AnalysisResult.");
  m.def("analysis_names", &analysis::analysisNames, "The analyses geardyn.run runs in-process.");
  m.def("grouped_warnings", &analysis::groupedWarnings, py::arg("warnings"),
        py::arg("max_named") = 8,
        "One line per kind of warning, as the command line prints them (summary.json and "
        "Result.warnings keep each).");
}

}  // namespace geardyn::python
