/// The meshes of a gear train: kinematics, layout of the shaft centres, mesh geometry, the
/// loaded flank of every mesh, its deflection gradient, damping, frequency and phase.
///
/// Mesh deflection (docs/theory/gear_trains.md). Gear a and gear b touch at the operating
/// pitch point c; the transverse line of action has the unit direction
///   n_t = σ cos α_wt t + sin α_wt s,   t = x̂ × e,
/// with e the unit vector from a's centre to b's, s the direction in which the contact force
/// pushes b radially (s = e for an external mesh, −e when one member is a ring) and σ = ±1 the
/// loaded flank. The deflection (compression) along the normal, whose transverse part is
/// cos β_b n_t, is δ = cos β_b n_t · [u_a + θ_a x̂ × (c − c_a) − u_b − θ_b x̂ × (c − c_b)], so
/// every rigid motion and the rolling motion give δ = 0, and the mesh moment on a is
/// −F cos β_b [(c − c_a) × n_t] = −σ F r_ba cos β_b. With a = sun or ring and b = planet this is
/// Lin & Parker's (1999) δ_sn and δ_rn term by term (σ = +1).

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include "geardyn/error.h"
#include "geardyn/geometry/gear_pair.h"
#include "geardyn/geometry/internal_gear_pair.h"
#include "geardyn/stiffness/mesh_stiffness_summary.h"
#include "geardyn/system/detail/train_building.h"
#include "geardyn/system/gear_train_model.h"
#include "geardyn/system/planet_phasing.h"

namespace geardyn {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

/// Operating geometry of one mesh, whichever the pair type.
struct PairGeometry {
  double centre_distance, pressure_angle, base_helix, rb_a, rb_b, rw_a, rw_b, contact_ratio;
};

PairGeometry externalPair(const GearSpec& a, const GearSpec& b, std::optional<double> distance,
                          const std::string& key_a, const std::string& key_b,
                          const std::string& key_pair, std::vector<std::string>& warnings) {
  GearPairSpec spec;
  spec.pinion = a;
  spec.gear = b;
  spec.centre_distance = distance;
  const GearPair pair = makeGearPair(spec, key_a, key_b, key_pair);
  // Implausible modules and face widths are noted once per gear under its own key (the
  // gearbox description); the pair's notes name them "pinion" and "gear".
  auto implausible = plausibilityNotes(a, "pinion");
  for (auto& note : plausibilityNotes(b, "gear")) implausible.push_back(std::move(note));
  for (const auto& w : pair.warnings()) {
    if (std::find(implausible.begin(), implausible.end(), w) == implausible.end())
      warnings.push_back(key_pair + ": " + w);
  }
  return {pair.centreDistance(),
          pair.operatingPressureAngle(),
          pair.baseHelixAngle(),
          pair.pinion().base_radius,
          pair.gear().base_radius,
          pair.pinion().operating_pitch_radius,
          pair.gear().operating_pitch_radius,
          pair.contactRatioTotal()};
}

/// `ring_is_a`: the ring is member a (its radii go first).
PairGeometry internalPair(const GearSpec& pinion, const GearSpec& ring, bool ring_is_a,
                          std::optional<double> distance, const std::string& key_pair) {
  const InternalGearPair pair(pinion, ring, distance, key_pair);
  const double c = std::cos(pair.operatingPressureAngle());
  const double rbp = pair.pinionBaseRadius(), rbr = pair.ringBaseRadius();
  PairGeometry g{pair.centreDistance(),
                 pair.operatingPressureAngle(),
                 pair.baseHelixAngle(),
                 rbp,
                 rbr,
                 rbp / c,
                 rbr / c,
                 pair.contactRatioTransverse() + pair.overlapRatio()};
  if (ring_is_a) std::swap(g.rb_a, g.rb_b), std::swap(g.rw_a, g.rw_b);
  return g;
}

/// The body of spec.gears[g] (a flexible shaft's node at its position).
int bodyOfGear(const GearTrainModel& model, const GearTrainSpec& spec, int g) {
  return detail::bodyAtOf(model, spec.gears[g].shaft, "gears." + spec.gears[g].name + ".shaft",
                          spec.gears[g].position, "gears." + spec.gears[g].name + ".position");
}

/// A mesh between bodies a and b with loaded flank σ = +1: its geometry, pitch point and
/// transverse line of action (see the file comment).
TrainMesh placedMesh(const std::vector<TrainBody>& bodies, std::string name, TrainMeshKind kind,
                     int a, int b, int za, int zb, const PairGeometry& g, bool ring_is_a) {
  TrainMesh m;
  m.name = std::move(name);
  m.kind = kind;
  m.body_a = a, m.body_b = b, m.teeth_a = za, m.teeth_b = zb;
  m.centre_distance = g.centre_distance;
  m.pressure_angle = g.pressure_angle;
  m.base_helix_angle = g.base_helix;
  m.base_radius_a = g.rb_a, m.base_radius_b = g.rb_b;
  m.contact_ratio = g.contact_ratio;
  const Eigen::Vector2d e = (bodies[b].centre - bodies[a].centre).normalized();
  const bool internal = kind == TrainMeshKind::kInternal || kind == TrainMeshKind::kRingPlanet;
  const bool b_is_ring = internal && !ring_is_a;
  // Pitch point: on the far side of the pinion from a ring's centre.
  m.pitch_point = b_is_ring ? Eigen::Vector2d(bodies[a].centre - g.rw_a * e)
                            : Eigen::Vector2d(bodies[a].centre + g.rw_a * e);
  m.normal = std::cos(g.pressure_angle) * Eigen::Vector2d(-e.y(), e.x()) +
             std::sin(g.pressure_angle) * (internal ? -e : e);
  return m;
}

/// The mesh's stiffness, transmission error, damping ratio and contact, checked (InputError
/// naming `key`).
void setMeshModel(TrainMesh& m, const std::shared_ptr<const MeshStiffness>& stiffness,
                  const TransmissionError& error, double zeta, const TrainMeshContact& contact,
                  const std::string& key) {
  const bool internal = m.kind == TrainMeshKind::kInternal || m.kind == TrainMeshKind::kRingPlanet;
  if (!stiffness) throw InputError(key + ".stiffness", "", "a mesh-stiffness model");
  m.stiffness = stiffness;
  m.mean_stiffness = summarizeMeshStiffness(*stiffness, 0).mean;
  if (!(m.mean_stiffness > 0.0) || !std::isfinite(m.mean_stiffness)) {
    throw InputError(key + ".stiffness", fmt::format("{:g} N/m mean", m.mean_stiffness),
                     "a mesh stiffness with a positive mean");
  }
  if (!(zeta >= 0.0) || !std::isfinite(zeta)) {
    throw InputError(key + ".damping_ratio", fmt::format("{:g}", zeta), "a ratio >= 0");
  }
  m.transmission_error = error;
  m.damping_ratio = zeta;
  if (!(contact.backlash >= 0.0) || !std::isfinite(contact.backlash) ||
      (contact.law == ContactLaw::kBacklash && !(contact.backlash > 0.0))) {
    throw InputError(key + ".backlash", fmt::format("{:g} m", contact.backlash),
                     contact.law == ContactLaw::kBacklash
                         ? "a backlash > 0 m (contact = \"backlash\")"
                         : "a backlash >= 0 m");
  }
  if (contact.tooth_pairs) {
    if (internal) {
      throw InputError(key + ".contact", "\"tooth_pairs\"",
                       "linear, one_sided or backlash on a ring (internal) mesh: the loaded "
                       "tooth contact is written for external pairs");
    }
    if (contact.law != ContactLaw::kOneSided || contact.tooth_pairs->count() < 1) {
      throw InputError(key + ".contact", "\"tooth_pairs\"",
                       "at least one one-sided contact element and no backlash");
    }
  }
  m.contact = contact;
}

}  // namespace

/// What the steps of buildMeshes hand on: the geometry of every fixed-axis mesh and planetary
/// stage, and the speed constraints of the kinematics.
struct GearTrainModel::MeshLayout {
  struct FixedMesh {
    int ga, gb, ba, bb;  // gears and bodies of members a and b
    PairGeometry geometry;
    TrainMeshKind kind;
  };
  struct Stage {
    int sun, ring, carrier, sun_gear, ring_gear;  // bodies; gears
    PairGeometry sun_planet, ring_planet;
    std::vector<double> angles;  // planet position angles [rad]
  };
  std::vector<FixedMesh> fixed;
  std::vector<Stage> stages;
  std::vector<SpeedConstraint> constraints;
};

void GearTrainModel::buildMeshes() {
  MeshLayout layout;
  addFixedAxisMeshGeometry(layout);
  addPlanetaryStageGeometry(layout);
  solveTrainKinematics(layout);
  placeShaftCentres(layout);
  createMeshes(layout);
  orientMeshesByLoad();
  // The ring-to-sun phase of each planet, from its loaded flanks (system/planet_phasing.h).
  for (std::size_t s = 0; s < layout.stages.size(); ++s) {
    const MeshLayout::Stage& g = layout.stages[s];
    const PlanetaryStageSpec& st = spec_.stages[s];
    addRingSunPhases(
        meshes_, bodies_, static_cast<int>(s), bodies_[g.carrier].speed_ratio,
        planetMeshGeometry(spec_.gears[g.sun_gear].gear, st.planet, spec_.gears[g.ring_gear].gear,
                           g.sun_planet.centre_distance, "planetary." + st.name));
  }
}

/// Fixed-axis meshes: their geometry and kinematic constraints.
void GearTrainModel::addFixedAxisMeshGeometry(MeshLayout& layout) {
  for (const TrainMeshSpec& m : spec_.meshes) {
    const std::string key = "meshes." + m.name;
    if (m.gear_a == m.gear_b) {
      throw InputError(key + ".gears", "\"" + m.gear_a + "\"", "two different gears");
    }
    const int ga = detail::gearIndexOf(spec_, m.gear_a, key + ".gears");
    const int gb = detail::gearIndexOf(spec_, m.gear_b, key + ".gears");
    const int ba = bodyOfGear(*this, spec_, ga), bb = bodyOfGear(*this, spec_, gb);
    if (spec_.gears[ga].shaft == spec_.gears[gb].shaft) {
      throw InputError(key + ".gears", fmt::format("[\"{}\", \"{}\"]", m.gear_a, m.gear_b),
                       fmt::format("gears on two different shafts: both sit on shaft \"{}\"",
                                   spec_.gears[ga].shaft));
    }
    const TrainGearSpec &A = spec_.gears[ga], &B = spec_.gears[gb];
    if (A.internal && B.internal) {
      throw InputError(key + ".gears", "", "at most one internal (ring) gear in a mesh");
    }
    if (!std::isfinite(m.position_angle)) {
      throw InputError(key + ".position_angle_deg", "", "a finite angle");
    }
    MeshLayout::FixedMesh p{ga, gb, ba, bb, {}, TrainMeshKind::kExternal};
    if (A.internal || B.internal) {
      p.kind = TrainMeshKind::kInternal;
      p.geometry = B.internal ? internalPair(A.gear, B.gear, false, m.centre_distance, key)
                              : internalPair(B.gear, A.gear, true, m.centre_distance, key);
      layout.constraints.push_back({{ba, bb}, {double(A.gear.teeth), -double(B.gear.teeth)}, key});
    } else {
      p.geometry = externalPair(A.gear, B.gear, m.centre_distance, "gears." + A.name,
                                "gears." + B.name, key, warnings_);
      layout.constraints.push_back({{ba, bb}, {double(A.gear.teeth), double(B.gear.teeth)}, key});
    }
    layout.fixed.push_back(p);
  }
}

/// Planetary stages: sun–planet and ring–planet geometry, planet angles, the planets'
/// kinematic constraints and the carrier frames.
void GearTrainModel::addPlanetaryStageGeometry(MeshLayout& layout) {
  const bool planar = spec_.dofs == TrainDofs::kPlanar;
  for (std::size_t s = 0; s < spec_.stages.size(); ++s) {
    const PlanetaryStageSpec& st = spec_.stages[s];
    const std::string key = "planetary." + st.name;
    MeshLayout::Stage g{};
    g.sun_gear = detail::gearIndexOf(spec_, st.sun, key + ".sun");
    g.ring_gear = detail::gearIndexOf(spec_, st.ring, key + ".ring");
    if (spec_.gears[g.sun_gear].internal) {
      throw InputError(key + ".sun", "\"" + st.sun + "\"", "an external gear (internal = false)");
    }
    if (!spec_.gears[g.ring_gear].internal) {
      throw InputError(key + ".ring", "\"" + st.ring + "\"", "a ring gear (internal = true)");
    }
    g.sun = bodyOfGear(*this, spec_, g.sun_gear);
    g.ring = bodyOfGear(*this, spec_, g.ring_gear);
    g.carrier = detail::shaftBodyOf(*this, spec_, st.carrier, key + ".carrier");
    if (g.sun == g.ring || g.sun == g.carrier || g.ring == g.carrier) {
      throw InputError(key, "", "sun, ring and carrier on three different shafts");
    }
    const GearSpec &sun = spec_.gears[g.sun_gear].gear, &ring = spec_.gears[g.ring_gear].gear;
    g.sun_planet = externalPair(sun, st.planet, std::nullopt, "gears." + st.sun, key + ".planet",
                                key, warnings_);
    // The planet sits at the sun–planet centre distance; the ring mesh must work there.
    g.ring_planet = internalPair(st.planet, ring, true, g.sun_planet.centre_distance, key);
    const int zs = sun.teeth, zr = ring.teeth, zp = st.planet.teeth, N = st.planets;
    if (st.planet_angles.empty()) {
      if ((zs + zr) % N != 0) {
        throw InputError(key + ".planets", std::to_string(N),
                         fmt::format("a number of equally spaced planets that divides z_sun + "
                                     "z_ring = {} + {} = {} (Parker & Lin 2004: otherwise the "
                                     "planets cannot be assembled); or give planet_angles_deg",
                                     zs, zr, zs + zr));
      }
      for (int n = 0; n < N; ++n) g.angles.push_back(kTwoPi * n / N);
    } else {
      if (static_cast<int>(st.planet_angles.size()) != N) {
        throw InputError(key + ".planet_angles_deg",
                         fmt::format("{} values", st.planet_angles.size()),
                         fmt::format("one angle per planet ({})", N));
      }
      for (int n = 0; n < N; ++n) {
        const double ticks = (zs + zr) * (st.planet_angles[n] - st.planet_angles[0]) / kTwoPi;
        if (std::abs(ticks - std::round(ticks)) > 1e-6) {
          throw InputError(key + ".planet_angles_deg",
                           fmt::format("{:g}", st.planet_angles[n] * 180 / std::numbers::pi),
                           fmt::format("multiples of 360/(z_sun + z_ring) = {:g} deg from the "
                                       "first planet, so that the planet can be assembled",
                                       360.0 / (zs + zr)));
        }
      }
      g.angles = st.planet_angles;
    }
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
      if (bodies_[b].stage != static_cast<int>(s)) continue;
      const int p = static_cast<int>(b);
      const std::string pkey = fmt::format("{}.planet{}", key, bodies_[b].planet + 1);
      layout.constraints.push_back(
          {{g.sun, p, g.carrier}, {double(zs), double(zp), -double(zs + zp)}, pkey + ".sun_mesh"});
      layout.constraints.push_back({{g.ring, p, g.carrier},
                                    {double(zr), -double(zp), double(zp - zr)},
                                    pkey + ".ring_mesh"});
    }
    if (planar && st.carrier_frame_terms) {
      for (int central : {g.sun, g.ring, g.carrier}) {
        if (bodies_[central].stage >= 0 && bodies_[central].stage != static_cast<int>(s)) {
          throw InputError(
              key + ".carrier_frame_terms", "true",
              fmt::format("false: shaft \"{}\" already belongs to the rotating frame "
                          "of planetary.{}",
                          bodies_[central].name, spec_.stages[bodies_[central].stage].name));
        }
        bodies_[central].stage = static_cast<int>(s);
      }
    }
    layout.stages.push_back(g);
  }
}

/// Speed ratios of every body from the mesh, shaft, coupling and bearing constraints.
void GearTrainModel::solveTrainKinematics(MeshLayout& layout) {
  // The nodes of a flexible shaft turn together and share its axis.
  for (std::size_t s = 0; s < spec_.shafts.size(); ++s) {
    const auto& chain = shaft_nodes_[s];
    for (std::size_t k = 1; k < chain.size(); ++k) {
      layout.constraints.push_back(
          {{chain[k - 1], chain[k]}, {1.0, -1.0}, "shafts." + spec_.shafts[s].name});
    }
  }
  for (const auto& c : spec_.couplings) {
    const auto [a, b] = detail::couplingBodies(*this, c);
    layout.constraints.push_back({{a, b}, {c.ratio, -1.0}, "couplings." + c.name});
  }
  for (const auto& b : spec_.bearings) {
    if (!(b.k_torsion > 0.0)) continue;
    const std::string key = "bearings." + b.name;
    const int body =
        detail::bodyAtOf(*this, b.shaft, key + ".shaft", b.position, key + ".position");
    if (b.other_shaft.empty()) {
      for (int node : shaft_nodes_[bodies_[body].shaft]) bodies_[node].grounded_torsion = true;
      layout.constraints.push_back({{body}, {1.0}, key});
    } else {
      layout.constraints.push_back(
          {{body, detail::bodyAtOf(*this, b.other_shaft, key + ".other_shaft", b.other_position,
                                   key + ".other_position")},
           {1.0, -1.0},
           key});
    }
  }
  std::vector<std::string> names;
  for (const auto& b : bodies_) names.push_back(b.name);
  const int input = detail::inputBody(*this);
  kinematics_ = solveKinematics(names, layout.constraints, input, "operating_point.input");
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    bodies_[b].speed_ratio = kinematics_.speed_ratio[b];
  }
}

/// Shaft centres from the meshes (loops must close) and coaxial members; planets on their
/// carriers.
void GearTrainModel::placeShaftCentres(const MeshLayout& layout) {
  struct Link {
    int a, b;
    Eigen::Vector2d offset;
    std::string source;
  };
  std::vector<Link> links;
  for (std::size_t i = 0; i < layout.fixed.size(); ++i) {
    const double psi = spec_.meshes[i].position_angle;
    links.push_back(
        {layout.fixed[i].ba, layout.fixed[i].bb,
         layout.fixed[i].geometry.centre_distance * Eigen::Vector2d(std::cos(psi), std::sin(psi)),
         "meshes." + spec_.meshes[i].name});
  }
  for (const auto& c : layout.constraints) {
    if (c.bodies.size() == 2 && c.coefficients[0] == -c.coefficients[1] &&
        (c.source.rfind("couplings.", 0) == 0 || c.source.rfind("bearings.", 0) == 0 ||
         c.source.rfind("shafts.", 0) == 0)) {
      links.push_back({c.bodies[0], c.bodies[1], Eigen::Vector2d::Zero(), c.source});
    }
  }
  for (std::size_t s = 0; s < layout.stages.size(); ++s) {
    const std::string key = "planetary." + spec_.stages[s].name;
    links.push_back({layout.stages[s].sun, layout.stages[s].carrier, Eigen::Vector2d::Zero(), key});
    links.push_back(
        {layout.stages[s].ring, layout.stages[s].carrier, Eigen::Vector2d::Zero(), key});
  }
  std::vector<bool> placed(bodies_.size(), false);
  const int first = shaft_body_[0];
  bodies_[first].centre = Eigen::Vector2d(spec_.origin_y, spec_.origin_z);
  placed[first] = true;
  for (bool progress = true; progress;) {
    progress = false;
    for (const Link& l : links) {
      if (placed[l.a] && !placed[l.b]) {
        bodies_[l.b].centre = bodies_[l.a].centre + l.offset;
        placed[l.b] = progress = true;
      } else if (placed[l.b] && !placed[l.a]) {
        bodies_[l.a].centre = bodies_[l.b].centre - l.offset;
        placed[l.a] = progress = true;
      } else if (placed[l.a] && placed[l.b]) {
        const Eigen::Vector2d gap = bodies_[l.a].centre + l.offset - bodies_[l.b].centre;
        if (gap.norm() > 1e-6 * std::max(1e-3, l.offset.norm())) {
          throw InputError(
              l.source, "",
              fmt::format("the shaft centres do not close: placed by the other meshes and "
                          "couplings, {} sits {:.6g} mm from where this connection puts it; "
                          "correct the mesh position angles or centre distances of the loop",
                          bodies_[l.b].name, 1e3 * gap.norm()));
        }
      }
    }
  }
  for (std::size_t s = 0; s < layout.stages.size(); ++s) {
    const Eigen::Vector2d c = bodies_[layout.stages[s].carrier].centre;
    for (auto& body : bodies_) {
      if (body.kind != TrainBodyKind::kPlanet || body.stage != static_cast<int>(s)) continue;
      const double psi = layout.stages[s].angles[body.planet];
      body.centre = c + layout.stages[s].sun_planet.centre_distance *
                            Eigen::Vector2d(std::cos(psi), std::sin(psi));
    }
  }
}

/// The meshes with σ = +1: fixed-axis meshes, then each planet's sun and ring meshes with
/// their phases.
void GearTrainModel::createMeshes(const MeshLayout& layout) {
  for (std::size_t i = 0; i < layout.fixed.size(); ++i) {
    const TrainMeshSpec& ms = spec_.meshes[i];
    const MeshLayout::FixedMesh& p = layout.fixed[i];
    TrainMesh m = placedMesh(bodies_, ms.name, p.kind, p.ba, p.bb, spec_.gears[p.ga].gear.teeth,
                             spec_.gears[p.gb].gear.teeth, p.geometry, spec_.gears[p.ga].internal);
    setMeshModel(m, ms.stiffness, ms.transmission_error, ms.damping_ratio, ms.contact,
                 "meshes." + ms.name);
    m.frequency_ratio = m.teeth_a * std::abs(bodies_[p.ba].speed_ratio) / kTwoPi;
    m.phase = ms.phase.value_or(0.0);
    m.gear_a = p.ga, m.gear_b = p.gb;
    if (ms.damping) {
      if (!(*ms.damping >= 0.0) || !std::isfinite(*ms.damping)) {
        throw InputError("meshes." + ms.name + ".damping", fmt::format("{:g} N s/m", *ms.damping),
                         "a dashpot >= 0");
      }
      m.damping = *ms.damping;
    }
    meshes_.push_back(std::move(m));
  }
  for (std::size_t s = 0; s < layout.stages.size(); ++s) {
    const PlanetaryStageSpec& st = spec_.stages[s];
    const MeshLayout::Stage& g = layout.stages[s];
    const std::string key = "planetary." + st.name;
    const int zs = spec_.gears[g.sun_gear].gear.teeth, zr = spec_.gears[g.ring_gear].gear.teeth;
    const double relative = bodies_[g.sun].speed_ratio - bodies_[g.carrier].speed_ratio;
    const double sign_s = relative >= 0 ? 1.0 : -1.0;
    const double sign_r =
        bodies_[g.ring].speed_ratio - bodies_[g.carrier].speed_ratio >= 0 ? 1.0 : -1.0;
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
      if (bodies_[b].kind != TrainBodyKind::kPlanet || bodies_[b].stage != static_cast<int>(s))
        continue;
      const int n = bodies_[b].planet;
      const double psi = g.angles[n] - g.angles[0];
      TrainMesh sun = placedMesh(bodies_, fmt::format("{}.sun_planet{}", st.name, n + 1),
                                 TrainMeshKind::kSunPlanet, g.sun, static_cast<int>(b), zs,
                                 st.planet.teeth, g.sun_planet, false);
      setMeshModel(sun, st.sun_planet_stiffness, st.sun_planet_error, st.sun_planet_damping_ratio,
                   st.sun_planet_contact, key + ".sun_planet");
      TrainMesh ring = placedMesh(bodies_, fmt::format("{}.ring_planet{}", st.name, n + 1),
                                  TrainMeshKind::kRingPlanet, g.ring, static_cast<int>(b), zr,
                                  st.planet.teeth, g.ring_planet, true);
      setMeshModel(ring, st.ring_planet_stiffness, st.ring_planet_error,
                   st.ring_planet_damping_ratio, st.ring_planet_contact, key + ".ring_planet");
      sun.stage = ring.stage = static_cast<int>(s);
      sun.planet = ring.planet = n;
      sun.frequency_ratio = ring.frequency_ratio = zs * std::abs(relative) / kTwoPi;
      // Parker & Lin 2004: the teeth of a central member j at planet n repeat those at planet 1
      // a rotation ψ_n later, so φ_jn = φ_j1 − sgn(ω_j − ω_c) z_j ψ_n / 2π (mod 1).
      // (Rounded to 1e-12 so that whole periods read 0, not 1 − ε.)
      auto snapped = [](double phase) {
        const double p = wrapPhase(std::round(phase * 1e12) / 1e12);
        return p >= 1.0 ? 0.0 : p;
      };
      sun.phase = snapped(-sign_s * zs * psi / kTwoPi);
      ring.phase = snapped(-sign_r * zr * psi / kTwoPi);
      meshes_.push_back(std::move(sun));
      meshes_.push_back(std::move(ring));
    }
  }
}

/// The static mesh forces of the torsional model with σ = +1 everywhere [N] (the torque flow).
std::vector<double> GearTrainModel::torsionalMeshForces() const {
  const int nb = static_cast<int>(bodies_.size());
  auto torsional_gradient = [&](const TrainMesh& m) {
    Eigen::VectorXd g = Eigen::VectorXd::Zero(nb);
    const double cb = std::cos(m.base_helix_angle);
    for (auto [body, sign] : {std::pair{m.body_a, 1.0}, std::pair{m.body_b, -1.0}}) {
      const Eigen::Vector2d r = m.pitch_point - bodies_[body].centre;
      g(body) += sign * cb * (r.x() * m.normal.y() - r.y() * m.normal.x());
      if (bodies_[body].kind == TrainBodyKind::kPlanet) {
        const int carrier = detail::carrierBody(*this, bodies_[body].stage);
        const Eigen::Vector2d rc = bodies_[body].centre - bodies_[carrier].centre;
        g(carrier) += sign * cb * (rc.x() * m.normal.y() - rc.y() * m.normal.x());
      }
    }
    return g;
  };
  Eigen::MatrixXd Kt = Eigen::MatrixXd::Zero(nb, nb);
  for (const TrainMesh& m : meshes_) {
    const Eigen::VectorXd g = torsional_gradient(m);
    Kt += m.mean_stiffness * g * g.transpose();
  }
  auto spring = [&](int a, int b, double k) {
    Kt(a, a) += k, Kt(b, b) += k, Kt(a, b) -= k, Kt(b, a) -= k;
  };
  for (const auto& c : spec_.couplings) {
    // The spring on ratio θ_a − θ_b (a coupling: ratio 1).
    const auto [a, b] = detail::couplingBodies(*this, c);
    Kt(a, a) += c.ratio * c.ratio * c.k_torsion, Kt(b, b) += c.k_torsion;
    Kt(a, b) -= c.ratio * c.k_torsion, Kt(b, a) -= c.ratio * c.k_torsion;
  }
  for (const auto& beam : beams_) {
    spring(beam.body_a, beam.body_b,
           beam.segment.shear_modulus * beam.segment.polarMomentOfArea() / beam.segment.length);
  }
  for (const auto& bearing : spec_.bearings) {
    if (!(bearing.k_torsion > 0.0)) continue;
    const int a = detail::bodyAtOf(*this, bearing.shaft, "bearings", bearing.position, "bearings");
    if (bearing.other_shaft.empty()) {
      Kt(a, a) += bearing.k_torsion;
    } else {
      spring(a,
             detail::bodyAtOf(*this, bearing.other_shaft, "bearings", bearing.other_position,
                              "bearings"),
             bearing.k_torsion);
    }
  }
  Eigen::VectorXd Ft = Eigen::VectorXd::Zero(nb);
  const int input = detail::inputBody(*this), out = detail::outputBody(*this);
  Ft(input) += spec_.operating.input_torque;
  if (std::abs(bodies_[out].speed_ratio) > 1e-12) {
    Ft(out) -= spec_.operating.input_torque / bodies_[out].speed_ratio;
  }
  const Eigen::VectorXd theta = Kt.completeOrthogonalDecomposition().solve(Ft);
  std::vector<double> force(meshes_.size());
  for (std::size_t i = 0; i < meshes_.size(); ++i) {
    force[i] = meshes_[i].mean_stiffness * torsional_gradient(meshes_[i]).dot(theta);
  }
  return force;
}

/// Loaded flanks from the torque flow: a mesh whose torsional force comes out negative carries
/// its load on the other flank (σ = −1). Then each mesh's gradient over the model's DOFs, its
/// equivalent mass and its damping.
void GearTrainModel::orientMeshesByLoad() {
  const std::vector<double> force = torsionalMeshForces();
  double largest = 0.0;
  for (double f : force) largest = std::max(largest, std::abs(f));
  for (std::size_t i = 0; i < meshes_.size(); ++i) {
    TrainMesh& m = meshes_[i];
    if (force[i] < -1e-9 * largest) {
      // The other flank: mirror the tangential part of the line of action.
      const Eigen::Vector2d e = (bodies_[m.body_b].centre - bodies_[m.body_a].centre).normalized();
      const Eigen::Vector2d t(-e.y(), e.x());
      m.normal -= 2.0 * m.normal.dot(t) * t;
    } else if (std::abs(force[i]) <= 1e-9 * largest || largest == 0.0) {
      warnings_.push_back(
          fmt::format("mesh {} carries no static load at the operating point: "
                      "its line of action is taken on the drive flank of {}",
                      m.name, bodies_[m.body_a].name));
    }
    // Gradient over the model's DOFs.
    std::vector<int> dofs;
    Eigen::VectorXd v;
    if (spec_.dofs == TrainDofs::kFull) {
      fullMeshGradient(m, dofs, v);
    } else {
      Eigen::MatrixXd J;
      detail::stackJacobians({detail::pointJacobian(*this, m.body_a, m.pitch_point, 1.0),
                              detail::pointJacobian(*this, m.body_b, m.pitch_point, -1.0)},
                             dofs, J);
      detail::requireSameFrame(*this, m.body_a, m.body_b, m.name);
      v = std::cos(m.base_helix_angle) * (J.transpose() * m.normal);
    }
    m.dofs = dofs;
    m.gradient.assign(v.data(), v.data() + v.size());
    // Equivalent mass of the two rotations along the line of action, for the damping ratio.
    double compliance = 0.0;
    for (std::size_t k = 0; k < dofs.size(); ++k) {
      for (std::size_t b = 0; b < bodies_.size(); ++b) {
        if (rotationDof(static_cast<int>(b)) == dofs[k]) {
          compliance += v(k) * v(k) / rotatingInertia(static_cast<int>(b));
        }
      }
    }
    m.equivalent_mass = compliance > 0.0 ? 1.0 / compliance : 0.0;
    const bool given = m.gear_a >= 0 && spec_.meshes[i].damping.has_value();
    if (given) {
      m.damping_ratio = m.equivalent_mass > 0.0
                            ? m.damping / (2.0 * std::sqrt(m.mean_stiffness * m.equivalent_mass))
                            : 0.0;
    } else {
      m.damping = 2.0 * m.damping_ratio * std::sqrt(m.mean_stiffness * m.equivalent_mass);
    }
  }
}

}  // namespace geardyn
