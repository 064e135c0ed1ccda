/// Python bindings of contact/: the loaded tooth contact analysis of a gear pair with designed
/// tip relief or explicit modifications, and its Harris map. Keyword names follow the
/// `geardyn ltca` configuration keys; SI units; numpy arrays out.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "geardyn/contact/loaded_contact.h"
#include "geardyn/error.h"

namespace py = pybind11;

namespace geardyn::python {
namespace {

std::shared_ptr<const LoadedToothContact> makeContact(const GearPair& pair,
                                                      const std::string& relief,
                                                      std::optional<double> design_load,
                                                      const std::string& shape, int slices,
                                                      double pinion_crowning) {
  PotentialEnergyOptions o;
  if (pair.baseHelixAngle() > 0.0) o.slices = slices;
  auto k = std::make_shared<const PotentialEnergyMeshStiffness>(pair, o);
  PairModifications m;
  if (relief != "none") {
    if (relief != "long" && relief != "short") {
      throw InputError("relief", relief, "one of \"none\", \"long\", \"short\"");
    }
    if (!design_load) throw InputError("design_load", "None", "needed by a designed relief [N]");
    m = designedTipRelief(*k, *design_load, relief == "long",
                          shape == "parabolic" ? ReliefShape::kParabolic : ReliefShape::kLinear);
  }
  m.pinion.crowning = pinion_crowning;
  return std::make_shared<const LoadedToothContact>(k, m, slices);
}

}  // namespace

void bindContact(py::module_& m) {
  m.def(
      "loaded_contact",
      [](const GearPair& pair, double force, const std::string& relief,
         std::optional<double> design_load, const std::string& shape, int positions, int slices,
         double crowning) {
        const auto c = makeContact(pair, relief, design_load, shape, slices, crowning);
        const auto points = c->sweep(force, positions);
        const auto n = static_cast<py::ssize_t>(points.size());
        py::array_t<double> phase(n), ste(n), no_load(n), secant(n), tangent(n);
        py::array_t<double> loads({n, static_cast<py::ssize_t>(c->pairCount())});
        for (py::ssize_t i = 0; i < n; ++i) {
          const auto& p = points[i];
          phase.mutable_at(i) = p.phase;
          ste.mutable_at(i) = p.ste;
          no_load.mutable_at(i) = p.no_load_te;
          secant.mutable_at(i) = p.secant;
          tangent.mutable_at(i) = p.tangent;
          for (int j = 0; j < c->pairCount(); ++j) loads.mutable_at(i, j) = p.pair_loads[j];
        }
        py::dict d;
        d["phase"] = phase;
        d["ste"] = ste;
        d["no_load_te"] = no_load;
        d["secant_stiffness"] = secant;
        d["tangent_stiffness"] = tangent;
        d["pair_loads"] = loads;
        return d;
      },
      py::arg("pair"), py::arg("force"), py::kw_only(), py::arg("relief") = "none",
      py::arg("design_load") = py::none(), py::arg("shape") = "linear", py::arg("positions") = 200,
      py::arg("slices") = 1, py::arg("crowning") = 0.0,
      "Loaded tooth contact over one mesh period at `force` [N] along the line of action: "
      "{'phase', 'ste' [m], 'no_load_te' [m], 'secant_stiffness', 'tangent_stiffness' [N/m], "
      "'pair_loads' [N] (positions x pairs)}. relief: \"none\", \"long\" or \"short\" tip "
      "relief designed for design_load [N]; crowning: pinion lead crowning [m].");
  m.def(
      "harris_map",
      [](const GearPair& pair, const std::vector<double>& forces, const std::string& relief,
         std::optional<double> design_load, const std::string& shape, int positions, int slices) {
        const auto c = makeContact(pair, relief, design_load, shape, slices, 0.0);
        const auto map = harrisMap(*c, forces, positions);
        py::array_t<double> ptp(static_cast<py::ssize_t>(map.size()));
        for (std::size_t i = 0; i < map.size(); ++i) ptp.mutable_at(i) = map[i].peak_to_peak;
        return ptp;
      },
      py::arg("pair"), py::arg("forces"), py::kw_only(), py::arg("relief") = "none",
      py::arg("design_load") = py::none(), py::arg("shape") = "linear", py::arg("positions") = 200,
      py::arg("slices") = 1, "Peak-to-peak loaded STE [m] at each force (a Harris map).");
}

}  // namespace geardyn::python
