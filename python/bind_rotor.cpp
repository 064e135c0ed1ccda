/// Python bindings of the lateral geared rotor (system/lateral_rotor.h), its time and frequency
/// responses (solvers/rotor_response.h), the full spectrum and gear whirl analysis (signal/) and
/// the DTE identification (identify/). Keyword names follow the `geardyn rotor`, `spectrum` and
/// `identify` configuration keys; SI units; numpy arrays in and out.

#include <fmt/format.h>
#include <pybind11/complex.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <numbers>

#include "geardyn/config/rotor_gearbox.h"
#include "geardyn/error.h"
#include "geardyn/identify/dte_identification.h"
#include "geardyn/signal/gear_whirl.h"
#include "geardyn/solvers/rotor_response.h"
#include "geardyn/solvers/train_periodic_record.h"

namespace py = pybind11;

namespace geardyn::python {
namespace {

using Complex = std::complex<double>;
using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

std::vector<double> toVector(const Array& a, const char* key) {
  if (a.ndim() != 1) throw InputError(key, fmt::format("{}-d array", a.ndim()), "a 1-d array");
  return std::vector<double>(a.data(), a.data() + a.size());
}

std::vector<TeHarmonic> harmonics(const std::vector<double>& amplitudes,
                                  const std::vector<double>& phases, const char* key) {
  if (phases.size() != 1 && phases.size() != amplitudes.size()) {
    throw InputError(key, fmt::format("{} phases", phases.size()),
                     fmt::format("one phase, or one per harmonic ({})", amplitudes.size()));
  }
  std::vector<TeHarmonic> out;
  for (std::size_t i = 0; i < amplitudes.size(); ++i)
    out.push_back({amplitudes[i], phases.size() == 1 ? phases[0] : phases[i]});
  return out;
}

py::dict peaksDict(const std::array<std::vector<WhirlComponent>, 2>& peaks) {
  py::dict out;
  const char* shafts[] = {"pinion", "gear"};
  for (int s = 0; s < 2; ++s) {
    py::dict shaft;
    for (const auto& c : peaks[s]) shaft[c.name.c_str()] = py::make_tuple(c.frequency, c.value);
    out[shafts[s]] = shaft;
  }
  return out;
}

MeasuredWhirlPeaks peaksFrom(const py::dict& d) {
  MeasuredWhirlPeaks m;
  m.pinion_speed = d["pinion_speed"].cast<double>();
  const char* shafts[] = {"pinion", "gear"};
  for (int s = 0; s < 2; ++s) {
    for (const auto& [name, value] : d["peaks"][shafts[s]].cast<py::dict>()) {
      const auto t = value.cast<py::tuple>();
      m.peaks[s].push_back({name.cast<std::string>(), t[0].cast<double>(), t[1].cast<Complex>()});
    }
  }
  if (d.contains("coefficient_sigma")) {
    const auto sigma = d["coefficient_sigma"].cast<std::array<double, 2>>();
    m.coefficient_sigma = sigma;
  }
  return m;
}

py::dict valueDict(const IdentifiedValue& v) {
  py::dict d;
  d["value"] = v.value;
  d["ci95"] = py::make_tuple(v.low, v.high);
  d["identifiable"] = v.identifiable;
  return d;
}

py::dict phasorDict(const IdentifiedPhasor& p) {
  py::dict d;
  d["amplitude"] = valueDict(p.amplitude);
  d["phase"] = valueDict(p.phase);
  return d;
}

/// geardyn.LateralRotor: Rao's 4-DOF rotor description.
void bindLateralRotorSpec(py::module_& m) {
  py::class_<LateralRotorSpec>(
      m, "LateralRotor",
      "The 4-DOF lateral geared rotor of Rao (2023), SI units; the keyword "
      "names are the `geardyn rotor` keys (defaults: Table 4.1).")
      .def(py::init([](double pinion_mass, double gear_mass, double pinion_shaft_stiffness,
                       double gear_shaft_stiffness, double shaft_damping_ratio,
                       double mesh_stiffness, double mesh_damping_ratio, double mean_te,
                       std::vector<double> te_x, std::vector<double> te_x_phase,
                       std::vector<double> te_y, std::vector<double> te_y_phase,
                       double pinion_runout, double pinion_runout_phase, double gear_runout,
                       double gear_runout_phase, double gravity, int pinion_teeth, int gear_teeth,
                       double pinion_speed_rpm, std::optional<double> mesh_damping) {
             LateralRotorSpec s;
             s.pinion_mass = pinion_mass;
             s.gear_mass = gear_mass;
             s.pinion_shaft_stiffness = pinion_shaft_stiffness;
             s.gear_shaft_stiffness = gear_shaft_stiffness;
             s.mesh_stiffness = mesh_stiffness;
             s.mean_te = mean_te;
             s.te_x = harmonics(te_x, te_x_phase, "te_x_phase");
             s.te_y = harmonics(te_y, te_y_phase, "te_y_phase");
             s.pinion_runout = pinion_runout;
             s.pinion_runout_phase = pinion_runout_phase;
             s.gear_runout = gear_runout;
             s.gear_runout_phase = gear_runout_phase;
             s.gravity = gravity;
             s.pinion_teeth = pinion_teeth;
             s.gear_teeth = gear_teeth;
             s.pinion_speed = pinion_speed_rpm / 60.0;
             lateralRotorDamping(s, shaft_damping_ratio, mesh_damping_ratio);
             if (mesh_damping) s.mesh_damping = *mesh_damping;
             s.validate();
             return s;
           }),
           py::kw_only(), py::arg("pinion_mass") = 0.310, py::arg("gear_mass") = 1.270,
           py::arg("pinion_shaft_stiffness") = 1e6, py::arg("gear_shaft_stiffness") = 1e6,
           py::arg("shaft_damping_ratio") = 0.01, py::arg("mesh_stiffness") = 6e8,
           py::arg("mesh_damping_ratio") = 0.01, py::arg("mean_te") = 50e-6,
           py::arg("te_x") = std::vector<double>{40e-6, 25e-6, 35e-6, 20e-6, 10e-6},
           py::arg("te_x_phase") = std::vector<double>{0.785},
           py::arg("te_y") = std::vector<double>{30e-6, 15e-6, 25e-6, 10e-6, 5e-6},
           py::arg("te_y_phase") = std::vector<double>{1.570}, py::arg("pinion_runout") = 200e-6,
           py::arg("pinion_runout_phase") = 1.047, py::arg("gear_runout") = 300e-6,
           py::arg("gear_runout_phase") = 2.094, py::arg("gravity") = 9.81,
           py::arg("pinion_teeth") = 16, py::arg("gear_teeth") = 35,
           py::arg("pinion_speed_rpm") = 660.0, py::arg("mesh_damping") = py::none())
      .def_readonly("mesh_stiffness", &LateralRotorSpec::mesh_stiffness, "k_m [N/m]")
      .def_readonly("mesh_damping", &LateralRotorSpec::mesh_damping, "c_m [N s/m]")
      .def_readonly("pinion_shaft_damping", &LateralRotorSpec::pinion_shaft_damping, "[N s/m]")
      .def_readonly("gear_shaft_damping", &LateralRotorSpec::gear_shaft_damping, "[N s/m]")
      .def_readonly("mean_te", &LateralRotorSpec::mean_te, "e_m [m]")
      .def_property_readonly(
          "te_x",
          [](const LateralRotorSpec& s) {
            std::vector<std::pair<double, double>> v;
            for (const auto& h : s.te_x) v.push_back({h.amplitude, h.phase});
            return v;
          },
          "[(amplitude [m], phase [rad]), ...] per mesh harmonic")
      .def_property_readonly("te_y",
                             [](const LateralRotorSpec& s) {
                               std::vector<std::pair<double, double>> v;
                               for (const auto& h : s.te_y) v.push_back({h.amplitude, h.phase});
                               return v;
                             })
      .def_readonly("pinion_runout", &LateralRotorSpec::pinion_runout, "e_p [m]")
      .def_readonly("gear_runout", &LateralRotorSpec::gear_runout, "e_g [m]")
      .def_property_readonly("pinion_speed_rpm",
                             [](const LateralRotorSpec& s) { return 60.0 * s.pinion_speed; })
      .def_property_readonly(
          "common_period",
          [](const LateralRotorSpec& s) { return LateralRotorModel(s).commonPeriod(); },
          "[s]: t_g/gcd(t_p, t_g) pinion revolutions")
      .def(
          "frequency_response",
          [](const LateralRotorSpec& s) { return peaksDict(modelWhirlPeaks(s)); },
          "Exact steady state per whirl component: {shaft: {component: (frequency [Hz], complex "
          "0-peak radius at t = 0 [m])}}, probe frame.")
      .def(
          "time_response",
          [](const LateralRotorSpec& s, double duration, long long samples, double rtol,
             double atol, double steady_tolerance) {
            TrainRecordOptions o;
            o.duration = duration;
            o.samples = samples;
            o.integrator.relative_tolerance = rtol;
            o.integrator.absolute_tolerance = atol;
            o.steady_tolerance = steady_tolerance;
            TrainRecord r;
            {
              py::gil_scoped_release release;
              // The gearbox the rotor is (config/rotor_gearbox.h), recorded from rest.
              std::vector<std::string> warnings;
              const GearTrainModel train(config::lateralRotorGearTrain(s, "python", warnings));
              r = recordTrainFromRest(train, train.inputSpeed(),
                                      config::lateralRotorProbeDofs(train),
                                      LateralRotorModel(s).commonPeriod(), o);
            }
            const auto rows = static_cast<py::ssize_t>(r.displacement.rows());
            py::array_t<double> t(static_cast<py::ssize_t>(r.t.size()));
            py::array_t<double> eta({rows, py::ssize_t{4}});
            std::copy(r.t.begin(), r.t.end(), t.mutable_data());
            double* e = eta.mutable_data();
            for (py::ssize_t k = 0; k < rows; ++k)
              for (int c = 0; c < 4; ++c) e[4 * k + c] = r.displacement(k, c);
            py::dict d;
            d["t"] = t;
            d["eta"] = eta;
            d["sample_rate"] = r.sample_rate;
            d["transient_end"] = r.transient_end;
            d["window"] = py::make_tuple(r.window_begin, r.window_end);
            d["status"] = toString(r.status);
            d["message"] = r.message;
            d["steps"] = r.steps;
            return d;
          },
          py::kw_only(), py::arg("duration") = 15.0, py::arg("samples") = 32768,
          py::arg("relative_tolerance") = 1e-8, py::arg("absolute_tolerance") = 1e-8,
          py::arg("steady_tolerance") = 1e-6,
          "Dormand-Prince from rest: {'t', 'eta' (N x 4: x1, y1, x2, y2 [m]), 'sample_rate', "
          "'transient_end', 'window' (steady whole common periods), 'status', 'message'}.");
}

/// The lateral rotor's responses and the identification from Python.
void bindRotorFunctions(py::module_& m) {
  m.def(
      "full_spectrum",
      [](const Array& x, const Array& y, double sample_rate, const std::string& window) {
        const auto s =
            fullSpectrum(toVector(x, "x"), toVector(y, "y"), sample_rate,
                         window == "hann" ? SpectrumWindow::kHann : SpectrumWindow::kRectangular);
        py::array_t<double> f(static_cast<py::ssize_t>(s.frequency.size()));
        py::array_t<Complex> c(static_cast<py::ssize_t>(s.coefficient.size()));
        std::copy(s.frequency.begin(), s.frequency.end(), f.mutable_data());
        std::copy(s.coefficient.begin(), s.coefficient.end(), c.mutable_data());
        return py::make_tuple(f, c);
      },
      py::arg("x"), py::arg("y"), py::arg("sample_rate"), py::arg("window") = "rectangular",
      "Full spectrum of z = x + jy: (frequency [Hz] ascending, complex 0-peak whirl radius, FFT "
      "scaled 1/N; forward f > 0, backward f < 0).");

  m.def(
      "gear_whirl_peaks",
      [](const Array& x1, const Array& y1, const Array& x2, const Array& y2, double sample_rate,
         double pinion_speed_rpm, int pinion_teeth, int gear_teeth, int harmonics,
         double first_sample_time, double reference_time, const std::string& frame,
         const std::string& method) {
        const std::array<std::vector<double>, 4> channels{toVector(x1, "x1"), toVector(y1, "y1"),
                                                          toVector(x2, "x2"), toVector(y2, "y2")};
        GearPairSpectrumOptions o;
        o.frame = frame == "shaft" ? WhirlFrame::kShaft : WhirlFrame::kProbe;
        o.method = method == "exact_bins"      ? WhirlExtraction::kExactBins
                   : method == "least_squares" ? WhirlExtraction::kLeastSquares
                                               : WhirlExtraction::kAuto;
        const GearWhirlSetup setup{pinion_speed_rpm / 60.0, pinion_teeth, gear_teeth, harmonics};
        const auto s = analyseGearPairRecord(channels, sample_rate, first_sample_time,
                                             reference_time, setup, o);
        py::dict d;
        d["pinion_speed"] = setup.pinion_speed;
        d["peaks"] = peaksDict(s.peaks);
        d["coefficient_sigma"] = py::make_tuple(s.coefficient_sigma[0], s.coefficient_sigma[1]);
        return d;
      },
      py::arg("x1"), py::arg("y1"), py::arg("x2"), py::arg("y2"), py::arg("sample_rate"),
      py::kw_only(), py::arg("pinion_speed_rpm"), py::arg("pinion_teeth"), py::arg("gear_teeth"),
      py::arg("harmonics") = 5, py::arg("first_sample_time") = 0.0, py::arg("reference_time") = 0.0,
      py::arg("frame") = "probe", py::arg("method") = "auto",
      "Whirl peaks of both shafts (static, mesh_i_fwd/bwd, pinion/gear_1x_fwd/bwd) with each "
      "shaft's peak noise: the input of identify_dte.");

  m.def(
      "identify_dte",
      [](const LateralRotorSpec& known, const py::list& spectra, const std::string& method,
         std::optional<int> harmonics, double mesh_damping_ratio,
         std::optional<double> prior_mesh_stiffness, double prior_mesh_stiffness_rsd,
         std::optional<double> prior_mesh_damping, double prior_mesh_damping_rsd) {
        std::vector<MeasuredWhirlPeaks> data;
        for (const auto& item : spectra) {
          MeasuredWhirlPeaks p = peaksFrom(item.cast<py::dict>());
          p.pinion_speed = item.cast<py::dict>()["pinion_speed"].cast<double>();
          data.push_back(p);
        }
        IdentificationOptions o;
        o.method = method == "three_step" ? IdentificationMethod::kThreeStep
                                          : IdentificationMethod::kJoint;
        o.harmonics = harmonics.value_or(-1);
        o.mesh_damping_ratio = mesh_damping_ratio;
        if (prior_mesh_stiffness)
          o.mesh_stiffness = {prior_mesh_stiffness, prior_mesh_stiffness_rsd};
        if (prior_mesh_damping) o.mesh_damping = {prior_mesh_damping, prior_mesh_damping_rsd};
        const DteIdentification r = identifyDte(known, data, o);
        py::dict d;
        d["mesh_stiffness"] = valueDict(r.mesh_stiffness);
        d["mean_te"] = valueDict(r.mean_te);
        d["mesh_damping"] = valueDict(r.mesh_damping);
        py::list tx, ty;
        for (const auto& h : r.te_x) tx.append(phasorDict(h));
        for (const auto& h : r.te_y) ty.append(phasorDict(h));
        d["te_x"] = tx;
        d["te_y"] = ty;
        d["pinion_runout"] = phasorDict(r.pinion_runout);
        d["gear_runout"] = phasorDict(r.gear_runout);
        d["converged"] = r.converged;
        d["message"] = r.message;
        d["chi_square"] = r.chi_square;
        d["rotor"] = r.spec;
        return d;
      },
      py::arg("known"), py::arg("spectra"), py::kw_only(), py::arg("method") = "joint",
      py::arg("harmonics") = py::none(), py::arg("mesh_damping_ratio") = 0.01,
      py::arg("prior_mesh_stiffness") = py::none(), py::arg("prior_mesh_stiffness_rsd") = 0.5,
      py::arg("prior_mesh_damping") = py::none(), py::arg("prior_mesh_damping_rsd") = 0.5,
      "Gear-mesh DTE parameters from whirl peaks (a list of gear_whirl_peaks results, one per "
      "speed; probe frame). `known` supplies masses, shafts, gravity and teeth. Returns values "
      "with 95 % intervals and identifiability, and 'rotor' (the identified LateralRotor).");
}

}  // namespace

void bindRotor(py::module_& m) {
  bindLateralRotorSpec(m);
  bindRotorFunctions(m);
}

}  // namespace geardyn::python
