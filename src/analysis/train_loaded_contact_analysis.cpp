/// `train`'s mesh misalignment and loaded contact across the face
/// (train_loaded_contact_analysis.h).

#include "train_loaded_contact_analysis.h"

#include <fmt/format.h>

#include <chrono>
#include <cmath>

#include "geardyn/analysis/run_budget.h"
#include "geardyn/config/ltca_config.h"
#include "geardyn/error.h"
#include "geardyn/io/csv_table.h"

namespace geardyn::analysis::detail {

nlohmann::ordered_json writeMeshMisalignment(const std::vector<MeshMisalignment>& meshes,
                                             AnalysisResult& result, std::string& text) {
  io::CsvTable table({"mesh", "face_width_m", "mid_face_x_m", "mismatch_m",
                      "mismatch_out_of_plane_m", "tilt_in_plane_rad", "tilt_out_of_plane_rad",
                      "approach_m", "centre_distance_change_m"});
  nlohmann::ordered_json json = nlohmann::ordered_json::object();
  for (const MeshMisalignment& m : meshes) {
    table.addRow({m.mesh, m.face_width, m.mid_face, m.mismatch, m.mismatch_out_of_plane,
                  m.tilt_in_plane, m.tilt_out_of_plane, m.approach, m.centre_distance_change});
    json[m.mesh] = {{"face_width_m", m.face_width},
                    {"mismatch_m", m.mismatch},
                    {"mismatch_out_of_plane_m", m.mismatch_out_of_plane},
                    {"tilt_in_plane_rad", m.tilt_in_plane},
                    {"tilt_out_of_plane_rad", m.tilt_out_of_plane},
                    {"approach_m", m.approach},
                    {"centre_distance_change_m", m.centre_distance_change}};
    text += fmt::format(
        "  mesh {:<12} misalignment f_ma {:+.3f} um in the plane of action ({:+.3f} um out of "
        "it) over {:.1f} mm, centre distance {:+.3f} um\n",
        m.mesh, 1e6 * m.mismatch, 1e6 * m.mismatch_out_of_plane, 1e3 * m.face_width,
        1e6 * m.centre_distance_change);
  }
  result.addTable("mesh_misalignment.csv", table);
  return json;
}

TrainLoadedContactOptions loadedContactOptions(const config::Config& analysis) {
  TrainLoadedContactOptions o;
  o.slices = static_cast<int>(analysis.integer("contact.slices"));
  o.positions = static_cast<int>(analysis.integer("contact.positions"));
  o.harmonics = static_cast<int>(analysis.integer("contact.harmonics"));
  o.tolerance = analysis.real("contact.tolerance");
  o.max_iterations = static_cast<int>(analysis.integer("contact.max_iterations"));
  if (2 * o.harmonics >= o.positions) {
    throw InputError("contact.harmonics", std::to_string(o.harmonics),
                     fmt::format("below contact.positions / 2 = {}", o.positions / 2));
  }
  o.validate();
  return o;
}

std::vector<std::shared_ptr<const LoadedToothContact>> gearboxMeshContacts(
    const GearTrainModel& model, const config::Config& gearbox, int slices) {
  auto contacts = trainMeshContacts(model, slices);
  const auto& meshes = gearbox.resolved().contains("meshes") ? gearbox.resolved()["meshes"]
                                                             : nlohmann::ordered_json::object();
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const std::string& name = model.meshes()[i].name;
    if (!contacts[i] || !meshes.contains(name) || !meshes[name].contains("modifications")) continue;
    const PairModifications mods = config::pairModificationsFromConfig(
        gearbox, contacts[i]->stiffness(), "meshes." + name + ".modifications");
    contacts[i] =
        std::make_shared<const LoadedToothContact>(contacts[i]->sharedStiffness(), mods, slices);
  }
  return contacts;
}

void addFaceLoadTables(const FaceLoadDistribution& face, const std::string& name,
                       AnalysisResult& result) {
  io::CsvTable table({"mesh_fraction", "z_m", "line_load_n_per_m"});
  for (std::size_t i = 0; i < face.points.size(); ++i) {
    for (std::size_t j = 0; j < face.z.size(); ++j)
      table.addRow({face.points[i].phase, face.z[j], face.line_load[i][j]});
  }
  result.addTable(name + ".csv", table);
  io::CsvTable mean({"z_m", "mean_line_load_n_per_m"});
  for (std::size_t j = 0; j < face.z.size(); ++j) mean.addRow({face.z[j], face.mean_line_load[j]});
  result.addTable(name + "_mean.csv", mean);
}

namespace {

/// The coupled fixed point at every load factor × the operating torque (the train rebuilt at
/// that torque, GearTrainModel::withParameters): contact_load_cases.csv; the summary's
/// per-case numbers.
nlohmann::ordered_json loadCases(
    const GearTrainModel& model,
    const std::vector<std::shared_ptr<const LoadedToothContact>>& contacts,
    const TrainLoadedContactOptions& options, const std::vector<double>& factors,
    AnalysisResult& result) {
  nlohmann::ordered_json json = nlohmann::ordered_json::array();
  if (factors.empty()) return json;
  std::vector<std::string> header{"load_factor",        "mesh",
                                  "force_transverse_n", "mismatch_m",
                                  "face_load_factor",   "centre_of_load_m",
                                  "ste_peak_to_peak_m"};
  for (int h = 1; h <= options.harmonics; ++h) header.push_back(fmt::format("ste_h{}_m", h));
  io::CsvTable table(header);
  for (double f : factors) {
    if (!(f > 0.0) || !std::isfinite(f)) {
      throw InputError("contact.load_factors", fmt::format("{:g}", f), "factors > 0");
    }
    GearTrainSpec spec = model.spec();
    spec.operating.input_torque *= f;
    const GearTrainModel scaled = model.withParameters(std::move(spec));
    const TrainLoadedContactResult r = solveTrainLoadedContact(scaled, contacts, options);
    nlohmann::ordered_json meshes = nlohmann::ordered_json::object();
    for (const TrainMeshLoadedContact& m : r.meshes) {
      const std::string& name = model.meshes()[m.mesh].name;
      std::vector<io::CsvCell> row{f,
                                   name,
                                   m.force_transverse,
                                   m.misalignment.mismatch,
                                   m.face.k_hbeta,
                                   m.face.centre_of_load,
                                   m.ste_peak_to_peak};
      for (const auto& c : m.ste_harmonics) row.push_back(std::abs(c));
      table.addRow(row);
      meshes[name] = {{"face_load_factor", m.face.k_hbeta},
                      {"mismatch_m", m.misalignment.mismatch},
                      {"ste_peak_to_peak_m", m.ste_peak_to_peak}};
    }
    json.push_back({{"load_factor", f}, {"converged", r.converged}, {"meshes", meshes}});
  }
  result.addTable("contact_load_cases.csv", table);
  return json;
}

}  // namespace

TrainLoadedContactResult runTrainContact(const GearTrainModel& model,
                                         const config::Config& analysis,
                                         const config::Config& gearbox, AnalysisResult& result,
                                         io::RunSummary& summary, std::string& text) {
  const auto start = std::chrono::steady_clock::now();
  if (model.dofsPerBody() != 6) {
    throw InputError("analysis.run", "\"contact\"",
                     "a gearbox with dofs = \"full\" (the misalignment is the gears' tilt)");
  }
  const TrainLoadedContactOptions options = loadedContactOptions(analysis);
  const auto contacts = gearboxMeshContacts(model, gearbox, options.slices);
  TrainLoadedContactResult r = solveTrainLoadedContact(model, contacts, options);
  io::CsvTable table({"mesh", "face_width_m", "mismatch_m", "force_transverse_n",
                      "face_load_factor", "face_load_factor_max", "centre_of_load_m",
                      "loaded_face_fraction", "ste_mean_m", "ste_peak_to_peak_m",
                      "mean_tangent_stiffness_n_per_m"});
  io::CsvTable harmonics({"mesh", "order", "amplitude_m", "phase_rad"});
  nlohmann::ordered_json meshes = nlohmann::ordered_json::object();
  std::string lines;
  for (const TrainMeshLoadedContact& m : r.meshes) {
    const std::string& name = model.meshes()[m.mesh].name;
    table.addRow({name, m.face.face_width, m.misalignment.mismatch, m.force_transverse,
                  m.face.k_hbeta, m.face.k_hbeta_max, m.face.centre_of_load, m.face.loaded_fraction,
                  m.ste_mean, m.ste_peak_to_peak, m.mean_tangent_stiffness});
    std::vector<double> amplitudes;
    for (std::size_t h = 0; h < m.ste_harmonics.size(); ++h) {
      amplitudes.push_back(std::abs(m.ste_harmonics[h]));
      harmonics.addRow({name, static_cast<double>(h + 1), std::abs(m.ste_harmonics[h]),
                        std::arg(m.ste_harmonics[h])});
    }
    addFaceLoadTables(m.face, "face_load_" + name, result);
    meshes[name] = {{"mismatch_m", m.misalignment.mismatch},
                    {"force_transverse_n", m.force_transverse},
                    {"face_load_factor", m.face.k_hbeta},
                    {"face_load_factor_max", m.face.k_hbeta_max},
                    {"centre_of_load_m", m.face.centre_of_load},
                    {"loaded_face_fraction", m.face.loaded_fraction},
                    {"ste_peak_to_peak_m", m.ste_peak_to_peak},
                    {"ste_harmonics_m", amplitudes},
                    {"mean_tangent_stiffness_n_per_m", m.mean_tangent_stiffness}};
    lines += fmt::format(
        "  mesh {:<12} f_ma {:+.3f} um: K_Hbeta {:.4f} [-], centre of load {:+.2f} mm, loaded STE "
        "{:.4g} um peak to peak ({:.4g} um at the mesh order)\n",
        name, 1e6 * m.misalignment.mismatch, m.face.k_hbeta, 1e3 * m.face.centre_of_load,
        1e6 * m.ste_peak_to_peak, amplitudes.empty() ? 0.0 : 1e6 * amplitudes[0]);
  }
  result.addTable("mesh_contact.csv", table);
  result.addTable("ste_harmonics.csv", harmonics);
  summary.results["contact"]["load_cases"] =
      loadCases(model, contacts, options, analysis.realList("contact.load_factors"), result);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  summary.results["contact"].update(nlohmann::ordered_json{{"iterations", r.iterations},
                                                           {"converged", r.converged},
                                                           {"tolerance", options.tolerance},
                                                           {"change_per_iteration", r.change},
                                                           {"slices", options.slices},
                                                           {"positions", options.positions},
                                                           {"meshes", meshes},
                                                           {"wall_time_s", seconds}});
  text += fmt::format("contact: {} after {} iterations (centre of load moved {:.3g} x b last)\n",
                      r.converged ? "converged" : "NOT converged", r.iterations,
                      r.change.empty() ? 0.0 : r.change.back()) +
          lines;
  if (!r.converged) {
    summary.warnings.push_back(fmt::format(
        "contact: the deflection <-> load distribution iteration did not reach contact.tolerance "
        "= {:g} in {} iterations (last change {:.3g} of the face width)",
        options.tolerance, r.iterations, r.change.empty() ? 0.0 : r.change.back()));
  }
  return r;
}

std::optional<GearTrainModel> withLoadedContactExcitation(const GearTrainModel& model,
                                                          const config::Config& analysis,
                                                          const config::Config& gearbox,
                                                          io::RunSummary& summary,
                                                          std::string& text) {
  std::vector<bool> wanted(model.meshes().size(), false);
  bool any = false;
  // Only the gearbox's [meshes.<name>] have the key (a planetary stage's meshes, named
  // <stage>.sun_planet<n>, are not in the schema).
  const auto& declared = gearbox.resolved().contains("meshes") ? gearbox.resolved()["meshes"]
                                                               : nlohmann::ordered_json::object();
  for (std::size_t i = 0; i < model.meshes().size(); ++i) {
    if (!declared.contains(model.meshes()[i].name)) continue;
    const std::string key = "meshes." + model.meshes()[i].name + ".excitation";
    if (!gearbox.has(key) || gearbox.string(key) != "ltca") continue;
    if (model.dofsPerBody() != 6 || model.meshes()[i].kind != TrainMeshKind::kExternal) {
      throw InputError(key, "\"ltca\"",
                       "an external mesh of a gearbox with dofs = \"full\" (the loaded contact "
                       "under the gearbox's tilts)");
    }
    wanted[i] = any = true;
  }
  if (!any) return std::nullopt;
  const TrainLoadedContactOptions options = loadedContactOptions(analysis);
  const auto contacts = gearboxMeshContacts(model, gearbox, options.slices);
  const TrainLoadedContactResult r = solveTrainLoadedContact(model, contacts, options);
  GearTrainSpec spec = loadedContactExcitation(model, r, wanted);
  nlohmann::ordered_json json = nlohmann::ordered_json::object();
  for (const TrainMeshLoadedContact& m : r.meshes) {
    if (!wanted[m.mesh]) continue;
    const std::string& name = model.meshes()[m.mesh].name;
    json[name] = {{"face_load_factor", m.face.k_hbeta},
                  {"mismatch_m", m.misalignment.mismatch},
                  {"ste_peak_to_peak_m", m.ste_peak_to_peak}};
    text += fmt::format(
        "  mesh {} excited by its loaded contact: k_t(phi) and e(phi) from {} positions "
        "(K_Hbeta {:.4f} [-], loaded STE {:.4g} um peak to peak)\n",
        name, m.face.points.size(), m.face.k_hbeta, 1e6 * m.ste_peak_to_peak);
  }
  summary.results["excitation_ltca"] = {
      {"iterations", r.iterations}, {"converged", r.converged}, {"meshes", json}};
  return GearTrainModel(std::move(spec), memoryLimitBytes());
}

}  // namespace geardyn::analysis::detail
