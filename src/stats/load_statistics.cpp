#include "geardyn/stats/load_statistics.h"

#include <fmt/format.h>

#include "geardyn/error.h"
#include "geardyn/stiffness/tabulated_stiffness.h"

namespace geardyn {

std::vector<LoadStatistics> meanExcitationAgainstLoad(const LoadedToothContact& contact,
                                                      double design_load,
                                                      const std::vector<double>& loads,
                                                      int positions, double* mean_stiffness,
                                                      const ProgressCallback& progress) {
  if (!(design_load > 0.0)) {
    throw InputError("ltca.design_load", fmt::format("{:g}", design_load), "must be > 0 [N]");
  }
  double k_bar = 0.0;
  for (const auto& p : contact.sweep(design_load, positions)) k_bar += p.tangent / positions;
  if (mean_stiffness) *mean_stiffness = k_bar;
  const double x0 = design_load / k_bar;
  std::vector<LoadStatistics> out;
  for (double a : loads) {
    if (progress) progress(static_cast<double>(out.size()), static_cast<double>(loads.size()));
    if (!(a > 0.0)) throw InputError("ltca.statistics_loads", fmt::format("{:g}", a), "> 0");
    LoadStatistics s;
    s.a = a;
    std::vector<double> k, e;
    for (const auto& p : contact.sweep(a * design_load, positions)) {
      s.phase.push_back(p.phase);
      s.tangent.push_back(p.tangent);
      s.ste.push_back(p.ste);
      k.push_back(p.tangent / k_bar);
      e.push_back(p.ste / x0);
    }
    s.statistics = meanExcitationFromSamples(k, e, a, 0.0);
    out.push_back(std::move(s));
  }
  return out;
}

GearPairModelSpec gearPairModelAtLoad(const LoadStatistics& load, double force, double mass,
                                      double damping, double mesh_frequency, double contact_ratio) {
  GearPairModelSpec spec;
  spec.mass = mass;
  spec.damping = damping;
  spec.mean_force = force;
  spec.mesh_frequency = mesh_frequency;
  spec.stiffness = std::make_shared<TabulatedMeshStiffness>(load.phase, load.tangent, contact_ratio,
                                                            "ltca_tangent");
  std::vector<double> error;
  for (std::size_t i = 0; i < load.phase.size(); ++i)
    error.push_back(load.ste[i] - force / load.tangent[i]);
  spec.transmission_error.addTable(load.phase, error);
  return spec;
}

}  // namespace geardyn
