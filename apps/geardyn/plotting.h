#pragma once
/// \file
/// PNG plots of a result folder, drawn by the Python package (matplotlib, Debian's
/// /usr/bin/python3) as `python3 -m geardyn.plot COMMAND DIR`. Plotting is optional: if Python,
/// matplotlib or the package is missing, the run still succeeds and says so on stderr.

#include <filesystem>
#include <string>
#include <vector>

namespace geardyn::cli {

/// Runs the plotter for `command` on `folder`; returns the names of the files it wrote (empty,
/// with a warning on stderr, if it could not run). The interpreter is $GEARDYN_PYTHON or the one
/// CMake pinned; the package is found next to the executable (build/python) or on PYTHONPATH.
std::vector<std::string> drawPlots(const std::string& command, const std::filesystem::path& folder);

/// Runs `python -m MODULE ARGS...` of the geardyn package (same interpreter and package folder
/// as drawPlots) with this process's stdin, stdout and stderr; returns its exit code, or -1
/// (with a message on stderr) if it could not start.
int runPythonModule(const std::string& module, const std::vector<std::string>& args);

}  // namespace geardyn::cli
