#include "geardyn/stiffness/tabulated_stiffness.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "geardyn/error.h"

namespace geardyn {

TabulatedMeshStiffness::TabulatedMeshStiffness(std::vector<double> phases,
                                               std::vector<double> values, double contact_ratio,
                                               std::string name)
    : phases_(std::move(phases)),
      values_(std::move(values)),
      contact_ratio_(contact_ratio),
      name_(std::move(name)) {
  if (phases_.size() != values_.size() || phases_.size() < 2) {
    throw InputError("stiffness table",
                     fmt::format("{} phases, {} values", phases_.size(), values_.size()),
                     "as many phases as values, at least 2");
  }
  for (std::size_t i = 0; i < phases_.size(); ++i) {
    if (!(phases_[i] >= 0.0 && phases_[i] < 1.0) || (i > 0 && !(phases_[i] > phases_[i - 1]))) {
      throw InputError("stiffness table", fmt::format("phase {} = {:g}", i, phases_[i]),
                       "phases ascending in [0, 1)");
    }
    if (!(values_[i] > 0.0) || !std::isfinite(values_[i])) {
      throw InputError("stiffness table", fmt::format("value {} = {:g}", i, values_[i]),
                       "stiffness must be finite and > 0 [N/m]");
    }
  }
  if (!(contact_ratio_ > 0.0) || !std::isfinite(contact_ratio_)) {
    throw InputError("contact_ratio", fmt::format("{:g}", contact_ratio_), "must be > 0");
  }
}

double TabulatedMeshStiffness::stiffness(double phase) const {
  const double p = wrapPhase(phase);
  const auto hi = std::upper_bound(phases_.begin(), phases_.end(), p);
  const std::size_t n = phases_.size();
  const std::size_t b = hi == phases_.end() ? 0 : static_cast<std::size_t>(hi - phases_.begin());
  const std::size_t a = (b + n - 1) % n;
  const double pa = phases_[a], pb = b > a ? phases_[b] : phases_[b] + 1.0;
  const double x = p >= pa ? p : p + 1.0;
  return values_[a] + (values_[b] - values_[a]) * (x - pa) / (pb - pa);
}

}  // namespace geardyn
