/// The shafts of a gear train: rigid bodies (mass, inertias and mass centre from their own
/// values, sections, gears and disks) or flexible chains of Timoshenko beam elements with a
/// node at every section end, gear, bearing, disk and torque position (gear_train_model.h).
///
/// Node DOF order (kFull): (y, z, θ_x, x, θ_y, θ_z). The beam element matrices are those of
/// the FE geared rotor (models/timoshenko_shaft_element.h, order [u_x, u_y, u_z, θ_x, θ_y,
/// θ_z]) permuted to it, so a flexible train reproduces fe_geared_rotor's matrices.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geardyn/error.h"
#include "geardyn/models/timoshenko_shaft_element.h"
#include "geardyn/system/detail/train_building.h"
#include "geardyn/system/gear_train_model.h"

namespace geardyn {
namespace detail {

/// Position in the train's node order of FE DOF k (kUx … kRz).
constexpr int kFullOffset[kNodeDofs] = {3, 0, 1, 2, 4, 5};

std::vector<ShaftSection> shaftSections(const TrainShaftSpec& shaft) {
  const std::string key = "shafts." + shaft.name;
  const std::size_t n = shaft.section_lengths.size();
  auto item = [&](const std::vector<double>& values, std::size_t i, const char* name) {
    if (values.empty()) return 0.0;
    if (values.size() == 1) return values[0];
    if (values.size() != n) {
      throw InputError(key + "." + name, fmt::format("{} values", values.size()),
                       fmt::format("one value or one per section ({})", n));
    }
    return values[i];
  };
  std::vector<ShaftSection> sections;
  double start = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    ShaftSection s;
    s.start = start;
    s.length = shaft.section_lengths[i];
    s.outer_radius = 0.5 * item(shaft.outer_diameters, i, "outer_diameters");
    s.inner_radius = 0.5 * item(shaft.inner_diameters, i, "inner_diameters");
    if (!(s.length > 0.0) || !std::isfinite(s.length) || !(s.outer_radius > 0.0) ||
        !(s.inner_radius >= 0.0 && s.inner_radius < s.outer_radius)) {
      throw InputError(key + ".section_lengths",
                       fmt::format("section {}: length {:g} m, diameters {:g}/{:g} m", i, s.length,
                                   2 * s.outer_radius, 2 * s.inner_radius),
                       "lengths > 0 and 0 <= inner < outer diameter");
    }
    s.mass = shaft.density * std::numbers::pi *
             (s.outer_radius * s.outer_radius - s.inner_radius * s.inner_radius) * s.length;
    sections.push_back(s);
    start += s.length;
  }
  return sections;
}

double shaftLength(const TrainShaftSpec& shaft) {
  double length = 0.0;
  for (double l : shaft.section_lengths) length += l;
  return length;
}

void MassSum::add(double m, double polar, double diametral, double x) {
  mass += m;
  first_moment += m * x;
  polar_inertia += polar;
  diametral_about_origin += diametral + m * x * x;
}

double MassSum::centre() const {
  return mass > 0.0 ? first_moment / mass : 0.0;
}

double MassSum::diametralAboutCentre() const {
  return diametral_about_origin - mass * centre() * centre();
}

void addSectionMasses(const std::vector<ShaftSection>& sections, MassSum& sum) {
  for (const auto& s : sections) {
    const double r2 = s.outer_radius * s.outer_radius + s.inner_radius * s.inner_radius;
    sum.add(s.mass, 0.5 * s.mass * r2, s.mass * (3.0 * r2 + s.length * s.length) / 12.0,
            s.start + 0.5 * s.length);
  }
}

}  // namespace detail

void GearTrainModel::buildShaftNodes(int s) {
  const TrainShaftSpec& shaft = spec_.shafts[s];
  const std::string key = "shafts." + shaft.name;
  const auto sections = detail::shaftSections(shaft);
  if (sections.empty()) {
    throw InputError(key + ".section_lengths", "[]",
                     "at least one section on a flexible shaft (its beam elements)");
  }
  if (shaft.mass != 0.0 || shaft.polar_inertia != 0.0 || shaft.diametral_inertia != 0.0) {
    throw InputError(key + ".mass", fmt::format("{:g} kg", shaft.mass),
                     "0 on a flexible shaft: its sections carry its mass; put lumped masses in "
                     "[disks.<name>] at a position");
  }
  if (!(shaft.youngs_modulus > 0.0) || !std::isfinite(shaft.youngs_modulus)) {
    throw InputError(key + ".youngs_modulus", fmt::format("{:g} Pa", shaft.youngs_modulus),
                     "a modulus > 0");
  }
  if (!(shaft.poisson_ratio >= 0.0 && shaft.poisson_ratio < 0.5)) {
    throw InputError(key + ".poisson_ratio", fmt::format("{:g}", shaft.poisson_ratio),
                     "a ratio in [0, 0.5)");
  }
  if (shaft.max_element_length && !(*shaft.max_element_length > 0.0)) {
    throw InputError(key + ".max_element_length", fmt::format("{:g} m", *shaft.max_element_length),
                     "a length > 0");
  }
  const double length = detail::shaftLength(shaft);
  const double tol = 1e-9 * length;
  // Node positions: section ends and every position something is attached at.
  std::vector<double> x{0.0};
  for (const auto& sec : sections) x.push_back(sec.start + sec.length);
  auto attach = [&](double position, const std::string& where) {
    if (!std::isfinite(position) || position < -tol || position > length + tol) {
      throw InputError(
          where, fmt::format("{:g} m", position),
          fmt::format("a position on shaft \"{}\", in [0, {:g}] m", shaft.name, length));
    }
    x.push_back(std::clamp(position, 0.0, length));
  };
  for (const auto& g : spec_.gears)
    if (g.shaft == shaft.name) attach(g.position, "gears." + g.name + ".position");
  for (const auto& b : spec_.bearings) {
    if (b.shaft == shaft.name) attach(b.position, "bearings." + b.name + ".position");
    if (b.other_shaft == shaft.name)
      attach(b.other_position, "bearings." + b.name + ".other_position");
  }
  for (const auto& d : spec_.disks)
    if (d.shaft == shaft.name) attach(d.position, "disks." + d.name + ".position");
  const OperatingPoint& op = spec_.operating;
  if (op.input_shaft == shaft.name && op.input_position)
    attach(*op.input_position, "operating_point.input_position");
  if (op.output_shaft == shaft.name && op.output_position)
    attach(*op.output_position, "operating_point.output_position");
  std::sort(x.begin(), x.end());
  std::vector<double> nodes{x.front()};
  for (double xi : x) {
    if (xi - nodes.back() > tol) nodes.push_back(xi);
  }
  // Split long elements evenly, once the nodes are known to fit (their count as a double: a
  // tiny max_element_length must not overflow an int or allocate before it is refused).
  if (shaft.max_element_length) {
    double count = static_cast<double>(bodies_.size()) + 1.0;
    for (std::size_t i = 1; i < nodes.size(); ++i) {
      count +=
          std::max(1.0, std::ceil((nodes[i] - nodes[i - 1]) / *shaft.max_element_length - 1e-9));
    }
    checkDenseFits(count * dofsPerBody(), key + ".max_element_length",
                   fmt::format("{:g} m", *shaft.max_element_length));
  }
  if (shaft.max_element_length) {
    std::vector<double> fine{nodes.front()};
    for (std::size_t i = 1; i < nodes.size(); ++i) {
      const double span = nodes[i] - nodes[i - 1];
      const int parts =
          std::max(1, static_cast<int>(std::ceil(span / *shaft.max_element_length - 1e-9)));
      for (int p = 1; p <= parts; ++p) fine.push_back(nodes[i - 1] + span * p / parts);
    }
    nodes = fine;
  }
  const double shear_modulus = shaft.youngs_modulus / (2.0 * (1.0 + shaft.poisson_ratio));
  std::vector<int>& chain = shaft_nodes_[s];
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    TrainBody body;
    body.name = fmt::format("{}.n{}", shaft.name, k);
    body.shaft = s;
    body.axial = shaft.axial_offset + nodes[k];
    chain.push_back(static_cast<int>(bodies_.size()));
    bodies_.push_back(body);
    if (k == 0) continue;
    const double mid = 0.5 * (nodes[k - 1] + nodes[k]);
    const auto sec = std::find_if(sections.begin(), sections.end(), [&](const auto& c) {
      return mid >= c.start && mid <= c.start + c.length;
    });
    ShaftSegment seg;
    seg.length = nodes[k] - nodes[k - 1];
    seg.outer_diameter = 2.0 * sec->outer_radius;
    seg.inner_diameter = 2.0 * sec->inner_radius;
    seg.youngs_modulus = shaft.youngs_modulus;
    seg.shear_modulus = shear_modulus;
    seg.density = shaft.density;
    seg.validate(key);
    beams_.push_back({s, static_cast<int>(k) - 1, chain[k - 1], chain[k], seg});
  }
}

int GearTrainModel::bodyAt(int shaft, double position, const std::string& key) const {
  const TrainShaftSpec& spec = spec_.shafts[shaft];
  const double length = detail::shaftLength(spec);
  const double tol = 1e-9 * std::max(length, 1e-3);
  if (!std::isfinite(position) || (length > 0.0 && (position < -tol || position > length + tol))) {
    throw InputError(key, fmt::format("{:g} m", position),
                     fmt::format("a position on shaft \"{}\", in [0, {:g}] m", spec.name, length));
  }
  if (!spec.flexible) return shaft_body_[shaft];
  for (int b : shaft_nodes_[shaft]) {
    if (std::abs(bodies_[b].axial - spec.axial_offset - position) <= tol) return b;
  }
  throw InputError(key, fmt::format("{:g} m", position),
                   fmt::format("a node position of shaft \"{}\"", spec.name));
}

double GearTrainModel::axialOffsetOf(int body, int shaft, double position) const {
  return spec_.shafts[shaft].axial_offset + position - bodies_[body].axial;
}

void GearTrainModel::assembleBeams() {
  for (const BeamElement& beam : beams_) {
    const ElementMatrix m = shaftElementMass(beam.segment);
    const ElementMatrix g = shaftElementGyroscopic(beam.segment);
    const double ratio = bodies_[beam.body_a].speed_ratio;
    const auto index = beamDofs(beam);
    for (int i = 0; i < 2 * kNodeDofs; ++i) {
      for (int j = 0; j < 2 * kNodeDofs; ++j) {
        M_(index[i], index[j]) += m(i, j);
        G_(index[i], index[j]) += ratio * g(i, j);
      }
    }
  }
}

std::vector<int> GearTrainModel::beamDofs(const BeamElement& beam) const {
  std::vector<int> index(2 * kNodeDofs);
  for (int d = 0; d < kNodeDofs; ++d) {
    index[d] = bodies_[beam.body_a].first_dof + detail::kFullOffset[d];
    index[kNodeDofs + d] = bodies_[beam.body_b].first_dof + detail::kFullOffset[d];
  }
  return index;
}

void GearTrainModel::addBeamElements() {
  for (const BeamElement& beam : beams_) {
    TrainElement e;
    e.name = fmt::format("{}.beam{}", spec_.shafts[beam.shaft].name, beam.index);
    e.kind = "shaft";
    e.dofs = beamDofs(beam);
    e.stiffness = shaftElementStiffness(beam.segment);
    e.jacobian = Eigen::MatrixXd::Identity(2 * kNodeDofs, 2 * kNodeDofs);
    e.local_stiffness = e.stiffness;
    for (int dof : e.dofs) e.moment_rows.push_back(dofName(dof).find("theta") != std::string::npos);
    // Material damping β_s K_e of the shaft (Visnadi & de Castro 2021 eq. 10).
    element_damping_.push_back(spec_.shafts[beam.shaft].stiffness_proportional_damping *
                               e.stiffness);
    elements_.push_back(e);
  }
}

double GearTrainModel::rotatingInertia(int body) const {
  // A node of a flexible shaft: its lumped inertia and half of its beams'.
  double inertia = bodies_[body].polar_inertia;
  for (const BeamElement& beam : beams_) {
    if (beam.body_a == body || beam.body_b == body) {
      inertia +=
          0.5 * beam.segment.density * beam.segment.polarMomentOfArea() * beam.segment.length;
    }
  }
  return inertia;
}

}  // namespace geardyn
