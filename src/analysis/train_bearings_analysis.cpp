/// Rolling bearings from their geometry in `geardyn train` (train_bearings_analysis.h).

#include "train_bearings_analysis.h"

#include <fmt/format.h>

#include <cmath>

#include "geardyn/units.h"

namespace geardyn::analysis::detail {

using Json = nlohmann::ordered_json;

void writeRollingBearings(const GearTrainModel& model, const TrainStaticResult& r,
                          AnalysisResult& result, Json& out) {
  io::CsvTable table({"bearing", "type", "u_y_m", "u_z_m", "u_x_m", "theta_y_rad", "theta_z_rad",
                      "f_y_n", "f_z_n", "f_x_n", "m_y_n_m", "m_z_n_m", "max_element_load_n",
                      "max_contact_pressure_pa", "k_yy_n_per_m", "k_zz_n_per_m", "k_xx_n_per_m"});
  out = Json::object();
  for (std::size_t i = 0; i < r.rolling_bearings.size(); ++i) {
    const TrainRollingBearing& b = model.rollingBearings()[i];
    const RollingBearingState& s = r.rolling_bearings[i];
    const std::string type = toString(b.bearing->geometry().type);
    table.addRow({b.name, type, s.displacement(0), s.displacement(1), s.displacement(2),
                  s.displacement(3), s.displacement(4), s.load(0), s.load(1), s.load(2), s.load(3),
                  s.load(4), s.max_element_load, s.max_pressure, s.stiffness(0, 0),
                  s.stiffness(1, 1), s.stiffness(2, 2)});
    Json stiffness = Json::array();
    for (int row = 0; row < 5; ++row) {
      Json line = Json::array();
      for (int col = 0; col < 5; ++col) line.push_back(s.stiffness(row, col));
      stiffness.push_back(line);
    }
    Json loads = Json::array();
    for (const RollingElementState& e : s.elements) loads.push_back(e.load);
    out[b.name] = {{"type", type},
                   {"displacement",
                    {s.displacement(0), s.displacement(1), s.displacement(2), s.displacement(3),
                     s.displacement(4)}},
                   {"displacement_order", "u_y_m, u_z_m, u_x_m, theta_y_rad, theta_z_rad"},
                   {"load", {s.load(0), s.load(1), s.load(2), s.load(3), s.load(4)}},
                   {"radial_load_n", std::hypot(s.load(0), s.load(1))},
                   {"axial_load_n", s.load(2)},
                   {"stiffness_matrix", stiffness},
                   {"radial_stiffness_yy_n_per_m", s.stiffness(0, 0)},
                   {"element_load_n", loads},
                   {"max_element_load_n", s.max_element_load},
                   {"max_contact_pressure_pa", s.max_pressure},
                   {"rating_life_l10r_mrev", std::isfinite(s.rating_life) && s.rating_life > 0.0
                                                 ? Json(s.rating_life)
                                                 : Json(nullptr)}};
  }
  result.addTable("bearings.csv", table);
}

std::optional<GearTrainModel> linearModelOf(const GearTrainModel& model, AnalysisResult& result,
                                            std::string& text) {
  if (model.rollingBearings().empty()) return std::nullopt;
  const TrainStaticResult r = solveTrainStatic(model, model.inputSpeed());
  Json bearings;
  writeRollingBearings(model, r, result, bearings);
  result.summary.results["bearings"] = {
      {"model",
       "rolling bearings from their geometry (ISO/TS 16281): nonlinear, coupled 5x5, "
       "in the static deflection"},
      {"linear_analyses",
       fmt::format("modal, Campbell, forced response, time, run-up and the nonlinear analyses use "
                   "the bearings linearised at the static deflection at the operating point "
                   "({:.1f} rpm, {} Newton iterations, status {})",
                   model.inputSpeed() / units::kRpm, r.iterations, r.status)},
      {"static_status", r.status},
      {"newton_iterations", r.iterations},
      {"bearings", bearings}};
  if (r.status != "ok") result.summary.warnings.push_back(r.message);
  text += fmt::format(
      "bearings: {} from their geometry, linearised at the static deflection "
      "({} Newton iterations)\n",
      model.rollingBearings().size(), r.iterations);
  for (std::size_t i = 0; i < r.rolling_bearings.size(); ++i) {
    const RollingBearingState& s = r.rolling_bearings[i];
    text += fmt::format(
        "  {:<16} radial {:9.1f} N  axial {:9.1f} N  k_yy {:.3g} N/m  p_max "
        "{:.0f} MPa  L10r {:.0f} Mrev\n",
        model.rollingBearings()[i].name, std::hypot(s.load(0), s.load(1)), s.load(2),
        s.stiffness(0, 0), s.max_pressure * 1e-6, s.rating_life);
  }
  return model.linearisedAt(r.displacement);
}

}  // namespace geardyn::analysis::detail
