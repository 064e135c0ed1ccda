#pragma once
/// \file
/// A gear train built once and analysed many times (issue 39; Python's geardyn.GearTrain): the
/// validated inputs of `train` (its analysis options and the gearbox, inline, TOML or REXS),
/// the assembled GearTrainModel and, with rolling bearings from their geometry, its
/// linearisation at the static deflection, kept between calls. No text and no file between an
/// analysis and the next.
///
/// set(key, value) changes a key of either file as `--set` does and reassembles only what
/// depends on it:
/// - `meshes.<m>.stiffness_value` and `planetary.<s>.sun_planet.stiffness_value` /
///   `.ring_planet.stiffness_value` of a constant mesh stiffness, `operating_point.speed_rpm`
///   and `operating_point.torque`: the value is range-checked against the gearbox schema, set
///   in the built description (GearTrainSpec) and GearTrainModel::withParameters reassembles
///   only what depends on it (rank-one updates of Σ k̄ v vᵀ and C, F₀; the train built anew
///   from the description when a mesh changes flank) — the configuration is not read again;
/// - a key of the analysis options (`modal.speed_rpm`, `forced.points`, …): the options are
///   read again, the model is kept;
/// - any other key: the inputs are read again with every key set so far and the train is
///   built anew.
/// The linearisation at the static deflection follows every change of the model.
/// modes(), staticDeflection() and forced() call the solvers as `geardyn train` does, so their
/// numbers are the CLI's.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geardyn/analysis/analyses.h"
#include "geardyn/config/config_schema.h"
#include "geardyn/solvers/train_modal.h"
#include "geardyn/solvers/train_response.h"
#include "geardyn/system/gear_train_model.h"

namespace geardyn::analysis {

/// As trainAnalysis on a train already built from inputs.gearbox (GearTrainSession: one model,
/// many analyses), running `analyses` (names of analysis.run); `spec_warnings`: those of
/// config::gearTrainFromConfig, reported with the model's.
AnalysisResult trainAnalysis(const TrainInputs& inputs, const GearTrainModel& model,
                             const std::vector<std::string>& analyses,
                             const AnalysisContext& context,
                             const std::vector<std::string>& spec_warnings = {});

class GearTrainSession {
 public:
  /// An analysis file (its gearbox inline or named by gearbox.file: TOML or REXS), or the
  /// text of one (`source` names it in messages, `base_dir` resolves gearbox.file), with
  /// `--set` overrides. InputError as `geardyn train` (naming the key).
  static GearTrainSession fromFile(const std::filesystem::path& file,
                                   std::vector<std::string> overrides = {});
  static GearTrainSession fromText(std::string text, std::string source,
                                   std::filesystem::path base_dir,
                                   std::vector<std::string> overrides = {});

  /// What set() reassembled.
  enum class Change { kNothing, kParameters, kModel };
  /// Sets `key` (dotted, as `--set`) to `value` (TOML syntax; a bare word is a string).
  Change set(const std::string& key, const std::string& value);

  const GearTrainModel& model() const noexcept { return *model_; }
  /// The model the linear analyses use: linearised at the static deflection when it has
  /// rolling bearings from their geometry, else model().
  const GearTrainModel& linearModel();
  /// The inputs with every key set so far (read again after set()'s fast changes).
  const TrainInputs& inputs();
  /// The `modal` analysis's speed [rad/s] and modes (its options: modal.speed_rpm, modes).
  double modalSpeed();
  std::vector<TrainMode> modes();
  /// The `static` analysis at the operating speed.
  TrainStaticResult staticDeflection() const;
  /// The analyses of `analyses` (empty: analysis.run) on the built model: the AnalysisResult
  /// of `geardyn train` (tables, summary, report).
  AnalysisResult analyze(const std::vector<std::string>& analyses, const AnalysisContext& context);
  /// The `forced` analysis at the input speeds `speeds` [rad/s] (forced.* for the rest):
  /// its tables forced_response.csv, forced_mesh_orders.csv (and forced_tones.csv).
  AnalysisResult forced(const std::vector<double>& speeds, const AnalysisContext& context);

 private:
  GearTrainSession(std::string text, std::string source, std::filesystem::path base_dir,
                   std::vector<std::string> overrides);
  /// Reads the inputs again with overrides_; `rebuild`: the model too.
  void reload(bool rebuild);
  /// The fast changes of set(): false when `key` is not one of them.
  bool setParameter(const std::string& key, const std::string& value);

  std::string text_, source_;
  std::filesystem::path base_dir_;
  std::vector<std::string> overrides_;
  std::shared_ptr<const config::ConfigSchema> schema_;  // trainSchema(true): ranges of keys
  std::optional<TrainInputs> inputs_;
  bool inputs_stale_ = false;  // overrides_ holds fast changes inputs_ has not read
  std::optional<GearTrainModel> model_;
  std::optional<GearTrainModel> linear_;  // linearised model (rolling bearings) or empty
  bool linear_stale_ = true;
  // [modal]'s options and speed (modal.speed_rpm [rad/s] when given), read once per reload:
  // they are analysis keys, which only reload() changes (modes() takes microseconds).
  TrainModalOptions modal_options_;
  std::optional<double> modal_speed_;
};

}  // namespace geardyn::analysis
