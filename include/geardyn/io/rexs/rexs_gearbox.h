#pragma once
/// \file
/// REXS → gearbox description, and back. The import maps a REXS model (io/rexs) onto the
/// gearbox file's keys (gearbox_config.h) and writes it as TOML text with a comment naming the
/// REXS component id of every value; analyses read that text through the same
/// gearTrainFromConfig as a hand-written file, so both give identical results by construction.
/// What is mapped, what is not and the defaults: docs/guide/rexs.md.

#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "geardyn/io/rexs/rexs_document.h"

namespace geardyn::io::rexs {

struct RexsImportOptions {
  /// Load case (REXS id) that becomes the operating point; absent: the first of the spectrum.
  std::optional<int> load_case;
  /// Radial stiffness [N/m] written for bearings that give none (catalogue and concept
  /// bearings); absent: kRexsDefaultBearingStiffness. A warning names every such bearing.
  std::optional<double> bearing_stiffness;
  /// The gearbox kinematics, for a torque given on another shaft than the input: the speed of
  /// `shaft` over the input shaft's speed [-] in the gearbox that the TOML text describes
  /// (`source` names the REXS file in messages); InputError when it cannot be known.
  /// config::importRexsGearbox supplies it from the gearbox model; empty: not known, and such a
  /// torque is written as 0 with a warning.
  std::function<double(const std::string& gearbox_toml, const std::string& source,
                       const std::string& shaft)>
      speed_ratio;
};

/// Radial stiffness [N/m] of a bearing whose REXS component gives none: the order of a
/// medium-size rolling bearing under operating load (10⁸–10⁹ N/m for 25–100 mm bores, e.g.
/// Harris & Kotzalas, Rolling Bearing Analysis, 5th ed., 2007, ch. 4); to be replaced by the
/// bearing's value (geardyn import --bearing-stiffness, or edit the file).
inline constexpr double kRexsDefaultBearingStiffness = 1e9;

/// Supports stiffer than this many times the stiffest mesh (REXS tools write 1e20 N/m for
/// "rigid") are written at it: in series with the mesh such a support softens it by < 1 %, and
/// the modal problem keeps its conditioning.
inline constexpr double kRexsRigidToMeshRatio = 100.0;

/// One load case of the spectrum, as the operating point it becomes.
struct RexsLoadCaseSummary {
  int id = 0;
  double speed_rpm = 0.0;      ///< of the input shaft
  double torque = 0.0;         ///< on the input shaft [N m]
  double time_fraction = 0.0;  ///< operating time fraction [-] (0 when not given)
};

struct RexsImport {
  std::string toml;  ///< the gearbox description
  std::vector<std::string> warnings;
  std::vector<RexsLoadCaseSummary> load_cases;
  int load_case = 0;  ///< the id written as the operating point (0: no load spectrum)
  /// What the REXS model holds (components of each kind, as REXS counts them).
  int rexs_shafts = 0, rexs_gears = 0, rexs_stages = 0, rexs_planetary_stages = 0,
      rexs_bearings = 0, rexs_couplings = 0;
};

/// Maps a REXS document onto a gearbox description (the import with the gearbox kinematics is
/// config::importRexsGearbox, config/rexs_gearbox_config.h) (InputError naming the component id,
/// type and attribute for what cannot be understood).
RexsImport importRexsGearbox(const io::rexs::Document& document,
                             const RexsImportOptions& options = {});

/// Reads a .rexs/.rexsj/.rexsz file and maps it.
RexsImport importRexsFile(const std::filesystem::path& file, const RexsImportOptions& options = {});

/// The gearbox description (a validated gearbox configuration's resolved keys,
/// config::Config::resolved()) as REXS JSON, version
/// kRexsExportVersion: shafts with sections and materials, gears with flanks, parallel stages,
/// planetary stages with their planets, bearings, couplings and the operating point as one
/// load case. Importing it gives the same description. What REXS cannot hold (damping, mesh
/// models, transmission errors, anisotropic bearings, extra masses of shafts) is listed in
/// `warnings`.
std::string exportRexsJson(const nlohmann::ordered_json& gearbox,
                           std::vector<std::string>& warnings);

/// The REXS version export writes: 2.0.0, the current one (its file structure is that of 1.x;
/// units as in its schema: MPa, kg / dm^3, N mm / rad, deg).
inline constexpr const char* kRexsExportVersion = "2.0.0";

}  // namespace geardyn::io::rexs
