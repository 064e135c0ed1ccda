/// `ltca CONFIG`: loaded tooth contact analysis, Harris map and Gelman's statistics
/// against load.

#include <fmt/format.h>

#include <algorithm>
#include <chrono>

#include "geardyn/analysis/analyses.h"
#include "geardyn/analysis/geometry_results.h"
#include "geardyn/analysis/ltca_results.h"
#include "geardyn/config/geometry_config.h"
#include "geardyn/config/ltca_config.h"
#include "geardyn/contact/face_load.h"
#include "geardyn/error.h"
#include "train_loaded_contact_analysis.h"

namespace geardyn::analysis {

AnalysisResult ltcaAnalysis(const config::Config& config, const AnalysisContext& context) {
  AnalysisResult result("ltca", config, context);
  const GearPair pair(config::gearPairSpecFromConfig(config));
  const int slices = static_cast<int>(config.integer("ltca.slices"));
  PotentialEnergyOptions pe;
  if (pair.baseHelixAngle() > 0.0) pe.slices = slices;  // the same slices as the contact
  auto stiffness = std::make_shared<const PotentialEnergyMeshStiffness>(pair, pe);
  PairModifications modifications = config::pairModificationsFromConfig(config, *stiffness);
  modifications.misalignment = config.real("ltca.misalignment");
  const LoadedToothContact contact(stiffness, modifications, slices);
  const double force = config.real("ltca.force");
  const int positions = static_cast<int>(config.integer("ltca.positions"));

  io::RunSummary& summary = result.summary;
  summary.warnings = pair.warnings();
  summary.warnings.insert(summary.warnings.end(), stiffness->warnings().begin(),
                          stiffness->warnings().end());

  const auto start = std::chrono::steady_clock::now();
  const auto points =
      contact.sweep(force, positions, static_cast<int>(config.integer("ltca.periods")),
                    context.progressFor("ltca: loaded contact", "positions"));
  const double sweep_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.addTable("ltca.csv", analysis::ltcaTable(points, force));
  const FaceLoadDistribution face = faceLoadDistribution(
      contact, force, std::vector<LoadedContactPoint>(points.begin(), points.begin() + positions));
  detail::addFaceLoadTables(face, "face_load", result);
  const auto [lo, hi] = std::minmax_element(points.begin(), points.end(),
                                            [](auto& a, auto& b) { return a.ste < b.ste; });
  double mean_tangent = 0.0;
  for (const auto& p : points) mean_tangent += p.tangent / static_cast<double>(points.size());
  summary.results["ltca"] = {
      {"force", force},
      {"ste_peak_to_peak", hi->ste - lo->ste},
      {"ste_min", lo->ste},
      {"ste_max", hi->ste},
      {"mean_tangent_stiffness", mean_tangent},
      {"contact_ratio", stiffness->contactRatio()},
      {"misalignment_m", modifications.misalignment},
      {"face_load_factor", face.k_hbeta},
      {"face_load_factor_max", face.k_hbeta_max},
      {"centre_of_load_m", face.centre_of_load},
      {"loaded_face_fraction", face.loaded_fraction},
      {"gearbox_mesh", config.has("gearbox.mesh")
                           ? nlohmann::ordered_json(config.string("gearbox.mesh"))
                           : nlohmann::ordered_json(nullptr)},
      {"wall_time_s", sweep_seconds}};
  std::string text = config.has("gearbox.mesh")
                         ? fmt::format("mesh {} of {}:\n", config.string("gearbox.mesh"),
                                       config.string("gearbox.file"))
                         : std::string();
  text += fmt::format(
      "loaded tooth contact at {:g} N: STE {:.4g} .. {:.4g} um (peak to peak {:.4g} um), mean "
      "tangent stiffness {:.4g} N/m\n",
      force, 1e6 * lo->ste, 1e6 * hi->ste, 1e6 * (hi->ste - lo->ste), mean_tangent);
  text += fmt::format(
      "  across the face ({} slices): K_Hbeta {:.4f} [-] (largest instantaneous {:.4f} [-]), "
      "centre of "
      "load {:+.2f} mm from the mid-face, {:.0f} % of the face loaded\n",
      slices, face.k_hbeta, face.k_hbeta_max, 1e3 * face.centre_of_load,
      100 * face.loaded_fraction);

  const auto design = config.optionalReal("modifications.design_load");
  std::vector<double> factors = config.realList("harris.load_factors");
  if (factors.empty() && design) {
    for (int i = 1; i <= 20; ++i) factors.push_back(0.1 * i);
  }
  if (!factors.empty()) {
    const double reference = design.value_or(force);
    std::vector<double> loads;
    for (double f : factors) {
      if (!(f > 0.0)) throw InputError("harris.load_factors", fmt::format("{:g}", f), "> 0");
      loads.push_back(f * reference);
    }
    const auto t0 = std::chrono::steady_clock::now();
    const auto map =
        harrisMap(contact, loads, positions, 3, context.progressFor("ltca: Harris map", "loads"));
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    result.addTable("harris.csv", analysis::harrisTable(map));
    const auto best = std::min_element(
        map.begin(), map.end(), [](auto& a, auto& b) { return a.peak_to_peak < b.peak_to_peak; });
    summary.results["harris"] = {{"loads", loads.size()},
                                 {"minimum_at", best->force},
                                 {"minimum_peak_to_peak", best->peak_to_peak},
                                 {"wall_time_s", seconds}};
    text += fmt::format(
        "  Harris map ({} loads x {} positions, {:.3g} ms): minimum {:.4g} um at "
        "{:.4g} N\n",
        loads.size(), positions, 1e3 * seconds, 1e6 * best->peak_to_peak, best->force);

    // Other designs on the same loads (one Harris map each).
    const auto designs = config.stringList("harris.compare_reliefs");
    if (!designs.empty()) {
      if (!design) {
        throw InputError("harris.compare_reliefs", fmt::format("{} designs", designs.size()),
                         "needs modifications.design_load");
      }
      const ReliefShape shape = config.string("modifications.shape") == "linear"
                                    ? ReliefShape::kLinear
                                    : ReliefShape::kParabolic;
      io::CsvTable table({"design", "force_transverse_n", "peak_to_peak_m", "mean_m"});
      nlohmann::ordered_json minima = nlohmann::ordered_json::object();
      for (const auto& name : designs) {
        const PairModifications m =
            name == "none" ? PairModifications{}
                           : designedTipRelief(*stiffness, *design, name == "long", shape);
        const auto other =
            harrisMap(LoadedToothContact(stiffness, m, slices), loads, positions, 3,
                      context.progressFor("ltca: Harris map, design " + name, "loads"));
        for (const auto& p : other) table.addRow({name, p.force, p.peak_to_peak, p.mean});
        const auto low = std::min_element(other.begin(), other.end(), [](auto& a, auto& b) {
          return a.peak_to_peak < b.peak_to_peak;
        });
        minima[name] = {{"minimum_at", low->force}, {"minimum_peak_to_peak", low->peak_to_peak}};
        text += fmt::format("  design {}: minimum {:.4g} um at {:.4g} N\n", name,
                            1e6 * low->peak_to_peak, low->force);
      }
      result.addTable("harris_designs.csv", table);
      summary.results["harris"]["designs"] = minima;
    }
  }
  if (design) {
    double k_bar = 0.0;
    const auto stats = meanExcitationAgainstLoad(
        contact, *design, config.realList("statistics.load_factors"), positions, &k_bar,
        context.progressFor("ltca: statistics against load", "loads"));
    result.addTable("load_statistics.csv", analysis::loadStatisticsTable(stats));
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    for (const auto& s : stats) {
      rows.push_back({{"a", s.a},
                      {"r_ke", s.statistics.r_ke},
                      {"ratio_eq7", s.statistics.ratio},
                      {"ratio_eq11", s.statistics.ratio_eq11},
                      {"classification", s.statistics.classification()}});
    }
    summary.results["statistics"] = {{"design_load", *design},
                                     {"mean_tangent_stiffness_at_design_load", k_bar},
                                     {"loads", rows}};
  }
  context.warnings(summary.warnings);
  result.report = text;
  return result;
}

}  // namespace geardyn::analysis
