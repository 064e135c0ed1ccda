/// REXS → validated gearbox description (rexs_gearbox_config.h).

#include "geardyn/config/rexs_gearbox_config.h"

#include "geardyn/config/gearbox_config.h"
#include "geardyn/error.h"
#include "geardyn/io/rexs/rexs_reader.h"
#include "geardyn/system/gear_train_model.h"

namespace geardyn::config {
namespace {

/// The speed of `shaft` over the input's in the gearbox the TOML text describes, from the
/// gearbox model's kinematics (InputError when the text does not build).
double gearboxSpeedRatio(const std::string& gearbox_toml, const std::string& source,
                         const std::string& shaft) {
  const Config c = parseConfig(gearbox_toml, source, gearboxSchema());
  std::vector<std::string> ignored;
  const GearTrainModel model(gearTrainFromConfig(c, ignored));
  return model.bodies()[model.bodyIndex(shaft)].speed_ratio;
}

}  // namespace

io::rexs::RexsImport importRexsGearbox(const io::rexs::Document& document,
                                       io::rexs::RexsImportOptions options) {
  if (!options.speed_ratio) options.speed_ratio = gearboxSpeedRatio;
  return io::rexs::importRexsGearbox(document, options);
}

io::rexs::RexsImport importRexsFile(const std::filesystem::path& file,
                                    io::rexs::RexsImportOptions options) {
  if (!options.speed_ratio) options.speed_ratio = gearboxSpeedRatio;
  return io::rexs::importRexsFile(file, options);
}

Config loadGearboxConfig(const std::filesystem::path& file,
                         const std::vector<std::string>& overrides, std::optional<int> load_case,
                         std::vector<std::string>& warnings) {
  if (!io::rexs::isRexsPath(file)) {
    if (load_case)
      throw InputError("gearbox.load_case", std::to_string(*load_case),
                       "only with a REXS gearbox file (.rexs, .rexsj, .rexsz); " + file.string() +
                           " is a gearbox TOML file");
    return loadConfigFile(file, gearboxSchema(), overrides);
  }
  io::rexs::RexsImportOptions options;
  options.load_case = load_case;
  io::rexs::RexsImport imported;
  try {
    imported = config::importRexsFile(file, options);
  } catch (const InputError& e) {
    // The load case is the analysis file's key (and a sweep's parameter): named as such.
    if (e.key() != "load_case") throw;
    throw InputError("gearbox.load_case", e.value(), e.allowed());
  }
  warnings.insert(warnings.end(), imported.warnings.begin(), imported.warnings.end());
  return parseConfig(imported.toml, file.string(), gearboxSchema(), overrides);
}

}  // namespace geardyn::config
