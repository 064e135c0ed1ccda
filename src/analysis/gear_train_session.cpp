/// GearTrainSession (gear_train_session.h): a gear train built once, analysed many times, with
/// set() reassembling only what a changed key reaches.

#include "geardyn/analysis/gear_train_session.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>

#include "geardyn/analysis/run_budget.h"
#include "geardyn/config/gearbox_config.h"
#include "geardyn/config/train_analysis.h"
#include "geardyn/error.h"
#include "geardyn/stiffness/api_stiffness.h"
#include "geardyn/units.h"
#include "train_bearings_analysis.h"
#include "train_forced_analysis.h"
#include "train_housing_analysis.h"

namespace geardyn::analysis {
namespace {

/// `value` as a plain number (TOML integer or float syntax without underscores), or nothing.
std::optional<double> plainNumber(const std::string& value) {
  std::string v = value;
  v.erase(0, v.find_first_not_of(" \t"));
  v.erase(v.find_last_not_of(" \t") + 1);
  if (!v.empty() && v[0] == '+') v.erase(0, 1);
  double x = 0.0;
  const auto [end, error] = std::from_chars(v.data(), v.data() + v.size(), x);
  if (error != std::errc() || end != v.data() + v.size() || !std::isfinite(x)) return std::nullopt;
  return x;
}

/// The section of `key` before its first dot.
std::string firstSection(const std::string& key) {
  return key.substr(0, key.find('.'));
}

/// "a.b.c" split at its dots.
std::vector<std::string> parts(const std::string& key) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (std::size_t dot; (dot = key.find('.', start)) != std::string::npos; start = dot + 1) {
    out.push_back(key.substr(start, dot - start));
  }
  out.push_back(key.substr(start));
  return out;
}

/// The InputError the configuration reader gives for a value outside the key's range.
void checkRange(const config::KeySpec& spec, const std::string& key, double value,
                const std::string& shown) {
  const bool below =
      spec.minimum && (spec.minimum_exclusive ? value <= *spec.minimum : value < *spec.minimum);
  const bool above =
      spec.maximum && (spec.maximum_exclusive ? value >= *spec.maximum : value > *spec.maximum);
  if (below || above) {
    throw InputError(key, shown,
                     fmt::format("must be {} ({}; set)", spec.allowedText(), spec.description));
  }
}

}  // namespace

GearTrainSession GearTrainSession::fromFile(const std::filesystem::path& file,
                                            std::vector<std::string> overrides) {
  return GearTrainSession(config::readConfigFile(file), file.string(), file.parent_path(),
                          std::move(overrides));
}

GearTrainSession GearTrainSession::fromText(std::string text, std::string source,
                                            std::filesystem::path base_dir,
                                            std::vector<std::string> overrides) {
  return GearTrainSession(std::move(text), std::move(source), std::move(base_dir),
                          std::move(overrides));
}

GearTrainSession::GearTrainSession(std::string text, std::string source,
                                   std::filesystem::path base_dir,
                                   std::vector<std::string> overrides)
    : text_(std::move(text)),
      source_(std::move(source)),
      base_dir_(std::move(base_dir)),
      overrides_(std::move(overrides)),
      schema_(std::make_shared<config::ConfigSchema>(config::trainSchema(true))) {
  reload(true);
}

void GearTrainSession::reload(bool rebuild) {
  TrainInputs fresh = parseTrainInputs(text_, source_, base_dir_, overrides_);
  if (fresh.analysis.boolean("gearbox.all_load_cases")) {
    throw InputError("gearbox.all_load_cases", "true",
                     "one load case per gear train: set gearbox.load_case");
  }
  if (rebuild) {
    std::vector<std::string> warnings;
    GearTrainSpec spec = config::gearTrainFromConfig(fresh.gearbox, warnings);
    detail::attachTrainHousing(fresh.gearbox, fresh.analysis,
                               fresh.analysis.stringList("analysis.run"), spec);
    model_.emplace(std::move(spec), memoryLimitBytes());
    linear_stale_ = true;
  }
  modal_options_ = config::trainModalOptionsFromConfig(fresh.analysis, "modal");
  modal_speed_.reset();
  if (fresh.analysis.has("modal.speed_rpm"))
    modal_speed_ = config::analysisSpeed(fresh.analysis, "modal", 0.0);
  inputs_ = std::move(fresh);
  inputs_stale_ = false;
}

const TrainInputs& GearTrainSession::inputs() {
  if (inputs_stale_) reload(false);
  return *inputs_;
}

GearTrainSession::Change GearTrainSession::set(const std::string& key, const std::string& value) {
  std::string k = key;
  k.erase(0, k.find_first_not_of(" \t"));
  k.erase(k.find_last_not_of(" \t") + 1);
  // The key's earlier value is replaced (a design loop sets one key many times).
  const auto assign = [&](std::vector<std::string>& list) {
    std::erase_if(list, [&](const std::string& o) {
      std::string name = o.substr(0, o.find('='));
      name.erase(name.find_last_not_of(" \t") + 1);
      name.erase(0, name.find_first_not_of(" \t"));
      return name == k;
    });
    list.push_back(k + "=" + value);
  };
  if (setParameter(k, value)) {
    assign(overrides_);
    inputs_stale_ = true;
    linear_stale_ = true;
    return Change::kParameters;
  }
  const auto& sections = config::gearboxSectionNames();
  const bool analysis_key =
      std::find(sections.begin(), sections.end(), firstSection(k)) == sections.end() ||
      k == "gearbox.load_case" || k == "gearbox.file" || k == "gearbox.all_load_cases";
  // gearbox.file and gearbox.load_case choose the gearbox: the model follows them.
  const bool keeps_model = analysis_key && firstSection(k) != "gearbox";
  std::vector<std::string> before = overrides_;
  assign(overrides_);
  try {
    reload(!keeps_model);
  } catch (...) {
    overrides_ = std::move(before);  // a rejected value leaves the train as it was
    throw;
  }
  return keeps_model ? Change::kNothing : Change::kModel;
}

bool GearTrainSession::setParameter(const std::string& key, const std::string& value) {
  const std::optional<double> number = plainNumber(value);
  if (!number) return false;
  const std::vector<std::string> p = parts(key);
  const bool operating =
      p.size() == 2 && p[0] == "operating_point" && (p[1] == "speed_rpm" || p[1] == "torque");
  const bool mesh = p.size() == 3 && p[0] == "meshes" && p[2] == "stiffness_value";
  const bool stage = p.size() == 4 && p[0] == "planetary" &&
                     (p[2] == "sun_planet" || p[2] == "ring_planet") && p[3] == "stiffness_value";
  if (!operating && !mesh && !stage) return false;
  const config::KeySpec* spec = schema_->findKey(key);
  if (spec == nullptr) return false;  // an unknown name: the reader says which
  GearTrainSpec train = model_->spec();
  const std::string prefix = key.substr(0, key.rfind('.') + 1);
  if (operating) {
    checkRange(*spec, key, *number, value);
    if (p[1] == "speed_rpm") {
      train.operating.input_speed = *number * units::kRpm;
    } else {
      train.operating.input_torque = *number;
    }
  } else {
    std::shared_ptr<const MeshStiffness>* slot = nullptr;
    if (mesh) {
      for (auto& m : train.meshes) {
        if (m.name == p[1]) slot = &m.stiffness;
      }
    } else {
      for (auto& s : train.stages) {
        if (s.name == p[1]) {
          slot = p[2] == "sun_planet" ? &s.sun_planet_stiffness : &s.ring_planet_stiffness;
        }
      }
    }
    if (slot == nullptr || !*slot) return false;  // an unknown name: the reader says which
    // Only a constant stiffness model has its value in this key (inputs_ is current for
    // `stiffness`: only stiffness_value and the operating point change without reading).
    const config::Config& gearbox = inputs_->gearbox;
    if (!gearbox.has(prefix + "stiffness") || gearbox.string(prefix + "stiffness") != "constant") {
      return false;
    }
    checkRange(*spec, key, *number, value);
    *slot = std::make_shared<ConstantMeshStiffness>("constant", *number, (*slot)->contactRatio());
  }
  model_.emplace(model_->withParameters(std::move(train)));
  return true;
}

const GearTrainModel& GearTrainSession::linearModel() {
  if (model_->rollingBearings().empty()) return *model_;
  if (linear_stale_) {
    linear_.emplace(
        model_->linearisedAt(solveTrainStatic(*model_, model_->inputSpeed()).displacement));
    linear_stale_ = false;
  }
  return *linear_;
}

double GearTrainSession::modalSpeed() {
  return modal_speed_ ? *modal_speed_ : model_->inputSpeed();
}

std::vector<TrainMode> GearTrainSession::modes() {
  // The options of [modal] are analysis keys: read by the last reload().
  return trainModes(linearModel(), modalSpeed(), modal_options_);
}

TrainStaticResult GearTrainSession::staticDeflection() const {
  return solveTrainStatic(*model_, model_->inputSpeed());
}

AnalysisResult GearTrainSession::analyze(const std::vector<std::string>& analyses,
                                         const AnalysisContext& context) {
  const TrainInputs& in = inputs();
  return trainAnalysis(
      in, *model_, analyses.empty() ? in.analysis.stringList("analysis.run") : analyses, context);
}

AnalysisResult GearTrainSession::forced(const std::vector<double>& speeds,
                                        const AnalysisContext& context) {
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    if (!std::isfinite(speeds[i])) {
      throw InputError(fmt::format("speeds[{}]", i),
                       fmt::format("{:g} rpm", speeds[i] / units::kRpm), "a finite speed");
    }
  }
  const TrainInputs& in = inputs();
  AnalysisResult result("train", in.analysis, context);
  std::string text;
  detail::runTrainForcedAt(linearModel(), in.analysis, speeds, result, result.summary, text,
                           context);
  result.report = text;
  return result;
}

}  // namespace geardyn::analysis
