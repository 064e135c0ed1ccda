/// The C++ side of bench/python_api_bench.py: the library call that `geardyn.run(command,
/// file)` makes from Python — the schema, loading and validating the file, the analysis —
/// timed in C++ over `repeat` runs after one warm-up: the fastest run (the least disturbed by
/// other processes on a shared machine) and the median, as one JSON line.
///
/// Usage: geardyn_analysis_bench COMMAND FILE REPEAT [KEY] (COMMAND: any of analysisNames(),
/// train too). For `train` the line also holds, on a GearTrainSession built once from FILE
/// (Python's geardyn.GearTrain), the fastest and median modal analysis of the built model
/// (`session_modes_s`) and, with KEY (a constant mesh's stiffness_value, or the operating
/// speed_rpm or torque), of setting KEY alternately to 1.0 and 1.1 times a value and computing
/// the modes again (`session_set_modes_s`).

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "geardyn/analysis/analyses.h"
#include "geardyn/analysis/gear_train_session.h"
#include "geardyn/config/config.h"
#include "geardyn/config/fe_rotor_config.h"

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

double fastest(const std::vector<double>& v) {
  return *std::min_element(v.begin(), v.end());
}

double seconds(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

/// The GearTrainSession timings of a `train` file (see the file comment), appended to the line.
void sessionTimings(const std::string& file, int repeat, const std::string& key) {
  using Clock = std::chrono::steady_clock;
  auto session = geardyn::analysis::GearTrainSession::fromFile(file);
  const int calls = 50 * repeat;  // a modal analysis of a small train takes microseconds
  std::vector<double> modes_s;
  double checksum = 0.0;
  for (int i = 0; i <= calls; ++i) {
    const auto t0 = Clock::now();
    checksum += session.modes().back().frequency;
    if (i > 0) modes_s.push_back(seconds(t0, Clock::now()));
  }
  std::printf(", \"session_modes_s\": %.9g, \"session_modes_median_s\": %.9g", fastest(modes_s),
              median(modes_s));
  if (key.empty()) return;
  const auto& analysis = session.inputs().gearbox;
  const double value = analysis.real(key);
  std::vector<double> set_s;
  for (int i = 0; i <= calls; ++i) {
    const auto t0 = Clock::now();
    session.set(key, std::to_string(i % 2 ? 1.1 * value : value));
    checksum += session.modes().back().frequency;
    if (i > 0) set_s.push_back(seconds(t0, Clock::now()));
  }
  std::printf(", \"session_set_modes_s\": %.9g, \"session_set_modes_median_s\": %.9g",
              fastest(set_s), median(set_s));
  if (!(checksum > 0.0)) std::fprintf(stderr, "no modes\n");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4 && argc != 5) {
    std::fprintf(stderr, "usage: %s COMMAND FILE REPEAT [KEY]\n", argv[0]);
    return 2;
  }
  const std::string command = argv[1], file = argv[2];
  const int repeat = std::max(1, std::stoi(argv[3]));
  std::vector<double> schema_s, load_s, analysis_s, total_s;
  for (int i = 0; i <= repeat; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    const auto schema = geardyn::analysis::analysisSchema(
        command, geardyn::config::peekConfigString(file, "model.type"));
    const auto t1 = std::chrono::steady_clock::now();
    // `train` reads its analysis file and the gearbox file it names (TrainInputs), as
    // geardyn.run('train', file) does; the others one configuration.
    std::optional<geardyn::analysis::TrainInputs> train;
    std::optional<geardyn::config::Config> config;
    if (command == "train") {
      train = geardyn::analysis::loadTrainInputs(file, {});
    } else {
      config = geardyn::config::loadConfigFile(file, schema);
    }
    const auto t2 = std::chrono::steady_clock::now();
    const auto result = train ? geardyn::analysis::trainAnalysis(*train, {})
                              : geardyn::analysis::runAnalysis(command, *config, {});
    const auto t3 = std::chrono::steady_clock::now();
    if (i == 0) continue;  // warm-up
    schema_s.push_back(seconds(t0, t1));
    load_s.push_back(seconds(t1, t2));
    analysis_s.push_back(seconds(t2, t3));
    total_s.push_back(seconds(t0, t3));
  }
  std::printf(
      "{\"command\": \"%s\", \"schema_s\": %.9g, \"load_s\": %.9g, \"analysis_s\": %.9g, "
      "\"total_s\": %.9g, \"total_median_s\": %.9g",
      command.c_str(), fastest(schema_s), fastest(load_s), fastest(analysis_s), fastest(total_s),
      median(total_s));
  if (command == "train") sessionTimings(file, repeat, argc == 5 ? argv[4] : "");
  std::printf("}\n");
  return 0;
}
