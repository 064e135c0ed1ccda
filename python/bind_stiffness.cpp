/// Python bindings of stiffness/: the mesh-stiffness models and their summary.

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <numbers>

#include "geardyn/error.h"
#include "geardyn/stiffness/api_stiffness.h"
#include "geardyn/stiffness/fourier_stiffness.h"
#include "geardyn/stiffness/iso6336_stiffness.h"
#include "geardyn/stiffness/mesh_stiffness_summary.h"
#include "geardyn/stiffness/potential_energy_stiffness.h"
#include "geardyn/stiffness/step_stiffness.h"
#include "geardyn/units.h"

namespace py = pybind11;

namespace geardyn::python {
namespace {

using geardyn::units::kDegree;

template <typename Enum>
Enum choose(const std::string& value, const std::string& key,
            std::initializer_list<std::pair<const char*, Enum>> options) {
  std::string allowed;
  for (const auto& [name, e] : options) {
    if (value == name) return e;
    allowed += (allowed.empty() ? "" : ", ") + std::string("\"") + name + "\"";
  }
  throw InputError(key, "\"" + value + "\"", "must be one of " + allowed);
}

/// f applied to a number (returns a float) or element-wise to anything array-like (returns an
/// array of the same shape). No allocation per element.
template <typename F>
py::object mapValues(const py::object& x, const F& f) {
  if (py::isinstance<py::float_>(x) || py::isinstance<py::int_>(x)) {
    return py::float_(f(x.cast<double>()));
  }
  const auto in = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(x);
  if (!in)
    throw InputError("phase", py::repr(x).cast<std::string>(),
                     "must be a number or an array of numbers");
  py::array_t<double> out(std::vector<py::ssize_t>(in.shape(), in.shape() + in.ndim()));
  const double* src = in.data();
  double* dst = out.mutable_data();
  for (py::ssize_t i = 0; i < in.size(); ++i) dst[i] = f(src[i]);
  return std::move(out);
}

/// geardyn.MeshStiffness: k(φ) of any model, its table and Fourier form.
void bindMeshStiffnessBase(py::module_& m) {
  py::class_<MeshStiffness, std::shared_ptr<MeshStiffness>>(
      m, "MeshStiffness",
      "Mesh stiffness over one mesh period as a function of the mesh phase (mesh periods; "
      "0 when a tooth pair enters contact). Call it with a phase or an array of phases [N/m].")
      .def(
          "__call__",
          [](const MeshStiffness& k, const py::object& phase) {
            return mapValues(phase, [&](double p) { return k.stiffness(p); });
          },
          py::arg("phase"), "k at mesh phase(s) [N/m]")
      .def_property_readonly("model", &MeshStiffness::model)
      .def_property_readonly("contact_ratio", &MeshStiffness::contactRatio)
      .def_property_readonly("pair_count", &MeshStiffness::pairCount)
      .def_property_readonly("discontinuities", &MeshStiffness::discontinuities,
                             "phases in [0, 1) where k may jump")
      .def(
          "pair_stiffness",
          [](const MeshStiffness& k, const py::object& phase, int pair) {
            return mapValues(phase, [&](double p) { return k.pairStiffness(p, pair); });
          },
          py::arg("phase"), py::arg("pair"), "stiffness of pair j (0: the newest) [N/m]")
      .def(
          "summary",
          [](const MeshStiffness& k, int order) {
            const MeshStiffnessSummary s = summarizeMeshStiffness(k, order);
            py::dict d;
            d["mean"] = s.mean;
            d["min"] = s.min;
            d["max"] = s.max;
            d["std"] = s.std;
            d["cosine"] = s.cosine;
            d["sine"] = s.sine;
            d["amplitude"] = s.amplitude;
            d["phase"] = s.phase;
            return d;
          },
          py::arg("order") = 10,
          "mean, min, max, std [N/m] and Fourier coefficients up to `order`: k = mean + "
          "sum(cosine_i cos(2 pi i phase) + sine_i sin(2 pi i phase))");
}

/// The mesh-stiffness models (constant, step, Fourier, potential energy, ...).
void bindMeshStiffnessModels(py::module_& m) {
  py::class_<ConstantMeshStiffness, MeshStiffness, std::shared_ptr<ConstantMeshStiffness>>(
      m, "ConstantMeshStiffness", "A constant mesh stiffness (API, ISO 6336 mean).")
      .def(py::init<std::string, double, double>(), py::arg("name"), py::arg("value"),
           py::arg("contact_ratio"));

  py::class_<StepMeshStiffness, MeshStiffness, std::shared_ptr<StepMeshStiffness>>(
      m, "StepMeshStiffness",
      "Step function (Visnadi 2021 eq. 7): k_max with n + 1 pairs for (eps - n) of the period.")
      .def(py::init<double, double, double>(), py::kw_only(), py::arg("k_min"), py::arg("k_max"),
           py::arg("contact_ratio"))
      .def_static("from_mean", &StepMeshStiffness::fromMean, py::arg("mean"),
                  py::arg("contact_ratio"),
                  "levels proportional to the pairs in contact around a mean [N/m]")
      .def_static("from_model", &StepMeshStiffness::fromModel, py::arg("source"),
                  "levels: the source's means over the n + 1 and n pair parts (mean preserved)")
      .def_property_readonly("k_min", &StepMeshStiffness::kMin)
      .def_property_readonly("k_max", &StepMeshStiffness::kMax);

  py::class_<FourierMeshStiffness, MeshStiffness, std::shared_ptr<FourierMeshStiffness>>(
      m, "FourierMeshStiffness",
      "Fourier series (Visnadi 2021 eq. 8): k = k0 [1 + sum s_i cos(2 pi i phase - phi_i)].")
      .def(py::init([](double mean, std::vector<double> amplitudes, std::vector<double> phases_deg,
                       double contact_ratio) {
             for (double& p : phases_deg) p *= kDegree;
             return FourierMeshStiffness(mean, amplitudes, phases_deg, contact_ratio);
           }),
           py::kw_only(), py::arg("mean"), py::arg("amplitudes"), py::arg("phases_deg"),
           py::arg("contact_ratio"), "mean k0 [N/m]; relative amplitudes s_i; phases [deg]")
      .def_static("fit", &FourierMeshStiffness::fit, py::arg("source"), py::arg("order"),
                  py::arg("mean") = 0.0,
                  "first `order` harmonics of a model (mean > 0 replaces its mean)")
      .def_property_readonly("mean", &FourierMeshStiffness::mean)
      .def_property_readonly("relative_amplitudes", &FourierMeshStiffness::relativeAmplitudes)
      .def_property_readonly("phases", &FourierMeshStiffness::phases, "[rad]");

  py::class_<PotentialEnergyMeshStiffness, MeshStiffness,
             std::shared_ptr<PotentialEnergyMeshStiffness>>(
      m, "PotentialEnergyMeshStiffness",
      "Potential-energy beam model (Ma 2014, Sainsot 2004; helical: Wan 2015). Options as in "
      "[mesh_stiffness.potential_energy].")
      .def(py::init([](const GearPair& pair, const std::string& root,
                       const std::string& foundation_arm, bool foundation,
                       std::optional<double> pinion_hub_radius,
                       std::optional<double> gear_hub_radius, int slices, bool helical_cos2_beta_b,
                       int table_points) {
             PotentialEnergyOptions o;
             o.root = choose<ToothRoot>(
                 root, "root",
                 {{"straight", ToothRoot::kStraight}, {"trochoid", ToothRoot::kTrochoid}});
             o.foundation_arm =
                 choose<FoundationArm>(foundation_arm, "foundation_arm",
                                       {{"force_line", FoundationArm::kForceLine},
                                        {"contact_height", FoundationArm::kContactHeight}});
             o.foundation = foundation;
             o.pinion_hub_radius = pinion_hub_radius;
             o.gear_hub_radius = gear_hub_radius;
             o.slices = slices;
             o.helical_cos2_beta_b = helical_cos2_beta_b;
             o.table_points = table_points;
             return PotentialEnergyMeshStiffness(pair, o);
           }),
           py::arg("pair"), py::kw_only(), py::arg("root") = "straight",
           py::arg("foundation_arm") = "force_line", py::arg("foundation") = true,
           py::arg("pinion_hub_radius") = py::none(), py::arg("gear_hub_radius") = py::none(),
           py::arg("slices") = 0, py::arg("helical_cos2_beta_b") = false,
           py::arg("table_points") = 257)
      .def(
          "pair_stiffness_per_width",
          [](const PotentialEnergyMeshStiffness& k, const py::object& s) {
            return mapValues(s, [&](double v) { return k.pairStiffnessPerWidth(v); });
          },
          py::arg("s"),
          "one pair's stiffness per unit face width at s along the line of action from T1 [N/m/m]")
      .def_property_readonly("contact_start", &PotentialEnergyMeshStiffness::contactStart,
                             "[m] from T1")
      .def_property_readonly("contact_end", &PotentialEnergyMeshStiffness::contactEnd,
                             "[m] from T1")
      .def_property_readonly("warnings", &PotentialEnergyMeshStiffness::warnings);
}

/// Phase conventions and the stiffness builders from a configuration.
void bindStiffnessFunctions(py::module_& m) {
  m.def("mesh_phase_from_roll_angle", &meshPhaseFromRollAngle, py::arg("roll_angle"),
        py::arg("pinion_teeth"), "mesh phase of a pinion roll angle [rad]: theta z1 / (2 pi)");
  m.def("roll_angle_from_mesh_phase", &rollAngleFromMeshPhase, py::arg("phase"),
        py::arg("pinion_teeth"), "pinion roll angle [rad] of a mesh phase");
  m.def(
      "api_mesh_stiffness",
      [](double face_width, double helix_angle_deg) {
        return apiMeshStiffness(face_width, helix_angle_deg * kDegree);
      },
      py::arg("face_width"), py::arg("helix_angle_deg") = 0.0,
      "API constant K' = 12.057 L[mm] cos^2(beta) 1e6 [N/m] (Visnadi eq. 5)");
  m.def(
      "api_directional_stiffness",
      [](double k_prime, double pressure_angle_deg, const std::string& loading,
         const std::string& rotation) {
        const auto a = choose<ApiLoading>(loading, "loading",
                                          {{"down", ApiLoading::kDown}, {"up", ApiLoading::kUp}});
        const auto b = choose<ApiRotation>(rotation, "rotation",
                                           {{"clockwise", ApiRotation::kClockwise},
                                            {"counterclockwise", ApiRotation::kCounterClockwise}});
        return apiDirectionalStiffness(k_prime,
                                       apiMeshDirection(pressure_angle_deg * kDegree, a, b));
      },
      py::arg("k_prime"), py::arg("pressure_angle_deg") = 20.0, py::arg("loading") = "down",
      py::arg("rotation") = "clockwise",
      "2x2 [[Kxx, Kxy], [Kyx, Kyy]] of Visnadi eqs. 1-4, 6 [N/m]");
  m.def(
      "iso6336_stiffness",
      [](const GearPair& pair, double c_m, bool material_factor) {
        Iso6336Options o;
        o.c_m = c_m;
        o.material_factor = material_factor;
        const Iso6336Stiffness s = iso6336Stiffness(pair, o);
        py::dict d;
        d["zn1"] = s.zn1;
        d["zn2"] = s.zn2;
        d["q_prime"] = s.q_prime;
        d["c_prime_th"] = s.c_prime_th;
        d["c_prime"] = s.c_prime;
        d["c_gamma_alpha"] = s.c_gamma_alpha;
        d["c_gamma_beta"] = s.c_gamma_beta;
        d["c_b"] = s.c_b;
        d["material_factor"] = s.material_factor;
        d["mesh_stiffness"] = s.meshStiffness();
        return d;
      },
      py::arg("pair"), py::arg("c_m") = 0.8, py::arg("material_factor") = true,
      "ISO 6336-1 method B: c', c_gamma_alpha [N/(mm um)] and the mean mesh stiffness [N/m]");
}

}  // namespace

void bindStiffness(py::module_& m) {
  bindMeshStiffnessBase(m);
  bindMeshStiffnessModels(m);
  bindStiffnessFunctions(m);
}

}  // namespace geardyn::python
