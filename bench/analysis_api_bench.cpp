/// The C++ side of bench/python_api_bench.py: the library call that `geardyn.run(command,
/// file)` makes from Python — the schema, loading and validating the file, the analysis —
/// timed in C++ over `repeat` runs after one warm-up: the fastest run (the least disturbed by
/// other processes on a shared machine) and the median, as one JSON line.
///
/// Usage: geardyn_analysis_bench COMMAND FILE REPEAT (COMMAND: any of analysisNames(), train too)

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "geardyn/analysis/analyses.h"
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

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: %s COMMAND FILE REPEAT\n", argv[0]);
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
    // `train` reads its analysis file and the gearbox file it names (one configuration).
    const auto config = command == "train" ? geardyn::analysis::loadAnalysisConfig(command, file)
                                           : geardyn::config::loadConfigFile(file, schema);
    const auto t2 = std::chrono::steady_clock::now();
    const auto result = geardyn::analysis::runAnalysis(command, config, {});
    const auto t3 = std::chrono::steady_clock::now();
    if (i == 0) continue;  // warm-up
    schema_s.push_back(seconds(t0, t1));
    load_s.push_back(seconds(t1, t2));
    analysis_s.push_back(seconds(t2, t3));
    total_s.push_back(seconds(t0, t3));
  }
  std::printf(
      "{\"command\": \"%s\", \"schema_s\": %.9g, \"load_s\": %.9g, \"analysis_s\": %.9g, "
      "\"total_s\": %.9g, \"total_median_s\": %.9g}\n",
      command.c_str(), fastest(schema_s), fastest(load_s), fastest(analysis_s), fastest(total_s),
      median(total_s));
  return 0;
}
