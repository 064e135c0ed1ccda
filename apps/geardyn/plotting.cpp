#include "plotting.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>

extern char** environ;

namespace geardyn::cli {
namespace {

/// The folder holding the `geardyn` Python package: build/python beside build/bin/geardyn.
std::string packageFolder() {
  std::error_code ec;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const auto beside = self.parent_path().parent_path() / "python";
    if (std::filesystem::exists(beside / "geardyn" / "plot.py", ec)) return beside.string();
  }
  return GEARDYN_PYTHON_PACKAGE_DIR;
}

/// The environment of the child: PYTHONPATH gets the package folder in front.
std::vector<std::string> childEnvironment() {
  std::vector<std::string> variables;
  const char* old_path = std::getenv("PYTHONPATH");
  variables.push_back("PYTHONPATH=" + packageFolder() +
                      (old_path ? std::string(":") + old_path : ""));
  for (char** e = environ; *e; ++e) {
    if (std::strncmp(*e, "PYTHONPATH=", 11) != 0) variables.emplace_back(*e);
  }
  return variables;
}

std::string pythonExecutable() {
  const char* override_python = std::getenv("GEARDYN_PYTHON");
  return override_python ? override_python : GEARDYN_PYTHON_EXECUTABLE;
}

/// Spawns `python -m module args...` with `actions` (may be null); -1 if it could not start
/// (errno-style code in `spawn_error`), else the exit status (128 + signal if killed).
int spawnModule(const std::string& module, const std::vector<std::string>& args,
                const posix_spawn_file_actions_t* actions, int& spawn_error) {
  const std::string python = pythonExecutable();
  std::vector<std::string> variables = childEnvironment();
  std::vector<char*> envp;
  for (auto& v : variables) envp.push_back(v.data());
  envp.push_back(nullptr);
  std::vector<std::string> words{python, "-m", module};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  spawn_error = posix_spawn(&pid, python.c_str(), actions, nullptr, argv.data(), envp.data());
  if (spawn_error != 0) return -1;
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return -1;
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  return 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

}  // namespace

int runPythonModule(const std::string& module, const std::vector<std::string>& args) {
  int spawn_error = 0;
  const int code = spawnModule(module, args, nullptr, spawn_error);
  if (code < 0) {
    std::cerr << "I/O error: could not start `" << pythonExecutable() << " -m " << module
              << "`: " << std::strerror(spawn_error != 0 ? spawn_error : errno)
              << " (set GEARDYN_PYTHON to an interpreter with numpy)\n";
  }
  return code;
}

std::vector<std::string> drawPlots(const std::string& command,
                                   const std::filesystem::path& folder) {
  const std::filesystem::path listing = folder / ".plot-files.txt";
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, listing.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  int spawned = 0;
  const int status = spawnModule("geardyn.plot", {command, folder.string()}, &actions, spawned);
  posix_spawn_file_actions_destroy(&actions);
  if (status != 0) {
    std::cerr << "warning: plots skipped: `" << pythonExecutable() << " -m geardyn.plot` "
              << (spawned != 0 ? std::string("could not start: ") + std::strerror(spawned)
                               : std::string("failed (is python3-matplotlib installed?)"))
              << "; set output.plots = false to silence this\n";
    std::filesystem::remove(listing);
    return {};
  }
  std::vector<std::string> files;
  std::ifstream in(listing);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty()) files.push_back(line);
  }
  in.close();
  std::filesystem::remove(listing);
  return files;
}

}  // namespace geardyn::cli
