/// `geardyn import` and `geardyn export` (rexs_command.h): thin, the library does the mapping.

#include "rexs_command.h"

#include <iostream>

#include "command.h"
#include "geardyn/config/gearbox_config.h"
#include "geardyn/config/rexs_gearbox_config.h"
#include "geardyn/error.h"
#include "geardyn/io/atomic_file.h"
#include "geardyn/io/rexs/rexs_gearbox.h"

namespace geardyn::cli {

RexsCommands::RexsCommands(CLI::App& app) {
  import_ = app.add_subcommand(
      "import",
      "REXS gearbox (.rexs XML, .rexsj JSON, .rexsz zip; versions 1.0-1.7) -> gearbox "
      "description (TOML, every value commented with its REXS component id)");
  import_->add_option("file", import_file_, "REXS file")->required();
  import_->add_option("--out,-o", import_out_, "gearbox file to write (default: FILE stem .toml)");
  import_->add_option("--load-case", load_case_,
                      "REXS id of the load case that becomes the "
                      "operating point (default: the first)");
  import_
      ->add_option("--bearing-stiffness", bearing_stiffness_,
                   "radial stiffness [N/m] of bearings the file gives none (default 1e9)")
      ->check(CLI::PositiveNumber);
  import_->add_flag("--quiet,-q", quiet_, "print nothing but warnings and errors");
  export_ = app.add_subcommand(
      "export", "gearbox description (TOML) -> REXS JSON (.rexsj), readable by geardyn import");
  export_->add_option("file", export_file_, "gearbox file (TOML)")->required();
  export_->add_option("--out,-o", export_out_, "REXS JSON file to write")->required();
  export_->add_flag("--quiet,-q", quiet_, "print nothing but warnings and errors");
}

std::optional<int> RexsCommands::runIfParsed() const {
  if (!import_->parsed() && !export_->parsed()) return std::nullopt;
  const std::string name = import_->parsed() ? "import" : "export";
  try {
    return import_->parsed() ? runImport() : runExport();
  } catch (const InputError& error) {
    std::cerr << "geardyn " << name << ": error: " << error.what() << "\n";
    return kExitBadInput;
  } catch (const IoError& error) {
    std::cerr << "geardyn " << name << ": I/O error: " << error.what() << "\n";
    return kExitIoFailure;
  } catch (const std::exception& error) {
    std::cerr << "geardyn " << name << ": internal error (please report): " << error.what() << "\n";
    return kExitInternalError;
  }
}

int RexsCommands::runImport() const {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(import_file_, ec)) {
    std::cerr << "geardyn import: I/O error: cannot read " << import_file_ << ": no such file\n";
    return kExitIoFailure;
  }
  io::rexs::RexsImportOptions options;
  options.load_case = load_case_;
  options.bearing_stiffness = bearing_stiffness_;
  const io::rexs::RexsImport imported = config::importRexsFile(import_file_, options);
  // The text must read back as a gearbox file (it is what analyses will read).
  std::vector<std::string> model_warnings;
  const config::Config config =
      config::parseConfig(imported.toml, import_file_.string(), config::gearboxSchema());
  config::gearTrainFromConfig(config, model_warnings);
  const std::filesystem::path out =
      import_out_.empty() ? std::filesystem::path(import_file_.stem().string() + ".toml")
                          : import_out_;
  io::writeFileAtomic(out, imported.toml);
  std::vector<std::string> all = imported.warnings;
  all.insert(all.end(), model_warnings.begin(), model_warnings.end());
  warnAll(all, quiet_);
  if (!quiet_) {
    std::cout << "imported " << import_file_.filename().string() << ": "
              << config.names("shafts").size() << " shafts, " << config.names("gears").size()
              << " gears, " << config.names("meshes").size() << " meshes, "
              << config.names("planetary").size() << " planetary stages, "
              << config.names("bearings").size() << " bearings, "
              << config.names("couplings").size() << " couplings; " << imported.load_cases.size()
              << " load case(s)\n"
              << "gearbox file: " << out.string() << "\n";
  }
  return kExitOk;
}

int RexsCommands::runExport() const {
  const config::Config config = config::loadConfigFile(export_file_, config::gearboxSchema());
  std::vector<std::string> warnings;
  config::gearTrainFromConfig(config, warnings);  // refuse what would not build
  warnings.clear();
  const std::string json = io::rexs::exportRexsJson(config.resolved(), warnings);
  io::writeFileAtomic(export_out_, json);
  warnAll(warnings, quiet_);
  if (!quiet_)
    std::cout << "REXS " << io::rexs::kRexsExportVersion << " JSON: " << export_out_.string()
              << "\n";
  return kExitOk;
}

}  // namespace geardyn::cli
