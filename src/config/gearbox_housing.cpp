/// The gearbox file's [housing] (gearbox_housing.h).

#include "geardyn/config/gearbox_housing.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <memory>

#include "geardyn/config/did_you_mean.h"
#include "geardyn/error.h"

namespace geardyn::config {
namespace {

namespace fs = std::filesystem;

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

/// A path of the gearbox file, relative to that file's folder.
std::string relativeToGearbox(const Config& gearbox, const std::string& path) {
  if (path.empty() || fs::path(path).is_absolute()) return path;
  return (fs::path(gearbox.source()).parent_path() / path).lexically_normal().string();
}

}  // namespace

void addHousingKeys(ConfigSchema& schema) {
  schema.section("housing",
                 "A flexible housing from a finite-element mesh (CalculiX deck), reduced by "
                 "Craig-Bampton and joined to the bearings' outer rings (docs/guide/housing.md).");
  schema.string("housing.deck")
      .optional()
      .doc(
          "CalculiX deck (.inp, relative to this file): mesh, material, *BOUNDARY, no *STEP; "
          "one *NSET per bearing seat named as its bearing");
  schema.string("housing.units")
      .choices({"si", "mm_t_s"})
      .optional()
      .doc("the deck's units, required: \"si\" (m, kg, s) or \"mm_t_s\" (mm, t, s)");
  schema.stringList("housing.seats")
      .optional()
      .doc(
          "seat node sets, each named as the bearing it carries (default: one per bearing to "
          "the housing, named as the bearing)");
  schema.stringList("housing.points")
      .defaultValue(nlohmann::ordered_json::array())
      .doc("response point node sets (their mean translation is reported)");
  schema.real("housing.cutoff_hz")
      .unit("Hz")
      .positive()
      .optional()
      .doc("fixed-interface modes kept below it (default: 2 x the highest analysed frequency)");
  schema.integer("housing.modes")
      .min(0)
      .optional()
      .doc("exactly this many fixed-interface modes instead of the cut-off (0: Guyan)");
  schema.boolean("housing.residual_vectors")
      .defaultValue(true)
      .doc(
          "add six residual vectors a seat to the fixed-interface modes (the truncated modes' "
          "static share of the seats' inertia load; false with modes = 0: Guyan)");
  schema.real("housing.stiffness_proportional_damping")
      .unit("s")
      .min(0.0)
      .defaultValue(0.0)
      .doc("beta of the housing's damping beta K_h (zeta = beta omega / 2)");
  for (const char* key : {"stiffness_matrix", "mass_matrix", "dof_map"}) {
    schema.string(std::string("housing.") + key)
        .optional()
        .doc(
            "K, M (MatrixMarket) and the node.direction DOF map from another tool, instead of "
            "ccx's assembly (the deck then gives nodes and sets only)");
  }
  schema.collection("housing.mounts",
                    "Mounting points: node sets held rigidly (no stiffness) or elastically.");
  schema.section("housing.mounts.*", "One mounting point (a node set of the deck).");
  schema.real("housing.mounts.*.stiffness")
      .unit("N/m")
      .positive()
      .optional()
      .doc("total stiffness in x, y and z, spread over the set's nodes (absent: fixed)");
}

bool hasHousing(const Config& gearbox) {
  return gearbox.has("housing.deck");
}

HousingSource housingSourceFromConfig(const Config& gearbox, const GearTrainSpec& spec,
                                      double default_cutoff_hz, std::vector<HousingLink>& links) {
  HousingSource source;
  source.deck = relativeToGearbox(gearbox, gearbox.string("housing.deck"));
  if (!gearbox.has("housing.units")) {
    throw InputError("housing.units", "(not declared)",
                     "the deck's units, \"si\" (m, kg, s) or \"mm_t_s\" (mm, t, s): a deck's "
                     "numbers have no units of their own");
  }
  source.units = gearbox.string("housing.units");
  std::vector<std::string> to_housing;  // bearings from a shaft to the housing
  for (const auto& b : spec.bearings) {
    if (b.other_shaft.empty()) to_housing.push_back(b.name);
  }
  links.clear();
  if (gearbox.has("housing.seats")) {
    for (const std::string& seat : gearbox.stringList("housing.seats")) {
      const auto b = std::find_if(to_housing.begin(), to_housing.end(),
                                  [&](const std::string& n) { return upper(n) == upper(seat); });
      if (b == to_housing.end()) {
        std::string lower = seat;  // bearing names are compared without case
        for (char& ch : lower) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
        const auto match = closestMatch(lower, to_housing);
        throw InputError("housing.seats", "\"" + seat + "\"",
                         "a node set named as the bearing to the housing it carries" +
                             (match ? " (did you mean \"" + *match + "\"?)" : std::string()));
      }
      links.push_back({*b, seat});
      source.seats.push_back(seat);
    }
  } else {
    for (const std::string& b : to_housing) links.push_back({b, b}), source.seats.push_back(b);
  }
  for (const std::string& b : to_housing) {
    if (std::none_of(links.begin(), links.end(),
                     [&](const HousingLink& l) { return l.bearing == b; })) {
      throw InputError("housing.seats", "\"" + b + "\"",
                       "a seat for every bearing to the housing: bearing \"" + b +
                           "\" has none (add its node set to housing.seats)");
    }
  }
  source.points = gearbox.stringList("housing.points");
  source.reduction.key = "housing";
  source.reduction.residual_vectors = gearbox.boolean("housing.residual_vectors");
  if (gearbox.has("housing.modes")) {
    source.reduction.modes = static_cast<int>(gearbox.integer("housing.modes"));
  } else {
    source.reduction.cutoff_hz =
        gearbox.has("housing.cutoff_hz") ? gearbox.real("housing.cutoff_hz") : default_cutoff_hz;
  }
  for (const std::string& set : gearbox.names("housing.mounts")) {
    const std::string key = "housing.mounts." + set + ".stiffness";
    if (gearbox.has(key)) {
      source.elastic_mounts.emplace_back(set, gearbox.real(key));
    } else {
      source.fixed_mounts.push_back(set);
    }
  }
  const bool any = gearbox.has("housing.stiffness_matrix") || gearbox.has("housing.mass_matrix") ||
                   gearbox.has("housing.dof_map");
  if (any) {
    for (const char* k : {"stiffness_matrix", "mass_matrix", "dof_map"}) {
      const std::string key = std::string("housing.") + k;
      if (!gearbox.has(key)) {
        throw InputError(key, "(absent)",
                         "a file: stiffness_matrix, mass_matrix and dof_map come together");
      }
    }
    source.stiffness_matrix =
        relativeToGearbox(gearbox, gearbox.string("housing.stiffness_matrix"));
    source.mass_matrix = relativeToGearbox(gearbox, gearbox.string("housing.mass_matrix"));
    source.dof_map = relativeToGearbox(gearbox, gearbox.string("housing.dof_map"));
    if (!source.fixed_mounts.empty()) {
      throw InputError("housing.mounts." + source.fixed_mounts.front(), "(fixed)",
                       "an elastic mount (stiffness) with matrices from another tool: fix DOFs "
                       "there (leave their rows out of the matrices)");
    }
  }
  return source;
}

std::string attachHousing(const Config& gearbox, GearTrainSpec& spec, double default_cutoff_hz,
                          double memory_limit) {
  if (!hasHousing(gearbox)) return "";
  auto housing = std::make_shared<TrainHousingSpec>();
  HousingSource source = housingSourceFromConfig(gearbox, spec, default_cutoff_hz, housing->links);
  source.memory_limit_bytes = memory_limit;
  LoadedHousing loaded = loadHousing(source);
  housing->reduced = std::move(loaded.housing);
  housing->stiffness_proportional_damping = gearbox.real("housing.stiffness_proportional_damping");
  housing->source = source.deck;
  housing->cache_file = loaded.cache_file;
  housing->from_cache = loaded.from_cache;
  housing->assembly_s = loaded.assembly_s;
  const Eigen::Index rv = housing->reduced.residual_vectors;
  const Eigen::VectorXd f =
      housing->reduced.mode_frequencies_hz.head(housing->reduced.mode_frequencies_hz.size() - rv);
  std::string line = fmt::format(
      "housing {}: {} seats, {} fixed-interface modes{}{}{}, {}\n", source.deck,
      housing->reduced.seats.size(), f.size(),
      source.reduction.modes < 0 ? fmt::format(" below {:.6g} Hz", source.reduction.cutoff_hz)
                                 : std::string(),
      f.size() > 0 ? fmt::format(" (first {:.6g} Hz)", f(0)) : std::string(),
      rv > 0 ? fmt::format(" + {} residual vectors", rv) : std::string(),
      loaded.from_cache ? "from " + loaded.cache_file
                        : (loaded.cache_file.empty() ? std::string("reduced (not cached)")
                                                     : "reduced, cached in " + loaded.cache_file));
  spec.housing = std::move(housing);
  return line;
}

}  // namespace geardyn::config
