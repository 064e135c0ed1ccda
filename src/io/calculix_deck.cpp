/// A CalculiX deck's nodes and node sets, and a ccx run that assembles K and M (calculix_deck.h).

#include "geardyn/io/calculix_deck.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "geardyn/error.h"

namespace geardyn::io {
namespace {

namespace fs = std::filesystem;

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::string strip(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

std::vector<std::string> splitCommas(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line);
  std::string item;
  while (std::getline(in, item, ',')) out.push_back(strip(item));
  while (!out.empty() && out.back().empty()) out.pop_back();
  return out;
}

/// The value of PARAMETER=value on a keyword line ("" when absent); names upper-cased.
std::string parameter(const std::vector<std::string>& fields, const std::string& name) {
  for (std::size_t i = 1; i < fields.size(); ++i) {
    const auto eq = fields[i].find('=');
    if (eq != std::string::npos && upper(strip(fields[i].substr(0, eq))) == name) {
      return strip(fields[i].substr(eq + 1));
    }
  }
  return "";
}

bool hasFlag(const std::vector<std::string>& fields, const std::string& name) {
  for (std::size_t i = 1; i < fields.size(); ++i) {
    if (upper(fields[i]) == name) return true;
  }
  return false;
}

bool parseInt(const std::string& s, long& value) {
  char* end = nullptr;
  value = std::strtol(s.c_str(), &end, 10);
  return !s.empty() && *end == '\0';
}

bool parseDouble(const std::string& s, double& value) {
  char* end = nullptr;
  value = std::strtod(s.c_str(), &end);
  return !s.empty() && *end == '\0';
}

enum class Card { kNone, kNode, kNset, kElement };

struct DeckReader {
  CalculixDeck deck;
  const std::string& key;
  int depth = 0;

  [[noreturn]] void fail(const std::string& path, long number, const std::string& line,
                         const std::string& what) const {
    throw InputError(key, path, fmt::format("line {} ('{}'): {}", number, line, what));
  }

  void nsetLine(const std::string& path, long number, const std::string& line,
                const std::string& set, bool generate) {
    std::vector<int>& nodes = deck.nsets[set];
    const std::vector<std::string> items = splitCommas(line);
    if (generate) {
      long a = 0, b = 0, step = 1;
      if (items.size() < 2 || !parseInt(items[0], a) || !parseInt(items[1], b) ||
          (items.size() > 2 && !parseInt(items[2], step)) || step <= 0 || b < a) {
        fail(path, number, line, "a GENERATE line 'first, last[, increment]'");
      }
      for (long n = a; n <= b; n += step) nodes.push_back(static_cast<int>(n));
      return;
    }
    for (const std::string& item : items) {
      long n = 0;
      if (parseInt(item, n)) {
        nodes.push_back(static_cast<int>(n));
      } else if (auto it = deck.nsets.find(upper(item)); it != deck.nsets.end()) {
        nodes.insert(nodes.end(), it->second.begin(), it->second.end());
      } else {
        fail(path, number, line,
             fmt::format("'{}' is neither a node number nor a node set defined above", item));
      }
    }
  }

  void read(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw IoError(fmt::format("cannot open {} for reading", path));
    if (++depth > 10) fail(path, 0, "*INCLUDE", "*INCLUDE nested more than 10 deep");
    Card card = Card::kNone;
    std::string set;
    bool generate = false;
    std::string raw;
    long number = 0;
    while (std::getline(in, raw)) {
      ++number;
      const std::string line = strip(raw);
      if (line.empty() || line.rfind("**", 0) == 0) continue;
      if (line[0] == '*') {
        const std::vector<std::string> fields = splitCommas(line);
        const std::string keyword = upper(fields[0]);
        card = Card::kNone;
        if (keyword == "*NODE") {
          card = Card::kNode;
        } else if (keyword == "*NSET") {
          set = upper(parameter(fields, "NSET"));
          if (set.empty()) fail(path, number, line, "*NSET needs NSET=<name>");
          generate = hasFlag(fields, "GENERATE");
          deck.nsets[set];
          card = Card::kNset;
        } else if (keyword == "*ELEMENT") {
          card = Card::kElement;
        } else if (keyword == "*STEP") {
          deck.has_step = true;
        } else if (keyword == "*INCLUDE") {
          fs::path included = parameter(fields, "INPUT");
          if (included.empty()) fail(path, number, line, "*INCLUDE needs INPUT=<file>");
          if (included.is_relative()) included = fs::path(path).parent_path() / included;
          read(included.string());
        }
        continue;
      }
      if (card == Card::kNode) {
        const std::vector<std::string> items = splitCommas(line);
        long id = 0;
        Eigen::Vector3d x = Eigen::Vector3d::Zero();
        bool ok = items.size() >= 2 && items.size() <= 4 && parseInt(items[0], id) && id > 0;
        for (std::size_t i = 1; ok && i < items.size(); ++i) ok = parseDouble(items[i], x[i - 1]);
        if (!ok) fail(path, number, line, "a *NODE line 'number, x[, y[, z]]'");
        deck.nodes[static_cast<int>(id)] = x;
      } else if (card == Card::kNset) {
        nsetLine(path, number, line, set, generate);
      } else if (card == Card::kElement) {
        ++deck.elements;
      }
    }
    --depth;
  }
};

/// Runs `argv` in `folder` with stdout and stderr into `log`; the exit status, or -1 when the
/// program could not be started (127: not found).
int runIn(const fs::path& folder, const std::vector<std::string>& args, const fs::path& log) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  // The child must not flush the parent's pending stdio buffers (they would print twice): flush
  // them first, and redirect with open/dup2 only.
  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid < 0) return -1;
  if (pid == 0) {
    if (chdir(folder.c_str()) != 0) _exit(126);
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0 || dup2(fd, STDOUT_FILENO) < 0 || dup2(fd, STDERR_FILENO) < 0) _exit(126);
    close(fd);
    execvp(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

/// ccx's *ERROR lines (and the next line, which often holds the offending card), else the log's
/// last lines.
std::string ccxErrors(const fs::path& log) {
  std::ifstream in(log);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(strip(l));
  std::string errors;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (lines[i].find("*ERROR") == std::string::npos) continue;
    errors += "\n  " + lines[i];
    if (i + 1 < lines.size() && !lines[i + 1].empty()) errors += "\n  " + lines[i + 1];
  }
  if (!errors.empty()) return errors;
  for (std::size_t i = lines.size() > 8 ? lines.size() - 8 : 0; i < lines.size(); ++i) {
    if (!lines[i].empty()) errors += "\n  " + lines[i];
  }
  return errors;
}

struct TemporaryFolder {
  fs::path path;
  TemporaryFolder() {
    std::string pattern = (fs::temp_directory_path() / "geardyn-ccx-XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) {
      throw IoError("cannot create a temporary folder for ccx in " +
                    fs::temp_directory_path().string());
    }
    path = pattern;
  }
  ~TemporaryFolder() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
};

}  // namespace

CalculixDeck readCalculixDeck(const std::string& path, const std::string& key) {
  if (!fs::exists(path)) throw InputError(key, path, "an existing CalculiX deck (.inp)");
  DeckReader reader{CalculixDeck{}, key};
  reader.read(path);
  if (reader.deck.nodes.empty()) {
    throw InputError(key, path, "a deck with *NODE lines (none found)");
  }
  for (auto& [name, nodes] : reader.deck.nsets) {
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  }
  return reader.deck;
}

double estimateHousingBytes(const CalculixDeck& deck) {
  const double dofs = 3.0 * static_cast<double>(deck.nodes.size());
  const double entries = kEntriesPerDof * dofs;
  // K and M in both triangles (12 B an entry), their triplets while reading (16 B), the
  // factorisation (12 B an entry of the factor).
  return entries * (2.0 * 2.0 * 12.0 + 2.0 * 2.0 * 16.0 + kFillPerEntry * 12.0);
}

void checkHousingFits(const CalculixDeck& deck, const std::string& path, const std::string& key,
                      double limit_bytes) {
  const double bytes = estimateHousingBytes(deck);
  if (bytes <= limit_bytes) return;
  throw InputError(key, path,
                   fmt::format("a mesh that fits in memory: {} nodes ({} DOFs) need about {:.3g} "
                               "GB to assemble and reduce ({:g} entries a DOF, a factor {:g} "
                               "times K's entries), the limit is {:.3g} GB (80 % of MemAvailable "
                               "or GEARDYN_MEMORY_LIMIT); coarsen the mesh",
                               deck.nodes.size(), 3 * deck.nodes.size(), bytes / 1e9,
                               kEntriesPerDof, kFillPerEntry, limit_bytes / 1e9));
}

FeMatrices runCalculix(const std::string& path, const std::string& key,
                       const std::string& ccx_command, const std::vector<std::string>& fixed_sets) {
  const fs::path deck = fs::absolute(path);
  if (!fs::exists(deck)) throw InputError(key, path, "an existing CalculiX deck (.inp)");
  TemporaryFolder folder;
  {
    std::ofstream job(folder.path / "job.inp");
    job << "** written by geardyn: the user's deck and the step that stores K and M\n"
        << "*INCLUDE, INPUT=" << deck.string() << "\n";
    for (const std::string& set : fixed_sets) job << "*BOUNDARY\n" << set << ", 1, 3\n";
    job << "*STEP\n*FREQUENCY, SOLVER=MATRIXSTORAGE\n1\n*END STEP\n";
    if (!job) throw IoError("cannot write " + (folder.path / "job.inp").string());
  }
  const fs::path log = folder.path / "job.log";
  const int status = runIn(folder.path, {ccx_command, "-i", "job"}, log);
  if (status == 127 || status == -1) {
    throw InputError(key, path,
                     fmt::format("'{}' (CalculiX) on PATH to assemble the deck: it could not be "
                                 "started (install calculix-ccx; scripts/setup.sh does)",
                                 ccx_command));
  }
  const fs::path sti = folder.path / "job.sti", mas = folder.path / "job.mas",
                 dof = folder.path / "job.dof";
  std::ifstream log_in(log);
  const std::string text((std::istreambuf_iterator<char>(log_in)), {});
  if (status != 0 || text.find("*ERROR") != std::string::npos || !fs::exists(sti) ||
      !fs::exists(mas) || !fs::exists(dof)) {
    throw InputError(key, path,
                     fmt::format("a deck ccx accepts (mesh, material, *BOUNDARY, no *STEP); ccx "
                                 "exited with status {} and said:{}",
                                 status, ccxErrors(log)));
  }
  return readCcxMatrixStorage(sti.string(), mas.string(), dof.string(), key);
}

}  // namespace geardyn::io
