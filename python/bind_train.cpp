/// Python bindings of analysis/gear_train_session.h: `geardyn._geardyn.GearTrain`, a gear train
/// built once and analysed many times in-process (issue 39). The pure-Python
/// geardyn.GearTrain (python/geardyn/train.py) builds it from a dict, a TOML or a REXS file and
/// shows the results as DataFrames; here the modes come back as numpy arrays, the other
/// analyses as the AnalysisResult of `geardyn train`.

#include <pybind11/complex.h>
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>

#include "geardyn/analysis/gear_train_session.h"
#include "geardyn/units.h"

namespace py = pybind11;

namespace geardyn::python {
namespace {

using analysis::GearTrainSession;

/// The modes of one modal analysis as arrays, one entry per mode (the columns of modes.csv).
py::dict modesDict(const GearTrainModel& model, const std::vector<TrainMode>& modes, bool shapes) {
  const auto n = static_cast<py::ssize_t>(modes.size());
  py::array_t<double> frequency(n), damping(n), growth(n), translational(n);
  py::array_t<bool> divergent(n);
  py::array_t<std::int64_t> multiplicity(n);
  py::list stage_type;
  const auto meshes = static_cast<py::ssize_t>(model.meshes().size());
  const auto elements = static_cast<py::ssize_t>(model.elements().size());
  py::array_t<double> mesh_strain({n, meshes}), element_strain({n, elements});
  auto f = frequency.mutable_unchecked<1>();
  auto z = damping.mutable_unchecked<1>();
  auto g = growth.mutable_unchecked<1>();
  auto t = translational.mutable_unchecked<1>();
  auto d = divergent.mutable_unchecked<1>();
  auto mu = multiplicity.mutable_unchecked<1>();
  auto ms = mesh_strain.mutable_unchecked<2>();
  auto es = element_strain.mutable_unchecked<2>();
  for (py::ssize_t j = 0; j < n; ++j) {
    const TrainMode& m = modes[j];
    f(j) = m.frequency, z(j) = m.damping_ratio, g(j) = m.growthRate();
    t(j) = m.translational_fraction, d(j) = m.divergent, mu(j) = m.multiplicity;
    std::string types;
    for (const auto& s : m.stage_type) types += (types.empty() ? "" : "/") + s;
    stage_type.append(types);
    for (py::ssize_t i = 0; i < meshes; ++i) ms(j, i) = m.mesh_strain_energy[i];
    for (py::ssize_t i = 0; i < elements; ++i) es(j, i) = m.element_strain_energy[i];
  }
  py::dict out;
  out["frequency_hz"] = frequency;
  out["damping_ratio"] = damping;
  out["divergent"] = divergent;
  out["growth_rate_1_per_s"] = growth;
  out["multiplicity"] = multiplicity;
  out["stage_type"] = stage_type;
  out["translational_fraction"] = translational;
  out["mesh_strain"] = mesh_strain;
  out["element_strain"] = element_strain;
  if (shapes) {
    Eigen::MatrixXcd x(model.dofCount(), modes.size());
    for (std::size_t j = 0; j < modes.size(); ++j)
      x.col(static_cast<Eigen::Index>(j)) = modes[j].shape;
    out["shapes"] = x;
  }
  return out;
}

/// Runs `work` without the GIL (a long forced response or Campbell diagram).
template <class Work>
auto released(Work&& work) {
  py::gil_scoped_release release;
  return work();
}

}  // namespace

void bindTrain(py::module_& m) {
  py::class_<GearTrainSession>(
      m, "GearTrain",
      "A gear train built once and analysed many times in-process (geardyn.GearTrain wraps "
      "it): modes as numpy arrays, the other analyses as AnalysisResult; set() changes a key "
      "and reassembles only what depends on it.")
      .def(py::init([](const std::string& path, const std::string& text, const std::string& source,
                       const std::string& base_dir, const std::vector<std::string>& overrides) {
             py::gil_scoped_release release;
             return path.empty() ? GearTrainSession::fromText(text, source, base_dir, overrides)
                                 : GearTrainSession::fromFile(path, overrides);
           }),
           py::kw_only(), py::arg("path") = "", py::arg("text") = "", py::arg("source") = "<dict>",
           py::arg("base_dir") = ".", py::arg("overrides") = std::vector<std::string>{},
           "From an analysis file (`path`) or the TOML `text` of one, with --set `overrides`.")
      .def(
          "set",
          [](GearTrainSession& s, const std::string& key, const std::string& value) {
            switch (s.set(key, value)) {
              case GearTrainSession::Change::kNothing:
                return "nothing";
              case GearTrainSession::Change::kParameters:
                return "parameters";
              default:
                return "model";
            }
          },
          py::arg("key"), py::arg("value"),
          "Sets `key` to `value` (TOML syntax, as --set); returns what was reassembled: "
          "'nothing' (an analysis option), 'parameters' (a mesh stiffness_value, the operating "
          "speed or torque: rank-one updates) or 'model' (built anew).")
      .def(
          "frequencies",
          [](GearTrainSession& s) {
            const std::vector<TrainMode> modes = s.modes();
            py::array_t<double> out(static_cast<py::ssize_t>(modes.size()));
            auto f = out.mutable_unchecked<1>();
            for (std::size_t j = 0; j < modes.size(); ++j)
              f(static_cast<py::ssize_t>(j)) = modes[j].frequency;
            return out;
          },
          "The natural frequencies of the `modal` analysis [Hz] (modes.csv frequency_hz).")
      .def(
          "modes",
          [](GearTrainSession& s, bool shapes) {
            return modesDict(s.linearModel(), s.modes(), shapes);
          },
          py::arg("shapes") = true,
          "The `modal` analysis as {column: numpy array} (modes.csv's columns; mesh_strain and "
          "element_strain: modes × meshes / elements; shapes: DOFs × modes, complex).")
      .def_property_readonly("modal_speed_rpm",
                             [](GearTrainSession& s) { return s.modalSpeed() / units::kRpm; })
      .def(
          "analyze",
          [](GearTrainSession& s, const std::vector<std::string>& analyses) {
            return std::make_shared<analysis::AnalysisResult>(
                released([&] { return s.analyze(analyses, {}); }));
          },
          py::arg("analyses") = std::vector<std::string>{},
          "`geardyn train` on the built model: the analyses named (default analysis.run).")
      .def(
          "forced",
          [](GearTrainSession& s, const std::vector<double>& speeds_rpm) {
            std::vector<double> speeds;
            for (double v : speeds_rpm) speeds.push_back(v * units::kRpm);
            return std::make_shared<analysis::AnalysisResult>(
                released([&] { return s.forced(speeds, {}); }));
          },
          py::arg("speeds_rpm"), "The forced response at these input speeds [rpm].")
      .def_property_readonly("dof_names",
                             [](const GearTrainSession& s) {
                               std::vector<std::string> names;
                               for (int i = 0; i < s.model().dofCount(); ++i)
                                 names.push_back(s.model().dofName(i));
                               return names;
                             })
      .def_property_readonly("mesh_names",
                             [](const GearTrainSession& s) {
                               std::vector<std::string> names;
                               for (const auto& m : s.model().meshes()) names.push_back(m.name);
                               return names;
                             })
      .def_property_readonly("element_names",
                             [](const GearTrainSession& s) {
                               std::vector<std::string> names;
                               for (const auto& e : s.model().elements()) names.push_back(e.name);
                               return names;
                             })
      .def_property_readonly(
          "element_parts",
          [](const GearTrainSession& s) {
            py::list out;
            for (const auto& e : s.model().elements())
              out.append(py::make_tuple(e.dofs, e.stiffness));
            return out;
          },
          "(DOFs, Jᵀ k J over them) of every bearing, coupling and pin: K = Σ over them")
      .def_property_readonly(
          "mesh_parts",
          [](const GearTrainSession& s) {
            py::list out;
            for (const auto& m : s.model().meshes())
              out.append(py::make_tuple(m.dofs, m.gradient, m.mean_stiffness));
            return out;
          },
          "(DOFs, v over them, k̄ [N/m]) of every mesh: Σ k̄ v vᵀ")
      .def_property_readonly(
          "mass", [](const GearTrainSession& s) { return s.model().mass(); }, "M [kg, kg m²]")
      .def_property_readonly(
          "stiffness",
          [](const GearTrainSession& s) {
            return s.model().meanStiffnessAt(s.model().inputSpeed());
          },
          "K + Ω² K_Ω + Σ k̄ v vᵀ at the operating speed [N/m, N m/rad]");
}

}  // namespace geardyn::python
