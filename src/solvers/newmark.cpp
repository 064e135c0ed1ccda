#include "geardyn/solvers/newmark.h"

#include <fmt/format.h>

#include "geardyn/error.h"

namespace geardyn {

void NewmarkParameters::validate() const {
  if (!(beta > 0.0 && beta <= 0.5)) {
    throw InputError("solver.beta", fmt::format("{:g}", beta), "must be in (0, 0.5]");
  }
  if (!(gamma >= 0.5 && gamma <= 1.0)) {
    throw InputError("solver.gamma", fmt::format("{:g}", gamma), "must be in [0.5, 1]");
  }
}

}  // namespace geardyn
