/// Readers of assembled finite-element matrices (fe_matrices.h).

#include "geardyn/io/fe_matrices.h"

#include <fmt/format.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <string>

#include "geardyn/error.h"

namespace geardyn::io {
namespace {

using Triplet = Eigen::Triplet<double>;

struct FileCloser {
  void operator()(std::FILE* f) const {
    if (f != nullptr) std::fclose(f);
  }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

File openFile(const std::string& path) {
  File f(std::fopen(path.c_str(), "r"));
  if (!f) throw IoError(fmt::format("cannot open {} for reading", path));
  return f;
}

std::string trimmed(const char* line) {
  std::string s(line);
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ')) s.pop_back();
  return s;
}

/// Parses `row column value` (1-based); false when the line is not of that form.
bool parseEntry(const char* line, long& row, long& col, double& value) {
  char* end = nullptr;
  errno = 0;
  row = std::strtol(line, &end, 10);
  if (end == line) return false;
  const char* p = end;
  col = std::strtol(p, &end, 10);
  if (end == p) return false;
  p = end;
  value = std::strtod(p, &end);
  if (end == p || errno == ERANGE) return false;
  for (; *end != '\0'; ++end) {
    if (*end != ' ' && *end != '\t' && *end != '\n' && *end != '\r') return false;
  }
  return true;
}

/// Calls visit(line number, text) for each line of a text file.
template <typename Visit>
void forEachLine(const std::string& path, Visit&& visit) {
  File f = openFile(path);
  char line[256];
  long number = 0;
  while (std::fgets(line, sizeof line, f.get()) != nullptr) visit(++number, line);
}

/// Reads `row column value` lines into triplets of both triangles (row <= column stored).
Eigen::SparseMatrix<double> readUpperTriangle(const std::string& path, long n,
                                              const std::string& key) {
  std::vector<Triplet> triplets;
  forEachLine(path, [&](long number, const char* line) {
    long row = 0, col = 0;
    double value = 0.0;
    if (!parseEntry(line, row, col, value) || row < 1 || col < 1 || row > n || col > n ||
        row > col || !std::isfinite(value)) {
      throw InputError(key, path,
                       fmt::format("line {} ('{}') is not 'row column value' with 1 <= row <= "
                                   "column <= {} (the equations in the .dof file) and a finite "
                                   "value, as ccx's *FREQUENCY, SOLVER=MATRIXSTORAGE writes",
                                   number, trimmed(line), n));
    }
    if (value == 0.0) return;
    triplets.emplace_back(row - 1, col - 1, value);
    if (row != col) triplets.emplace_back(col - 1, row - 1, value);
  });
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(triplets.begin(), triplets.end());
  return A;
}

}  // namespace

std::vector<FeDof> readDofMap(const std::string& path, const std::string& key) {
  std::vector<FeDof> dofs;
  forEachLine(path, [&](long number, const char* line) {
    const std::string text = trimmed(line);
    if (text.empty()) return;
    const std::size_t dot = text.find('.');
    char* end = nullptr;
    const long node = std::strtol(text.c_str(), &end, 10);
    const bool ok = dot != std::string::npos && end == text.c_str() + dot && node > 0 &&
                    dot + 2 == text.size() && text[dot + 1] >= '1' && text[dot + 1] <= '3';
    if (!ok) {
      throw InputError(key, path,
                       fmt::format("line {} ('{}') is not 'node.direction' with a positive node "
                                   "number and direction 1, 2 or 3 (ccx's .dof form)",
                                   number, text));
    }
    dofs.push_back({static_cast<int>(node), text[dot + 1] - '0'});
  });
  if (dofs.empty()) {
    throw InputError(key, path, "a DOF map with at least one 'node.direction' line");
  }
  return dofs;
}

FeMatrices readCcxMatrixStorage(const std::string& sti_path, const std::string& mas_path,
                                const std::string& dof_path, const std::string& key) {
  FeMatrices fe;
  fe.dofs = readDofMap(dof_path, key);
  const long n = static_cast<long>(fe.dofs.size());
  fe.K = readUpperTriangle(sti_path, n, key);
  fe.M = readUpperTriangle(mas_path, n, key);
  return fe;
}

Eigen::SparseMatrix<double> readMatrixMarket(const std::string& path, const std::string& key) {
  File f = openFile(path);
  char line[512];
  if (std::fgets(line, sizeof line, f.get()) == nullptr) {
    throw InputError(key, path, "a MatrixMarket file (it is empty)");
  }
  std::string banner = trimmed(line);
  for (char& c : banner) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const bool coordinate = banner.rfind("%%matrixmarket matrix coordinate real ", 0) == 0;
  const bool symmetric = banner.find(" symmetric") != std::string::npos;
  const bool general = banner.find(" general") != std::string::npos;
  if (!coordinate || (!symmetric && !general)) {
    throw InputError(key, path,
                     fmt::format("a '%%MatrixMarket matrix coordinate real symmetric' (or "
                                 "general) banner; the first line is '{}'",
                                 trimmed(line)));
  }
  long rows = -1, cols = -1, entries = -1, number = 1;
  while (std::fgets(line, sizeof line, f.get()) != nullptr) {
    ++number;
    if (line[0] == '%') continue;
    if (std::sscanf(line, "%ld %ld %ld", &rows, &cols, &entries) != 3 || rows <= 0 ||
        rows != cols || entries < 0) {
      throw InputError(key, path,
                       fmt::format("line {} ('{}'): the size line 'rows columns entries' of a "
                                   "square matrix",
                                   number, trimmed(line)));
    }
    break;
  }
  if (rows < 0) throw InputError(key, path, "a MatrixMarket size line (none found)");
  std::vector<Triplet> triplets;
  triplets.reserve(static_cast<std::size_t>(symmetric ? 2 * entries : entries));
  long read = 0;
  while (std::fgets(line, sizeof line, f.get()) != nullptr) {
    ++number;
    if (line[0] == '%' || trimmed(line).empty()) continue;
    long r = 0, c = 0;
    double v = 0.0;
    if (!parseEntry(line, r, c, v) || r < 1 || c < 1 || r > rows || c > rows || !std::isfinite(v)) {
      throw InputError(key, path,
                       fmt::format("line {} ('{}') is not 'row column value' with 1 <= row, "
                                   "column <= {}",
                                   number, trimmed(line), rows));
    }
    ++read;
    triplets.emplace_back(r - 1, c - 1, v);
    if (symmetric && r != c) triplets.emplace_back(c - 1, r - 1, v);
  }
  if (read != entries) {
    throw InputError(key, path,
                     fmt::format("{} entries as its size line says ({} found)", entries, read));
  }
  Eigen::SparseMatrix<double> A(rows, rows);
  A.setFromTriplets(triplets.begin(), triplets.end());
  return A;
}

FeMatrices readMatrixMarketModel(const std::string& k_path, const std::string& m_path,
                                 const std::string& dof_path, const std::string& key) {
  FeMatrices fe;
  fe.dofs = readDofMap(dof_path, key);
  fe.K = readMatrixMarket(k_path, key);
  fe.M = readMatrixMarket(m_path, key);
  const Eigen::Index n = static_cast<Eigen::Index>(fe.dofs.size());
  for (const auto& [A, path] : {std::pair{&fe.K, &k_path}, std::pair{&fe.M, &m_path}}) {
    if (A->rows() != n) {
      throw InputError(key, *path,
                       fmt::format("{} rows, one per line of the DOF map {} ({} found)", n,
                                   dof_path, A->rows()));
    }
    const Eigen::SparseMatrix<double> At = A->transpose();
    const double asym = (*A - At).norm(), size = A->norm();
    // Round-off of an exported symmetric matrix: its entries printed to ~1e-12 relative.
    if (asym > 1e-9 * size) {
      throw InputError(key, *path,
                       fmt::format("a symmetric matrix (‖A − Aᵀ‖/‖A‖ = {:.2g})", asym / size));
    }
  }
  return fe;
}

}  // namespace geardyn::io
