/// libgeardyn_cholmod.so: the only translation unit that calls CHOLMOD (see cholmod_module.h).
/// Built as a module of its own and loaded on demand; no geardyn symbol is used here, no
/// exception leaves.

#include "cholmod_module.h"

#include <cholmod.h>

#include <cstring>
#include <new>

namespace geardyn::detail {
namespace {

struct Factor {
  cholmod_common common;
  cholmod_factor* L = nullptr;
  int n = 0;
};

void* factorise(int n, const int* col_ptr, const int* row_index, const double* value, int* status,
                double* factor_entries) {
  Factor* f = new (std::nothrow) Factor;
  if (f == nullptr) {
    *status = kCholmodFailed;
    return nullptr;
  }
  f->n = n;
  cholmod_start(&f->common);
  f->common.print = 0;
  f->common.supernodal = CHOLMOD_SUPERNODAL;
  // METIS nested dissection only (the default also tries AMD and keeps the better, a second
  // symbolic analysis for nothing on a 3-D mesh).
  f->common.nmethods = 1;
  f->common.method[0].ordering = CHOLMOD_METIS;
  f->common.postorder = 1;
  cholmod_sparse A;
  std::memset(&A, 0, sizeof A);
  A.nrow = A.ncol = static_cast<std::size_t>(n);
  A.nzmax = static_cast<std::size_t>(col_ptr[n]);
  A.p = const_cast<int*>(col_ptr);
  A.i = const_cast<int*>(row_index);
  A.x = const_cast<double*>(value);
  A.stype = -1;  // the lower triangle
  A.itype = CHOLMOD_INT;
  A.xtype = CHOLMOD_REAL;
  A.dtype = CHOLMOD_DOUBLE;
  A.sorted = 1;
  A.packed = 1;
  f->L = cholmod_analyze(&A, &f->common);
  if (f->L != nullptr) cholmod_factorize(&A, f->L, &f->common);
  if (f->L == nullptr || f->common.status != CHOLMOD_OK || f->L->minor < f->L->n) {
    *status = (f->L != nullptr && f->common.status == CHOLMOD_NOT_POSDEF) ||
                      (f->L != nullptr && f->L->minor < f->L->n)
                  ? kCholmodNotPositiveDefinite
                  : kCholmodFailed;
    if (f->L != nullptr) cholmod_free_factor(&f->L, &f->common);
    cholmod_finish(&f->common);
    delete f;
    return nullptr;
  }
  *status = kCholmodOk;
  *factor_entries = f->common.lnz;
  return f;
}

int solve(void* factor, int nrhs, double* b) {
  Factor* f = static_cast<Factor*>(factor);
  cholmod_dense B;
  std::memset(&B, 0, sizeof B);
  B.nrow = static_cast<std::size_t>(f->n);
  B.ncol = static_cast<std::size_t>(nrhs);
  B.nzmax = B.nrow * B.ncol;
  B.d = B.nrow;
  B.x = b;
  B.xtype = CHOLMOD_REAL;
  B.dtype = CHOLMOD_DOUBLE;
  cholmod_dense* X = cholmod_solve(CHOLMOD_A, f->L, &B, &f->common);
  if (X == nullptr) return 1;
  std::memcpy(b, X->x, sizeof(double) * B.nzmax);
  cholmod_free_dense(&X, &f->common);
  return 0;
}

void release(void* factor) {
  Factor* f = static_cast<Factor*>(factor);
  cholmod_free_factor(&f->L, &f->common);
  cholmod_finish(&f->common);
  delete f;
}

constexpr CholmodModuleApi kApi{kCholmodModuleVersion, factorise, solve, release};

}  // namespace
}  // namespace geardyn::detail

extern "C" __attribute__((visibility("default"))) const geardyn::detail::CholmodModuleApi*
geardyn_cholmod_module() {
  return &geardyn::detail::kApi;
}
