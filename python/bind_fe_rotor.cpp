/// Python bindings of the finite-element geared rotor (system/fe_rotor_model.h), its Newmark
/// response, modal analysis and Campbell diagram (all three by the gear train's solvers, as
/// `geardyn rotor`). The model is built from a `geardyn rotor`
/// configuration file (with `[model] type = "fe_geared_rotor"`) and overrides with the same
/// keys; SI units; numpy arrays out (the response matrices without copies: they are handed to
/// numpy with the response as owner).

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <complex>
#include <memory>
#include <numbers>

#include "geardyn/analysis/fe_rotor_modes.h"
#include "geardyn/config/config.h"
#include "geardyn/config/fe_rotor_config.h"
#include "geardyn/config/geometry_config.h"
#include "geardyn/error.h"
#include "geardyn/solvers/fe_rotor_response.h"
#include "geardyn/units.h"

namespace py = pybind11;

namespace geardyn::python {
namespace {

using geardyn::units::kRpm;

/// A column-major Eigen matrix handed to numpy without a copy; `owner` keeps it alive.
py::array matrixView(const Eigen::MatrixXd& m, py::handle owner) {
  return py::array_t<double>({m.rows(), m.cols()},
                             {static_cast<py::ssize_t>(sizeof(double)),
                              static_cast<py::ssize_t>(sizeof(double) * m.rows())},
                             m.data(), owner);
}

/// A mode of the train reported on the FE rotor's DOFs (shape over its active DOFs).
py::dict modeDict(const TrainMode& m, const std::vector<int>& train_dof) {
  py::dict d;
  d["frequency_hz"] = m.frequency;
  d["damping_ratio"] = m.damping_ratio;
  d["eigenvalue"] = m.eigenvalue;
  d["whirl"] = m.whirl;
  d["forward_fraction"] = m.forward_fraction;
  d["lateral_fraction"] = m.lateral_fraction;
  d["torsional_fraction"] = m.torsional_fraction;
  d["axial_fraction"] = m.axial_fraction;
  py::array_t<std::complex<double>> shape(static_cast<py::ssize_t>(train_dof.size()));
  auto x = shape.mutable_unchecked<1>();
  for (std::size_t i = 0; i < train_dof.size(); ++i) x(i) = m.shape(train_dof[i]);
  d["shape"] = shape;
  return d;
}

/// The Python FeGearedRotor: the model (the gearbox it is, with the file's numbering) and its
/// configuration (for the train's modal solver).
struct FeRotorHandle {
  config::Config config;
  std::shared_ptr<FeRotorModel> model;
  std::shared_ptr<analysis::FeRotorTrain> train;  // built on first use by modal / campbell

  const analysis::FeRotorTrain& gearTrain() {
    if (!train) {
      std::vector<std::string> notes;  // the file's own build reported its warnings
      train =
          std::make_shared<analysis::FeRotorTrain>(analysis::feRotorTrain(config, *model, notes));
    }
    return *train;
  }
};

/// geardyn.FeTimeResponse: a time response's record.
void bindFeTimeResponse(py::module_& m) {
  py::class_<FeTimeResponse, std::shared_ptr<FeTimeResponse>>(
      m, "FeTimeResponse", "Newmark response of the FE geared rotor at the recorded channels.")
      .def_readonly("t", &FeTimeResponse::t, "[s]")
      .def_property_readonly(
          "displacement",
          [](py::object self) {
            return matrixView(self.cast<const FeTimeResponse&>().displacement, self);
          },
          "samples × channels [m or rad] (a view, no copy)")
      .def_property_readonly(
          "velocity",
          [](py::object self) {
            return matrixView(self.cast<const FeTimeResponse&>().velocity, self);
          },
          "samples × channels [m/s or rad/s] (a view)")
      .def_property_readonly(
          "acceleration",
          [](py::object self) {
            return matrixView(self.cast<const FeTimeResponse&>().acceleration, self);
          },
          "samples × channels [m/s² or rad/s²] (a view)")
      .def_readonly("speed", &FeTimeResponse::speed, "pinion speed [rad/s]")
      .def_readonly("mesh_stiffness", &FeTimeResponse::mesh_stiffness, "k_m [N/m]")
      .def_readonly("mesh_force", &FeTimeResponse::mesh_force, "[N]")
      .def_readonly("channels", &FeTimeResponse::channels, "active DOF indices")
      .def_readonly("steps", &FeTimeResponse::steps)
      .def_readonly("factorisations", &FeTimeResponse::factorisations)
      .def_readonly("message", &FeTimeResponse::message)
      .def_property_readonly("status", [](const FeTimeResponse& r) { return toString(r.status); });
}

/// geardyn.FeGearedRotor's construction from a configuration and its model's properties.
void bindFeRotorModel(py::class_<FeRotorHandle, std::shared_ptr<FeRotorHandle>>& c) {
  using Handle = FeRotorHandle;
  c.def(
       py::init([](const std::string& config, std::vector<std::string> overrides,
                   const std::string& stiffness) {
         // The gearbox the modes come from has the chosen model as its mesh stiffness.
         if (!stiffness.empty()) overrides.push_back("mesh.stiffness=" + stiffness);
         auto h = std::make_shared<Handle>(Handle{
             config::loadConfigFile(config, config::feRotorSchema(), overrides), nullptr, nullptr});
         config::FeRotorBuild build = config::feRotorFromConfig(h->config, stiffness);
         h->model = std::make_shared<FeRotorModel>(std::move(build.train), std::move(build.layout));
         return h;
       }),
       py::arg("config"), py::arg("overrides") = std::vector<std::string>{},
       py::arg("stiffness") = "",
       "config: path of the TOML file; overrides: [\"key=value\", ...] as --set; stiffness: "
       "a [mesh_stiffness] model name (default: mesh.stiffness)")
      .def_property_readonly("dof_count", [](const Handle& h) { return h.model->dofCount(); })
      .def_property_readonly("dof_names",
                             [](const Handle& h) {
                               std::vector<std::string> names;
                               for (int i = 0; i < h.model->dofCount(); ++i)
                                 names.push_back(h.model->dofName(i));
                               return names;
                             })
      .def(
          "dof_index",
          [](const Handle& h, int shaft, int node, int dof) {
            return h.model->dofIndex(shaft, node, dof);
          },
          py::arg("shaft"), py::arg("node"), py::arg("dof"),
          "active index of (shaft 0/1, node, dof 0-5 = ux uy uz rx ry rz), -1 if removed")
      .def_property_readonly(
          "mass", [](const Handle& h) -> const Eigen::MatrixXd& { return h.model->mass(); },
          py::return_value_policy::reference_internal, "M [kg, kg m, kg m²]")
      .def_property_readonly(
          "stiffness",
          [](const Handle& h) -> const Eigen::MatrixXd& { return h.model->stiffness(); },
          py::return_value_policy::reference_internal, "K without the mesh")
      .def_property_readonly(
          "damping", [](const Handle& h) -> const Eigen::MatrixXd& { return h.model->damping(); },
          py::return_value_policy::reference_internal, "C without gyroscopics")
      .def_property_readonly(
          "gyroscopic",
          [](const Handle& h) -> const Eigen::MatrixXd& { return h.model->gyroscopic(); },
          py::return_value_policy::reference_internal, "G₁ per rad/s of pinion speed")
      .def_property_readonly(
          "mesh_vector",
          [](const Handle& h) -> const Eigen::VectorXd& { return h.model->meshVector(); },
          py::return_value_policy::reference_internal, "v = ∂δ/∂q")
      .def_property_readonly(
          "static_load",
          [](const Handle& h) -> const Eigen::VectorXd& { return h.model->staticLoad(); },
          py::return_value_policy::reference_internal, "F [N, N m]")
      .def_property_readonly(
          "mean_mesh_stiffness", [](const Handle& h) { return h.model->meanMeshStiffness(); },
          "[N/m]");
}

/// geardyn.FeGearedRotor's analyses: time response, modes and Campbell diagram.
void bindFeRotorAnalyses(py::class_<FeRotorHandle, std::shared_ptr<FeRotorHandle>>& c) {
  using Handle = FeRotorHandle;
  c.def(
       "time_response",
       [](const Handle& h, double duration, double time_step, std::vector<std::string> channels,
          bool start_from_static) {
         const FeRotorModel& r = *h.model;
         FeTimeOptions o;
         o.duration = duration;
         o.time_step = time_step;
         o.start_from_static = start_from_static;
         for (const auto& name : channels) {
           int found = -1;
           for (int i = 0; i < r.dofCount(); ++i)
             if (r.dofName(i) == name) found = i;
           if (found < 0) throw InputError("channels", name, "a name of dof_names");
           o.channels.push_back(found);
         }
         auto response = std::make_shared<FeTimeResponse>();
         {
           py::gil_scoped_release release;
           *response = solveFeRotorTimeResponse(r, o);
         }
         return response;
       },
       py::kw_only(), py::arg("duration") = 0.5, py::arg("time_step") = 1e-5,
       py::arg("channels") = std::vector<std::string>{}, py::arg("start_from_static") = false,
       "Newmark (γ = 1/2, β = 1/4) over `duration` [s] with step `time_step` [s] at the "
       "configured speed profile; channels: DOF names (default all).")
      .def(
          "modal",
          [](Handle& h, double speed_rpm, int modes) {
            const analysis::FeRotorTrain& train = h.gearTrain();
            py::list out;
            for (const auto& mode : analysis::feRotorModes(
                     train, speed_rpm * kRpm, modes, h.config.real("modal.max_damping_ratio")))
              out.append(modeDict(mode, train.train_dof));
            return out;
          },
          py::arg("speed_rpm"), py::arg("modes") = 12,
          "Damped modes at a pinion speed [rpm], ascending (the train's modal solver, as "
          "`geardyn rotor` modal): frequency_hz, damping_ratio, whirl, energy fractions, complex "
          "shape over the active DOFs.")
      .def(
          "campbell",
          [](Handle& h, const std::vector<double>& speeds_rpm, int modes) {
            std::vector<double> speeds;
            for (double s : speeds_rpm) speeds.push_back(s * kRpm);
            const TrainCampbell d = analysis::feRotorCampbell(
                h.gearTrain(), *h.model, speeds, modes, h.config.real("modal.max_damping_ratio"));
            py::array_t<double> freq(
                {static_cast<py::ssize_t>(speeds.size()), static_cast<py::ssize_t>(modes)});
            std::vector<std::vector<std::string>> whirl(speeds.size());
            auto f = freq.mutable_unchecked<2>();
            for (std::size_t i = 0; i < speeds.size(); ++i) {
              for (int j = 0; j < modes; ++j) {
                const bool have = j < static_cast<int>(d.modes[i].size());
                f(i, j) = have ? d.modes[i][j].frequency : std::nan("");
                whirl[i].push_back(have ? d.modes[i][j].whirl : "");
              }
            }
            py::list critical, lines;
            for (const auto& c : d.critical_speeds) {
              py::dict x;
              x["mode"] = c.mode;
              x["line"] = c.line;
              x["speed_rpm"] = c.speed / kRpm;
              x["frequency_hz"] = c.frequency;
              x["whirl"] = c.whirl;
              critical.append(x);
            }
            // The order of a line: its slope [Hz per rad/s] × 2π, multiples of the pinion speed.
            for (const auto& l : d.lines)
              lines.append(py::make_tuple(l.name, l.slope * 2.0 * std::numbers::pi));
            py::dict out;
            out["speeds_rpm"] = speeds_rpm;
            out["frequency_hz"] = freq;
            out["whirl"] = whirl;
            out["lines"] = lines;
            out["critical_speeds"] = critical;
            return out;
          },
          py::arg("speeds_rpm"), py::arg("modes") = 8,
          "Campbell diagram (the train's, as `geardyn rotor` campbell): tracked modes over pinion "
          "speeds [rpm] (frequency_hz: speeds × modes), the order lines and the critical speeds.");
}

}  // namespace

void bindFeRotor(py::module_& m) {
  bindFeTimeResponse(m);
  py::class_<FeRotorHandle, std::shared_ptr<FeRotorHandle>> rotor(
      m, "FeGearedRotor",
      "The finite-element two-shaft geared rotor (Visnadi & de Castro 2021 §3): build it from a "
      "`geardyn rotor` configuration with [model] type = \"fe_geared_rotor\". Its time response, "
      "modes and Campbell diagram come from the gear train it is (the solvers of `geardyn "
      "rotor`).");
  bindFeRotorModel(rotor);
  bindFeRotorAnalyses(rotor);
}

}  // namespace geardyn::python
