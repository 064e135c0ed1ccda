#include "plotting.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
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

}  // namespace

std::vector<std::string> drawPlots(const std::string& command,
                                   const std::filesystem::path& folder) {
  const char* override_python = std::getenv("GEARDYN_PYTHON");
  const std::string python = override_python ? override_python : GEARDYN_PYTHON_EXECUTABLE;
  const std::filesystem::path listing = folder / ".plot-files.txt";

  // Environment: PYTHONPATH gets the package folder in front; stdout goes to a listing file.
  std::vector<std::string> variables;
  const char* old_path = std::getenv("PYTHONPATH");
  variables.push_back("PYTHONPATH=" + packageFolder() +
                      (old_path ? std::string(":") + old_path : ""));
  for (char** e = environ; *e; ++e) {
    if (std::strncmp(*e, "PYTHONPATH=", 11) != 0) variables.emplace_back(*e);
  }
  std::vector<char*> envp;
  for (auto& v : variables) envp.push_back(v.data());
  envp.push_back(nullptr);
  std::string module = "geardyn.plot", folder_text = folder.string();
  std::string m_flag = "-m", command_copy = command, python_copy = python;
  std::array<char*, 6> argv{python_copy.data(),  m_flag.data(),      module.data(),
                            command_copy.data(), folder_text.data(), nullptr};

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, listing.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  const int spawned =
      posix_spawn(&pid, python.c_str(), &actions, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  int status = 0;
  if (spawned != 0 || waitpid(pid, &status, 0) < 0 || !WIFEXITED(status) ||
      WEXITSTATUS(status) != 0) {
    std::cerr << "warning: plots skipped: `" << python << " -m geardyn.plot` "
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
