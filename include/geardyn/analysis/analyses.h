#pragma once
/// \file
/// Every analysis of geardyn as a library call: a validated configuration in, an
/// AnalysisResult out (summary, tables, report, status). The CLI commands (apps/geardyn) and
/// Python (`geardyn.run`) are thin layers over these functions. Each function throws InputError
/// for bad input and returns numerical failure as a status (RunSummary::numerical_failure).

#include <filesystem>
#include <string>
#include <vector>

#include "geardyn/analysis/analysis_result.h"
#include "geardyn/config/config.h"
#include "geardyn/config/config_schema.h"

namespace geardyn::analysis {

AnalysisResult geometryAnalysis(const config::Config& config, const AnalysisContext& context);
AnalysisResult stiffnessAnalysis(const config::Config& config, const AnalysisContext& context);
AnalysisResult simulateAnalysis(const config::Config& config, const AnalysisContext& context);
AnalysisResult hbmAnalysis(const config::Config& config, const AnalysisContext& context);
/// `rotor` without [model]: Rao 2023's lateral rotor.
AnalysisResult lateralRotorAnalysis(const config::Config& config, const AnalysisContext& context);
/// `rotor` with [model] type = "fe_geared_rotor": Visnadi 2021's finite-element rotor.
AnalysisResult feRotorAnalysis(const config::Config& config, const AnalysisContext& context);
AnalysisResult statsAnalysis(const config::Config& config, const AnalysisContext& context);
AnalysisResult spectrumAnalysis(const config::Config& config, const AnalysisContext& context);
AnalysisResult identifyAnalysis(const config::Config& config, const AnalysisContext& context);
AnalysisResult ltcaAnalysis(const config::Config& config, const AnalysisContext& context);

/// The inputs of `train`: its analysis configuration and the gearbox description — the
/// analysis file itself when the gearbox is inline, else the file it names (TOML, or REXS
/// imported in memory).
struct TrainInputs {
  config::Config analysis;
  config::Config gearbox;
  std::string analysis_source;        ///< the analysis file
  std::string gearbox_source;         ///< the gearbox file (the analysis file when inline)
  std::vector<std::string> warnings;  ///< of a REXS import

  /// Both configurations as one, as if the gearbox were inline: its sections beside the
  /// analysis's, [gearbox] holding the keys of both (what `sweep` records as its base and
  /// finds the named tables of a parameter key in).
  config::Config combined() const;
};
/// Reads the analysis file and its gearbox; `overrides` ("section.key=value") go to the file
/// that declares the section. Throws InputError naming the key; a key neither file takes is
/// named with a did-you-mean over the keys of both (config::trainSchema(true)).
TrainInputs loadTrainInputs(const std::filesystem::path& file,
                            const std::vector<std::string>& overrides);
/// As loadTrainInputs, from the text of an analysis file (e.g. a dict from Python); `source`
/// names it in messages and `base_dir` resolves a relative gearbox.file.
TrainInputs parseTrainInputs(std::string_view text, const std::string& source,
                             const std::filesystem::path& base_dir,
                             const std::vector<std::string>& overrides);
/// `train`: kinematics and phasing, then the analyses of `analysis.run` (static, modal,
/// Campbell, forced response, time response) on one gearbox (one load case).
AnalysisResult trainAnalysis(const TrainInputs& inputs, const AnalysisContext& context);

/// One analysis command: what `geardyn NAME`, `geardyn.run(NAME, …)`, `sweep` and the
/// benchmarks know of it. The one list of commands is analysisCommands(); the CLI adds only
/// `sweep`, `schema`, `import`, `export` and `report`, which are not analyses.
struct AnalysisCommand {
  const char* name;
  const char* help;     ///< one line (`geardyn --help`, docs/cli.md)
  const char* example;  ///< a run on a file of examples/, shown by `geardyn NAME --help`
  config::ConfigSchema (*schema)();  ///< its own schema (`rotor`: the lateral rotor's)
  /// Further schemas its files may follow (`rotor`: the finite-element rotor; `train`: the
  /// gearbox description).
  std::vector<config::ConfigSchema (*)()> variants;
  /// Its files translate into a gearbox description (`--print-gearbox`,
  /// config/translated_gearbox.h).
  bool has_gearbox = false;
  AnalysisResult (*run)(const config::Config&, const AnalysisContext&);
};
/// Every analysis command, in the CLI's order.
const std::vector<AnalysisCommand>& analysisCommands();

/// The analyses runAnalysis knows, in the CLI's order (the names of analysisCommands()).
const std::vector<std::string>& analysisNames();

/// The schema `name` validates a configuration with (`model_type` = the file's [model] type,
/// which selects the finite-element `rotor` schema), knowing the other analyses' schemas so
/// that their sections in the same file are ignored with a note but still spell-checked
/// (`train`, whose file holds a gearbox or names one: its own analysis and gearbox keys only,
/// as `geardyn train` reads it, and no other analysis takes its sections).
/// Throws InputError for an unknown name, with a did-you-mean.
config::ConfigSchema analysisSchema(const std::string& name, const std::string& model_type = "");

/// The configuration of analysis `name` read from `file` with `overrides` ("section.key=value")
/// as its command reads it: validated with analysisSchema(name, the file's [model] type); for
/// `train`, the analysis file and the gearbox it names as one (TrainInputs::combined), one load
/// case (gearbox.all_load_cases refused). Throws InputError naming a bad key.
config::Config loadAnalysisConfig(const std::string& name, const std::filesystem::path& file,
                                  const std::vector<std::string>& overrides = {});

/// Runs analysis `name` on a configuration validated with analysisSchema(name, ...) (for
/// `train`: with the gearbox inline) or read by loadAnalysisConfig.
AnalysisResult runAnalysis(const std::string& name, const config::Config& config,
                           const AnalysisContext& context);

}  // namespace geardyn::analysis
