#pragma once
/// \file
/// A mesh stiffness given as a table over one mesh period (e.g. the tangent stiffness of a
/// loaded tooth contact analysis, or a measured curve): periodic, piecewise linear between the
/// samples; every sample is a breakpoint, so statistics integrate it exactly.

#include <string>
#include <vector>

#include "geardyn/stiffness/mesh_stiffness.h"

namespace geardyn {

class TabulatedMeshStiffness final : public MeshStiffness {
 public:
  /// Ascending phases in [0, 1) and positive finite stiffnesses [N/m]; `contact_ratio` is
  /// reported as given. Throws InputError otherwise.
  TabulatedMeshStiffness(std::vector<double> phases, std::vector<double> values,
                         double contact_ratio, std::string name = "tabulated");

  std::string model() const override { return name_; }
  double stiffness(double phase) const override;
  std::vector<double> discontinuities() const override { return phases_; }
  double contactRatio() const override { return contact_ratio_; }

 private:
  std::vector<double> phases_, values_;
  double contact_ratio_;
  std::string name_;
};

}  // namespace geardyn
