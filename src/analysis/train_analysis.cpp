/// `train`: any gear train described once (a gearbox file or inline) and
/// analysed: kinematics and phasing, statics, modes, Campbell, forced response, time response,
/// run-up (train_runup_analysis.cpp), mesh statistics (train_stats_analysis.cpp), nonlinear
/// steady state (train_nonlinear_analysis.cpp).

#include "geardyn/config/train_analysis.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <toml++/toml.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <filesystem>
#include <numbers>
#include <optional>
#include <set>
#include <string_view>

#include "geardyn/analysis/analyses.h"
#include "geardyn/analysis/gear_train_session.h"
#include "geardyn/analysis/run_budget.h"
#include "geardyn/analysis/run_estimates.h"
#include "geardyn/config/fe_rotor_config.h"
#include "geardyn/config/gearbox_config.h"
#include "geardyn/config/rexs_gearbox_config.h"
#include "geardyn/config/toml_parse.h"
#include "geardyn/error.h"
#include "geardyn/io/rexs/rexs_gearbox.h"
#include "geardyn/io/rexs/rexs_reader.h"
#include "geardyn/system/gear_train_model.h"
#include "geardyn/system/mesh_misalignment.h"
#include "geardyn/system/train_housing.h"
#include "geardyn/units.h"
#include "train_bearings_analysis.h"
#include "train_forced_analysis.h"
#include "train_geometry.h"
#include "train_housing_analysis.h"
#include "train_loaded_contact_analysis.h"
#include "train_nonlinear_analysis.h"
#include "train_probes_analysis.h"
#include "train_runup_analysis.h"
#include "train_stats_analysis.h"
#include "train_time_analysis.h"
#include "train_undamped_modes.h"
#include "wall_clock.h"

namespace geardyn::analysis {
namespace {

using geardyn::units::kRpm;
using Json = nlohmann::ordered_json;
using detail::Clock;
using detail::secondsSince;

std::string stageTypes(const TrainMode& mode) {
  std::string out;
  for (const auto& t : mode.stage_type) out += (out.empty() ? "" : "/") + t;
  return out;
}

void writeKinematics(const GearTrainModel& model, AnalysisResult& result, io::RunSummary& summary,
                     std::string& text) {
  const double speed = model.inputSpeed();
  io::CsvTable bodies({"body", "kind", "shaft", "speed_ratio", "speed_rpm", "centre_y_m",
                       "centre_z_m", "axial_x_m", "mass_kg", "polar_inertia_kg_m2"});
  Json json = Json::array();
  for (const TrainBody& b : model.bodies()) {
    bodies.addRow({b.name, b.kind == TrainBodyKind::kPlanet ? "planet" : "shaft",
                   b.shaft >= 0 ? model.spec().shafts[b.shaft].name : std::string(), b.speed_ratio,
                   b.speed_ratio * speed / kRpm, b.centre.x(), b.centre.y(), b.axial, b.mass,
                   b.polar_inertia});
    json.push_back({{"body", b.name},
                    {"speed_ratio", b.speed_ratio},
                    {"speed_rpm", b.speed_ratio * speed / kRpm},
                    {"centre_m", {b.centre.x(), b.centre.y()}},
                    {"mass_kg", b.mass},
                    {"polar_inertia_kg_m2", b.polar_inertia}});
  }
  result.addTable("bodies.csv", bodies);
  io::CsvTable meshes({"mesh", "kind", "body_a", "body_b", "teeth_a", "teeth_b",
                       "mesh_frequency_hz", "phase_periods", "centre_distance_m",
                       "pressure_angle_deg", "contact_ratio", "mean_stiffness_normal_n_per_m",
                       "damping_normal_n_s_per_m"});
  Json mj = Json::array();
  for (const TrainMesh& m : model.meshes()) {
    const double f = m.frequency_ratio * std::abs(speed);
    meshes.addRow({m.name, toString(m.kind), model.bodies()[m.body_a].name,
                   model.bodies()[m.body_b].name, static_cast<long long>(m.teeth_a),
                   static_cast<long long>(m.teeth_b), f, m.phase, m.centre_distance,
                   m.pressure_angle / std::numbers::pi * 180, m.contact_ratio, m.mean_stiffness,
                   m.damping});
    mj.push_back({{"mesh", m.name},
                  {"kind", toString(m.kind)},
                  {"mesh_frequency_hz", f},
                  {"phase_periods", m.phase},
                  {"mean_stiffness_n_per_m", m.mean_stiffness}});
    text += fmt::format("  mesh {:<20} {:>9.2f} Hz  phase {:.4f} periods  k̄ {:.4g} N/m\n", m.name,
                        f, m.phase, m.mean_stiffness);
  }
  result.addTable("meshes.csv", meshes);
  summary.results["kinematics"] = {{"input_speed_rpm", speed / kRpm},
                                   {"output_torque_n_m", model.outputTorque()},
                                   {"bodies", json},
                                   {"meshes", mj}};
  summary.results["geometry"] = detail::trainGeometry(model);
}

void runStatic(const GearTrainModel& model, AnalysisResult& result, io::RunSummary& summary,
               std::string& text) {
  const auto start = Clock::now();
  const TrainStaticResult r = solveTrainStatic(model, model.inputSpeed());
  // Mesh forces along the contact normal [N]; an element's force resultant [N] and moment
  // resultant [N m] over its rows (TrainElement::moment_rows), one line each it has.
  io::CsvTable forces({"component", "kind", "unit", "force"});
  Json meshes = Json::object(), element_forces = Json::object(), element_moments = Json::object();
  for (std::size_t m = 0; m < model.meshes().size(); ++m) {
    forces.addRow({model.meshes()[m].name, "mesh_n", "N", r.mesh_force[m]});
    meshes[model.meshes()[m].name] = r.mesh_force[m];
  }
  for (std::size_t e = 0; e < model.elements().size(); ++e) {
    const TrainElement& el = model.elements()[e];
    const ElementLoad& load = r.element_load[e];
    if (load.has_force) {
      forces.addRow({el.name, el.kind + "_n", "N", load.force});
      element_forces[el.name] = load.force;
    }
    if (load.has_moment) {
      forces.addRow({el.name, el.kind + "_n_m", "N m", load.moment});
      element_moments[el.name] = load.moment;
    }
  }
  result.addTable("static_forces.csv", forces);
  Json sharing = Json::array();
  for (const auto& s : r.load_sharing) {
    sharing.push_back({{"stage", s.stage},
                       {"load_sharing_factor", s.load_sharing_factor},
                       {"sun_planet_force_n", s.sun_planet_force},
                       {"ring_planet_force_n", s.ring_planet_force}});
    text += fmt::format("  {}: planet load sharing factor {:.4f} [-]\n", s.stage,
                        s.load_sharing_factor);
  }
  summary.results["static"] = {{"status", r.status},
                               {"rigid_modes", r.rigid_modes},
                               {"relative_residual", r.residual},
                               {"mesh_force_n", meshes},
                               {"element_force_n", element_forces},
                               {"element_moment_n_m", element_moments},
                               {"load_sharing", sharing},
                               {"newton_iterations", r.iterations},
                               {"wall_time_s", secondsSince(start)}};
  if (r.status != "ok") summary.warnings.push_back(r.message);
  text += fmt::format("static: {} ({} rigid-body modes)\n", r.status, r.rigid_modes);
  if (model.dofsPerBody() == 6) {
    summary.results["static"]["misalignment"] =
        detail::writeMeshMisalignment(meshMisalignment(model, r.displacement), result, text);
  }
}

void runModal(const GearTrainModel& model, const config::Config& analysis, AnalysisResult& result,
              io::RunSummary& summary, std::string& text) {
  const auto start = Clock::now();
  const double speed = config::analysisSpeed(analysis, "modal", model.inputSpeed());
  const auto modes =
      trainModes(model, speed, config::trainModalOptionsFromConfig(analysis, "modal"));
  std::vector<std::string> header{"mode",       "frequency_hz",          "damping_ratio",
                                  "divergent",  "growth_rate_1_per_s",   "multiplicity",
                                  "stage_type", "translational_fraction"};
  for (const TrainMesh& m : model.meshes()) header.push_back("strain_" + m.name);
  for (const TrainElement& e : model.elements()) header.push_back("strain_" + e.name);
  // A flexible housing: the mode's type ("housing" when most of its kinetic energy is there),
  // the housing's kinetic and strain energy fractions.
  const bool housed = model.housingFirstDof() >= 0;
  if (housed) {
    for (const char* c : {"mode_type", "housing_fraction", "strain_housing"}) header.push_back(c);
  }
  io::CsvTable table(header);
  io::CsvTable shapes({"mode", "dof", "real", "imag"});
  Json list = Json::array();
  for (std::size_t j = 0; j < modes.size(); ++j) {
    const TrainMode& m = modes[j];
    std::vector<io::CsvCell> row{std::to_string(j + 1), m.frequency,
                                 m.damping_ratio,       static_cast<long long>(m.divergent),
                                 m.growthRate(),        std::to_string(m.multiplicity),
                                 stageTypes(m),         m.translational_fraction};
    row.insert(row.end(), m.mesh_strain_energy.begin(), m.mesh_strain_energy.end());
    row.insert(row.end(), m.element_strain_energy.begin(), m.element_strain_energy.end());
    if (housed) {
      row.insert(row.end(), {m.whirl, m.housing_fraction, m.housing_strain_energy});
    }
    table.addRow(row);
    for (int i = 0; i < model.dofCount(); ++i) {
      shapes.addRow(
          {static_cast<long long>(j + 1), model.dofName(i), m.shape(i).real(), m.shape(i).imag()});
    }
    list.push_back({{"frequency_hz", m.frequency},
                    {"damping_ratio", m.damping_ratio},
                    {"divergent", m.divergent},
                    {"growth_rate_1_per_s", m.growthRate()},
                    {"multiplicity", m.multiplicity},
                    {"stage_type", m.stage_type}});
    if (housed) {
      list.back()["mode_type"] = m.whirl;
      list.back()["housing_fraction"] = m.housing_fraction;
      list.back()["housing_strain_energy"] = m.housing_strain_energy;
    }
  }
  const auto divergent =
      std::count_if(modes.begin(), modes.end(), [](const TrainMode& m) { return m.divergent; });
  if (divergent > 0) {
    double rate = 0.0;
    for (const TrainMode& m : modes) rate = std::max(rate, m.divergent ? m.eigenvalue.real() : 0.0);
    summary.warnings.push_back(fmt::format(
        "modal at {:.1f} rpm: {} divergent mode(s), growth rate up to {:.4g} 1/s: the train is "
        "statically unstable at this speed (a negative stiffness, e.g. centripetal softening of a "
        "member in a carrier frame beyond its support); a time response grows as e^(rate t)",
        speed / kRpm, divergent, rate));
  }
  // A model without any damping is a conservative system analysed on purpose (Lin & Parker's
  // modes); some undamped modes among damped ones are what a user overlooks.
  if (!model.dampingAt(speed).isZero(0.0)) {
    const std::string undamped =
        detail::undampedModesWarning(model, trainUndampedModes(model, modes), speed / kRpm);
    if (!undamped.empty()) summary.warnings.push_back(undamped);
  }
  result.addTable("modes.csv", table);
  result.addTable("mode_shapes.csv", shapes);
  // The lowest elastic natural frequency: neither a rigid-body mode (below 1e-6 × the highest
  // frequency, TrainModalOptions::rigid_frequency's default) nor a divergence; null if none.
  Json lowest = nullptr;
  const double highest = modes.empty() ? 0.0 : modes.back().frequency;
  for (const TrainMode& m : modes) {
    if (m.divergent || m.frequency <= 1e-6 * highest) continue;
    lowest = m.frequency;
    break;
  }
  summary.results["modal"] = {{"speed_rpm", speed / kRpm},
                              {"lowest_frequency_hz", lowest},
                              {"modes", list},
                              {"wall_time_s", secondsSince(start)}};
  text += fmt::format("modal at {:.1f} rpm: {} modes", speed / kRpm, modes.size());
  for (std::size_t j = 0; j < modes.size() && j < 8; ++j) {
    if (modes[j].divergent) {
      text += fmt::format("{} divergent ({:.4g} 1/s)", j ? "," : ":", modes[j].eigenvalue.real());
    } else {
      text += fmt::format("{} {:.1f} Hz", j ? "," : ":", modes[j].frequency);
    }
  }
  text += modes.size() > 8 ? ", …\n" : "\n";
}

void runCampbell(const GearTrainModel& model, const config::Config& analysis,
                 AnalysisResult& result, io::RunSummary& summary, std::string& text,
                 const AnalysisContext& context) {
  const auto start = Clock::now();
  const auto speeds = config::speedRangeFromConfig(analysis, "campbell", model.inputSpeed(), 0.0);
  TrainModalOptions options;
  options.modes =
      std::min<int>(static_cast<int>(analysis.integer("campbell.modes")), model.dofCount());
  const auto lines =
      trainOrderLines(model, static_cast<int>(analysis.integer("campbell.mesh_harmonics")));
  const TrainCampbell d = trainCampbell(model, speeds, options, lines,
                                        context.progressFor("train: Campbell", "speeds"));
  std::vector<std::string> header{"speed_rpm"};
  for (std::size_t j = 0; j < d.modes.front().size(); ++j)
    header.push_back(fmt::format("mode_{}_hz", j + 1));
  header.push_back("divergence_rate_1_per_s");
  io::CsvTable table(header);
  std::size_t first_divergent = speeds.size(), last_divergent = 0;
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    std::vector<io::CsvCell> row{speeds[i] / kRpm};
    for (const auto& m : d.modes[i]) row.emplace_back(std::in_place_type<double>, m.frequency);
    row.push_back(d.divergence_rate[i]);
    table.addRow(row);
    if (d.divergence_rate[i] > 0.0) {
      first_divergent = std::min(first_divergent, i);
      last_divergent = i;
    }
  }
  Json divergence = nullptr;
  if (first_divergent < speeds.size()) {
    const double rate = *std::max_element(d.divergence_rate.begin(), d.divergence_rate.end());
    divergence = {{"from_rpm", speeds[first_divergent] / kRpm},
                  {"to_rpm", speeds[last_divergent] / kRpm},
                  {"max_growth_rate_1_per_s", rate}};
    summary.warnings.push_back(fmt::format(
        "campbell: divergent modes (statically unstable train) between {:.1f} and {:.1f} rpm, "
        "growth rate up to {:.4g} 1/s (campbell.csv divergence_rate_1_per_s); they are not "
        "tracked as modes",
        speeds[first_divergent] / kRpm, speeds[last_divergent] / kRpm, rate));
  }
  result.addTable("campbell.csv", table);
  io::CsvTable lt({"line", "hz_per_rpm"});
  for (const auto& l : lines) lt.addRow({l.name, l.slope * kRpm});
  result.addTable("order_lines.csv", lt);
  io::CsvTable ct({"mode", "line", "speed_rpm", "frequency_hz"});
  Json crit = Json::array();
  for (const auto& c : d.critical_speeds) {
    ct.addRow({static_cast<long long>(c.mode + 1), c.line, c.speed / kRpm, c.frequency});
    crit.push_back({{"mode", c.mode + 1},
                    {"line", c.line},
                    {"speed_rpm", c.speed / kRpm},
                    {"frequency_hz", c.frequency}});
  }
  result.addTable("critical_speeds.csv", ct);
  summary.results["campbell"] = {{"speeds", speeds.size()},
                                 {"critical_speeds", crit},
                                 {"divergence", divergence},
                                 {"wall_time_s", secondsSince(start)}};
  text += fmt::format("campbell: {} speeds, {} critical speeds\n", speeds.size(),
                      d.critical_speeds.size());
}

/// The schemas of `train`, inline gearbox or not, declared once: declaring one takes about as
/// long as a small train's whole analysis (0.4 ms), and parseConfig only reads it (no mutable
/// state), so every run and thread shares them.
const config::ConfigSchema& trainSchemaOnce(bool inline_gearbox) {
  static const config::ConfigSchema with_gearbox = config::trainSchema(true);
  static const config::ConfigSchema without_gearbox = config::trainSchema(false);
  return inline_gearbox ? with_gearbox : without_gearbox;
}

/// The gearbox file an analysis file names: its gearbox.file, or the last --set of it (a sweep
/// over gearbox files); "" when the gearbox is inline.
std::string gearboxFileOf(std::string_view text, const std::string& source,
                          const std::vector<std::string>& overrides) {
  std::string ref;
  try {
    const toml::table table = config::parseToml(text, source);
    if (auto node = table.at_path("gearbox.file"); node && node.is_string())
      ref = *node.value<std::string>();
  } catch (const std::exception&) {
    // parseConfig reports a syntax error with its location.
  }
  for (const std::string& o : overrides) {
    const auto eq = o.find('=');
    std::string key = o.substr(0, eq);
    key.erase(key.find_last_not_of(" \t") + 1);
    key.erase(0, key.find_first_not_of(" \t"));
    if (key != "gearbox.file" || eq == std::string::npos) continue;
    std::string value = o.substr(eq + 1);
    value.erase(value.find_last_not_of(" \t") + 1);
    value.erase(0, value.find_first_not_of(" \t"));
    try {  // TOML ("x.toml"), or a bare word taken as a string, as config::parseConfig does
      const toml::table parsed = config::parseToml("v = " + value, "--set");
      if (auto v = parsed["v"].value<std::string>()) value = *v;
    } catch (const toml::parse_error&) {
    }
    ref = value;
  }
  return ref;
}

}  // namespace

TrainInputs loadTrainInputs(const std::filesystem::path& file,
                            const std::vector<std::string>& overrides) {
  return parseTrainInputs(config::readConfigFile(file), file.string(), file.parent_path(),
                          overrides);
}

TrainInputs parseTrainInputs(std::string_view text, const std::string& source,
                             const std::filesystem::path& base_dir,
                             const std::vector<std::string>& overrides) {
  const std::string ref = gearboxFileOf(text, source, overrides);
  if (ref.empty()) {
    config::Config both = config::parseConfig(text, source, trainSchemaOnce(true), overrides);
    if (both.has("gearbox.load_case"))
      throw InputError("gearbox.load_case", std::to_string(both.integer("gearbox.load_case")),
                       "only with a REXS gearbox file named by gearbox.file");
    return {both, both, source, source, {}};
  }
  // Every override names a key of the analysis file or of the gearbox (before they are split,
  // so that neither file's schema alone answers "unknown key; the keys in [...] are: (none)").
  config::checkOverrideKeys(trainSchemaOnce(true), overrides);
  std::vector<std::string> analysis_overrides, gearbox_overrides;
  const auto& sections = config::gearboxSectionNames();
  for (const auto& o : overrides) {
    const std::string first = o.substr(0, o.find_first_of(".="));
    // [gearbox] file, load_case and all_load_cases belong to the analysis file.
    std::string key = o.substr(0, o.find('='));
    key.erase(key.find_last_not_of(" \t") + 1);
    const bool analysis_key =
        key == "gearbox.file" || key == "gearbox.load_case" || key == "gearbox.all_load_cases";
    const bool to_gearbox =
        std::find(sections.begin(), sections.end(), first) != sections.end() && !analysis_key;
    (to_gearbox ? gearbox_overrides : analysis_overrides).push_back(o);
  }
  const std::filesystem::path path = base_dir / ref;
  config::Config analysis =
      config::parseConfig(text, source, trainSchemaOnce(false), analysis_overrides);
  std::optional<int> load_case;
  if (analysis.has("gearbox.load_case"))
    load_case = static_cast<int>(analysis.integer("gearbox.load_case"));
  std::vector<std::string> warnings;
  // A REXS file is imported in memory and read by the same gearTrainFromConfig as a TOML one.
  config::Config gearbox = config::loadGearboxConfig(path, gearbox_overrides, load_case, warnings);
  return {analysis, gearbox, source, path.string(), warnings};
}

config::Config TrainInputs::combined() const {
  if (gearbox_source == analysis_source) return analysis;
  nlohmann::ordered_json both = gearbox.resolved();
  for (const auto& [section, value] : analysis.resolved().items()) {
    if (both.contains(section) && both[section].is_object() && value.is_object()) {
      both[section].update(value);
    } else {
      both[section] = value;
    }
  }
  return config::Config(std::move(both), analysis_source);
}

AnalysisResult trainAnalysis(const TrainInputs& loaded, const AnalysisContext& context) {
  const auto start = Clock::now();
  std::vector<std::string> warnings;
  const std::vector<std::string> analyses = loaded.analysis.stringList("analysis.run");
  GearTrainSpec spec = config::gearTrainFromConfig(loaded.gearbox, warnings);
  detail::attachTrainHousing(loaded.gearbox, loaded.analysis, analyses, spec);
  // A train whose dense matrices would not fit is refused before they are allocated.
  const GearTrainModel model(std::move(spec), memoryLimitBytes());
  AnalysisResult result = trainAnalysis(loaded, model, analyses, context, warnings);
  result.summary.results["wall_time_s"] = secondsSince(start);
  result.summary.wall_time_s = secondsSince(start);
  return result;
}

AnalysisResult trainAnalysis(const TrainInputs& loaded, const GearTrainModel& given,
                             const std::vector<std::string>& analyses,
                             const AnalysisContext& context,
                             const std::vector<std::string>& spec_warnings) {
  const auto start = Clock::now();
  AnalysisResult result("train", loaded.analysis, context);
  io::RunSummary& summary = result.summary;
  if (loaded.gearbox_source != loaded.analysis_source) {
    summary.config["gearbox_description"] = loaded.gearbox.resolved();
  }
  std::vector<std::string> warnings = loaded.warnings;
  warnings.insert(warnings.end(), spec_warnings.begin(), spec_warnings.end());
  warnings.insert(warnings.end(), given.warnings().begin(), given.warnings().end());
  summary.warnings = warnings;
  std::string text = fmt::format(
      "gear train {}: {} bodies, {} meshes, {} DOFs ({})\n",
      given.spec().name.empty() ? loaded.gearbox_source : given.spec().name, given.bodies().size(),
      given.meshes().size(), given.dofCount(), toString(given.spec().dofs));
  // Meshes with excitation = "ltca" take their loaded contact under the gearbox's deflection.
  const std::optional<GearTrainModel> excited =
      detail::withLoadedContactExcitation(given, loaded.analysis, loaded.gearbox, summary, text);
  const GearTrainModel& model = excited ? *excited : given;
  writeKinematics(model, result, summary, text);
  if (model.housingFirstDof() >= 0) {
    const TrainHousingSpec& h = *model.spec().housing;
    // The modal coordinates: the fixed-interface modes, then the residual vectors.
    const Eigen::Index rv = h.reduced.residual_vectors;
    const Eigen::VectorXd f =
        h.reduced.mode_frequencies_hz.head(h.reduced.mode_frequencies_hz.size() - rv);
    text += fmt::format("housing {}: {} seats, {} fixed-interface modes{}{}, {} DOFs\n", h.source,
                        h.reduced.seats.size(), f.size(),
                        f.size() > 0 ? fmt::format(" ({:.1f} to {:.1f} Hz)", f(0), f(f.size() - 1))
                                     : std::string(rv > 0 ? "" : " (Guyan)"),
                        rv > 0 ? fmt::format(" + {} residual vectors", rv) : std::string(),
                        model.dofCount() - model.housingFirstDof());
    summary.results["housing"] = {
        {"deck", h.source},
        {"seats", h.reduced.seats},
        {"points", h.reduced.points},
        {"dofs", model.dofCount() - model.housingFirstDof()},
        {"fixed_interface_modes_hz", std::vector<double>(f.data(), f.data() + f.size())},
        {"residual_vectors", rv},
        {"cache_file", h.cache_file},
        {"from_cache", h.from_cache},
        {"assembly_s", h.assembly_s},
        {"factorisation_s", h.reduced.factorisation_s},
        {"modes_s", h.reduced.modes_s},
        {"other_reduction_s", h.reduced.other_s}};
  }
  // Bearings from their geometry: the static deflection is nonlinear; every other analysis
  // takes them linearised there (summary.results.bearings says so).
  const std::optional<GearTrainModel> linearised = detail::linearModelOf(model, result, text);
  const GearTrainModel& linear = linearised ? *linearised : model;
  // What has finished is shown at once (warnings, then the report's new lines): a run of
  // several analyses may take minutes.
  std::size_t warned = 0;
  std::set<std::string> shown;  // one line per warning: modal and time find the same modes
  const auto flush = [&] {
    std::vector<std::string> fresh;
    for (; warned < summary.warnings.size(); ++warned) {
      if (shown.insert(summary.warnings[warned]).second) fresh.push_back(summary.warnings[warned]);
    }
    context.warnings(fresh);
    if (context.print && text.size() > result.printed) {
      context.print(text.substr(result.printed));
      result.printed = text.size();
    }
  };
  flush();
  int code = 0;
  std::string status = "ok";
  std::optional<TrainTimeResponse> time_record;  // `time`'s Newmark run, reused by `stats`
  for (const std::string& analysis : analyses) {
    flush();
    if (analysis == "static") runStatic(model, result, summary, text);
    if (analysis == "contact")
      detail::runTrainContact(model, loaded.analysis, loaded.gearbox, result, summary, text);
    if (analysis == "modal") runModal(linear, loaded.analysis, result, summary, text);
    if (analysis == "campbell")
      runCampbell(linear, loaded.analysis, result, summary, text, context);
    if (analysis == "forced") {
      detail::runTrainForced(linear, loaded.analysis, result, summary, text, context);
    }
    if (analysis == "time")
      code = std::max(
          code, detail::runTrainTime(linear, loaded.analysis, result, text, time_record, context));
    if (analysis == "runup") {
      code = std::max(code, detail::runTrainRunUp(linear, loaded.analysis, result, text, context));
    }
    if (analysis == "stats") {
      code = std::max(code, detail::runTrainStats(linear, loaded.analysis, result, text,
                                                  time_record ? &*time_record : nullptr));
    }
    if (analysis == "nonlinear") {
      const std::string s =
          detail::runTrainNonlinear(linear, loaded.analysis, result, text, context);
      if (s != "ok") status = s, code = std::max(code, 1);
    }
  }
  if (status == "ok" && code != 0) status = "diverged";
  summary.status = status;
  summary.results["wall_time_s"] = secondsSince(start);
  flush();
  std::vector<std::string> once;
  for (const auto& w : summary.warnings) {
    if (std::find(once.begin(), once.end(), w) == once.end()) once.push_back(w);
  }
  summary.warnings = once;
  result.report = text;
  result.summary.numerical_failure = code != 0;
  result.summary.wall_time_s = secondsSince(start);
  return result;
}

}  // namespace geardyn::analysis
