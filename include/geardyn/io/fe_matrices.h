#pragma once
/// \file
/// Assembled finite-element stiffness and mass matrices from a finite-element tool (issue #37,
/// item 1): CalculiX's `*FREQUENCY, SOLVER=MATRIXSTORAGE` files and MatrixMarket K, M with a DOF
/// map. File formats only; what is done with the matrices (seat condensation, Craig–Bampton) is
/// in models/housing_superelement.h.
///
/// CalculiX CrunchiX User's Manual (ccx 2.20), *FREQUENCY: "If the MATRIXSTORAGE option is used,
/// the stiffness and mass matrices are stored in files jobname.sti and jobname.mas". Checked on
/// ccx 2.20 (Debian calculix-ccx) with a two-hexahedron deck:
///   - jobname.sti / jobname.mas: one entry a line, `row column value`, 1-based equation numbers,
///     the upper triangle (row <= column) column by column, explicit zeros included;
///   - jobname.dof: line i is equation i's `node.direction` (direction 1..3 = x, y, z; a DOF
///     fixed by *BOUNDARY has no equation and no line).
/// The values are in the deck's own consistent units (N/mm and t for an mm-t-s deck).

#include <Eigen/Sparse>
#include <string>
#include <vector>

namespace geardyn::io {

/// One equation of an assembled finite-element model: a node's translation.
struct FeDof {
  int node = 0;       ///< the node number as in the deck
  int direction = 0;  ///< 1, 2, 3 = x, y, z
};

/// Symmetric K and M of a finite-element model (both triangles stored) with the DOF of each row.
struct FeMatrices {
  Eigen::SparseMatrix<double> K;  ///< stiffness, in the source's units
  Eigen::SparseMatrix<double> M;  ///< mass, in the source's units
  std::vector<FeDof> dofs;        ///< dofs[i] is row/column i's node and direction
};

/// Reads ccx's jobname.sti, jobname.mas, jobname.dof (see the file comment). Throws
/// InputError(key, file, ...) on a malformed line (the file, line number and text) or on sizes
/// that disagree; IoError when a file cannot be opened.
FeMatrices readCcxMatrixStorage(const std::string& sti_path, const std::string& mas_path,
                                const std::string& dof_path, const std::string& key);

/// Reads a MatrixMarket `coordinate real symmetric|general` matrix; a symmetric file holds one
/// triangle and is mirrored. Throws InputError(key, path, ...) on a malformed file.
Eigen::SparseMatrix<double> readMatrixMarket(const std::string& path, const std::string& key);

/// Reads a DOF map in ccx's .dof form (one `node.direction` a line, row order). Throws
/// InputError(key, path, ...) on a malformed line.
std::vector<FeDof> readDofMap(const std::string& path, const std::string& key);

/// K and M in MatrixMarket with their DOF map (how Abaqus, Nastran or ANSYS users bring an
/// assembled model, docs/guide/housing.md); checks the three agree in size and symmetry.
FeMatrices readMatrixMarketModel(const std::string& k_path, const std::string& m_path,
                                 const std::string& dof_path, const std::string& key);

/// Bytes a line of ccx's .sti takes at least ("1 1 -1.0000000000000e+00\n"): the number of
/// entries a file holds is at most its size over this, so a model's size is known before it is
/// read.
inline constexpr double kMinBytesPerMatrixLine = 24.0;

}  // namespace geardyn::io
