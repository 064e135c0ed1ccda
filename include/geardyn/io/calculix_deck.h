#pragma once
/// \file
/// A CalculiX deck (`.inp`, the Abaqus keyword format) as a housing's source (issue #37, item 1):
/// the node coordinates and node sets geardyn needs (bearing seats, response points), read from
/// the deck, and a run of `ccx` that assembles its K and M.
///
/// The deck holds the mesh, the material and the mounting (`*BOUNDARY` on the feet), no *STEP:
/// geardyn adds the step. `runCalculix` writes, in a new temporary folder,
///   job.inp = `*INCLUDE, INPUT=<the deck>` + `*STEP` / `*FREQUENCY, SOLVER=MATRIXSTORAGE` /
///   `*END STEP`
/// and runs `ccx -i job` there (CalculiX CrunchiX User's Manual, ccx 2.20, *FREQUENCY and
/// *INCLUDE); ccx's messages are shown when it fails, the folder is removed afterwards.

#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

#include "geardyn/io/fe_matrices.h"

namespace geardyn::io {

/// What geardyn reads of a deck itself: nodes and node sets (names upper-cased, as ccx does).
struct CalculixDeck {
  std::map<int, Eigen::Vector3d> nodes;           ///< node number -> coordinates [deck units]
  std::map<std::string, std::vector<int>> nsets;  ///< *NSET name (upper case) -> node numbers
  long elements = 0;                              ///< number of element lines (for estimates)
  bool has_step = false;                          ///< the deck has its own *STEP
};

/// Reads *NODE, *NSET (plain lists, other sets' names, GENERATE), *ELEMENT line counts and
/// *INCLUDE (relative to the including file). Throws InputError(key, path, ...) naming the line
/// of a malformed card; IoError when a file cannot be opened.
CalculixDeck readCalculixDeck(const std::string& path, const std::string& key);

/// What a ccx run needs, estimated from the deck before it runs [B]: the assembled K and M
/// (3 DOFs a node, `kEntriesPerDof` upper-triangle entries a DOF, triplets while reading) and the
/// sparse factorisation of the reduction (`kFillPerEntry` times K's entries).
double estimateHousingBytes(const CalculixDeck& deck);

/// Refuses a housing whose estimate (estimateHousingBytes) exceeds `limit_bytes` before ccx runs
/// or anything is allocated: InputError(key, path, the node count, the estimate and the limit).
/// The caller passes analysis::memoryLimitBytes() (80 % of MemAvailable, GEARDYN_MEMORY_LIMIT).
void checkHousingFits(const CalculixDeck& deck, const std::string& path, const std::string& key,
                      double limit_bytes);

/// Runs `ccx` (the executable `ccx_command`, found on PATH) on the deck at `path` as described in
/// the file comment and reads the matrices it writes. InputError(key, path, ccx's *ERROR lines)
/// when ccx rejects the deck or writes no matrices; InputError(key, path, "ccx ... not found")
/// when ccx is missing.
/// `fixed_sets`: node sets held in x, y, z by a `*BOUNDARY` geardyn adds (the housing's fixed
/// mounts) besides the deck's own.
FeMatrices runCalculix(const std::string& path, const std::string& key,
                       const std::string& ccx_command = "ccx",
                       const std::vector<std::string>& fixed_sets = {});

/// Upper-triangle entries a DOF of a 3-D solid mesh has in K (second-order tetrahedra: about 40
/// neighbour nodes × 3 DOFs / 2); the estimate's basis.
inline constexpr double kEntriesPerDof = 60.0;
/// Fill of a nested-dissection sparse factorisation of a 3-D solid mesh relative to K's entries
/// (Eigen's SimplicialLDLT with AMD ordering on 10-50 k DOF housings: 10-30).
inline constexpr double kFillPerEntry = 30.0;

}  // namespace geardyn::io
