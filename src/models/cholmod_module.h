#pragma once
/// \file
/// The boundary to CHOLMOD (SuiteSparse; issue #37, "Performance"). The housing's K_oo is
/// factorised by CHOLMOD's supernodal Cholesky with METIS nested-dissection ordering in
/// libgeardyn_cholmod.so (cholmod_module.cpp), loaded on the first housing reduction like
/// libgeardyn_hdf5.so (module_loader.h): CHOLMOD brings METIS, BLAS, LAPACK and gfortran, which a
/// command without a housing should not map at start-up (issue 22). Why supernodal + METIS: a
/// 3-D solid mesh's factor is dominated by dense separator blocks, which a supernodal
/// factorisation handles as dense BLAS-3 blocks, and nested dissection keeps their fill lower
/// than minimum degree (AMD) does on 3-D meshes. Measured on the 35 k-DOF box (K with its feet
/// held, 1.17 M stored entries, Debian's reference BLAS): Eigen's SimplicialLDLT with AMD
/// 8.4 s CPU and 10.3 M entries in L; CHOLMOD supernodal with METIS 2.35 s CPU and 8.4 M.
/// The module exchanges plain arrays and reports failures as values, never as exceptions (it may
/// run on another copy of the C++ runtime than the executable).

namespace geardyn::detail {

inline constexpr int kCholmodModuleVersion = 1;

/// What a factorisation ended with.
enum CholmodStatus : int {
  kCholmodOk = 0,
  kCholmodNotPositiveDefinite = 1,
  kCholmodFailed = 2,  ///< out of memory or another CHOLMOD error
};

/// The functions of libgeardyn_cholmod.so.
struct CholmodModuleApi {
  int version;
  /// Factorises the symmetric positive definite n × n matrix given by its lower triangle in
  /// compressed columns (col_ptr[n + 1], row_index, value; 0-based, rows ascending in a
  /// column). Returns the factor, or nullptr with *status set; *factor_entries = entries of L.
  void* (*factorise)(int n, const int* col_ptr, const int* row_index, const double* value,
                     int* status, double* factor_entries);
  /// B ← A⁻¹ B for B n × nrhs, column-major. 0 on success.
  int (*solve)(void* factor, int nrhs, double* b);
  /// Frees the factor.
  void (*release)(void* factor);
};

}  // namespace geardyn::detail
