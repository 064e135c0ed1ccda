/// `geardyn sweep CONFIG [--resume] [--threads N]`: any analysis command over a grid or a random
/// sample of its configuration keys, on a thread pool or across MPI ranks (`mpirun -n N geardyn
/// sweep CONFIG`), resumable after a kill, gathered into sweep.h5 and sweep.csv.

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <thread>

#include "analysis_command.h"
#include "command.h"
#include "geardyn/analysis/run_estimates.h"
#include "geardyn/analysis/sweep_results.h"
#include "geardyn/config/config.h"
#include "geardyn/config/did_you_mean.h"
#include "geardyn/config/renamed_keys.h"
#include "geardyn/config/sweep_config.h"
#include "geardyn/error.h"
#include "geardyn/io/result_writer.h"
#include "plotting.h"
#include "progress.h"
#include "sweep_runner.h"

namespace geardyn::cli {
using analysis::estimateCommand;
using analysis::formatDuration;
namespace fs = std::filesystem;
namespace {

const Command& findCommand(const std::vector<Command>& commands, const std::string& name) {
  std::vector<std::string> names;
  for (const auto& c : commands) {
    if (c.name == name && c.name != "sweep") return c;
    if (c.name != "sweep") names.push_back(c.name);
  }
  throw InputError("study.command", "\"" + name + "\"",
                   fmt::format("an analysis command: {}", fmt::join(names, ", ")));
}

/// The base file of a study as its command reads it: the schema parameter keys are looked up
/// in, the file loaded with overrides (InputError naming a bad key) and one case's run. A
/// command that reads its file itself (`train`: an analysis file and its gearbox) brings its
/// own loader; the others are validated against their schema.
struct BaseFile {
  BaseFile(const Command& command_, const fs::path& file_)
      : command(command_), file(file_), schema(commandSchema(command_, file_)) {}

  config::Config load(const std::vector<std::string>& overrides) const {
    return command.load_file ? command.load_file(file, overrides)
                             : loadCommandFile(command, file, schema, overrides);
  }
  int run(const CommandOptions& options) const {
    return command.run_file ? command.run_file(options)
                            : command.run(load(options.overrides), options);
  }

  const Command& command;
  fs::path file;
  config::ConfigSchema schema;
};

/// Runs one case in-process into its own folder and reads its summary.
analysis::SweepCaseRecord runCase(const BaseFile& base, const config::SweepDefinition& study,
                                  long long index, const fs::path& cases_dir) {
  const StudyCase c = study.caseAt(index);
  analysis::SweepCaseRecord r;
  r.index = index;
  r.values = c.values;
  r.seed = c.seed;
  r.outputs.assign(study.outputs.size(), std::numeric_limits<double>::quiet_NaN());
  CommandOptions o;
  o.config_file = study.base;
  o.out_dir = cases_dir / fmt::format("{:06d}", index);
  o.overrides = study.overridesOf(c);
  o.overrides.push_back("output.plots=false");
  o.threads = 1;  // the sweep owns the cores
  o.quiet = true;
  try {
    const int code = base.run(o);
    const auto summary = nlohmann::json::parse(std::ifstream(o.out_dir / "summary.json"));
    // Success is the command's exit code 0; otherwise its own status ("max_periods", …).
    const std::string status = summary.value("status", std::string("failed"));
    r.status = code == kExitOk ? "ok" : (status == "ok" ? "failed" : status);
    std::vector<std::string> missing;
    for (std::size_t k = 0; k < study.outputs.size(); ++k) {
      bool ok = false;
      r.outputs[k] = analysis::outputValue(summary["results"], study.outputs[k].pointer, &ok);
      if (!ok) missing.push_back(study.outputs[k].pointer);
    }
    if (!missing.empty()) {
      if (r.status == "ok") r.status = "missing_output";
      std::vector<std::string> keys;
      for (const auto& [key, value] : summary["results"].items()) keys.push_back("/" + key);
      const std::string first = "/" + missing.front().substr(1, missing.front().find('/', 1) - 1);
      const auto match = config::closestMatch(first, keys);
      r.message = fmt::format("no number at {} in results{}; the results of `{}` have {}",
                              fmt::join(missing, ", "),
                              match ? fmt::format(" (did you mean {}?)", *match) : "",
                              study.command, fmt::join(keys, ", "));
    }
  } catch (const InputError& e) {
    r.status = "bad_input";
    r.message = e.what();
  } catch (const std::exception& e) {
    r.status = "error";
    r.message = e.what();
  }
  if (!study.keep_case_results) {
    std::error_code ec;
    fs::remove_all(o.out_dir, ec);
  }
  return r;
}

nlohmann::ordered_json outputStatistics(const config::SweepDefinition& study,
                                        const std::vector<analysis::SweepCaseRecord>& records) {
  nlohmann::ordered_json stats = nlohmann::ordered_json::object();
  for (std::size_t k = 0; k < study.outputs.size(); ++k) {
    // Two passes over the data shifted by its first value (Chan, Golub & LeVeque 1983): the
    // mean of the deviations, then their corrected sum of squares. No cancellation of
    // sum(x²) − n mean², and a constant column has mean x and std 0 exactly.
    const auto usable = [&](const analysis::SweepCaseRecord& r) {
      return r.status == "ok" && std::isfinite(r.outputs[k]);
    };
    double shift = NAN, sum = 0, lo = INFINITY, hi = -INFINITY;
    long long n = 0;
    for (const auto& r : records) {
      if (!usable(r)) continue;
      const double x = r.outputs[k];
      if (n == 0) shift = x;
      sum += x - shift, lo = std::min(lo, x), hi = std::max(hi, x), ++n;
    }
    if (n == 0) {
      stats[study.outputs[k].name] = {{"count", 0}};
      continue;
    }
    const double offset = sum / n;
    double squares = 0;
    for (const auto& r : records)
      if (usable(r)) squares += (r.outputs[k] - shift - offset) * (r.outputs[k] - shift - offset);
    const double mean = shift + offset;
    stats[study.outputs[k].name] = {{"count", n},
                                    {"mean", mean},
                                    {"std", n > 1 ? std::sqrt(squares / (n - 1)) : 0.0},
                                    {"min", lo},
                                    {"max", hi}};
  }
  return stats;
}

/// A key inside a named table ("meshes.stage1.damping_ratio") must name a table the base
/// configuration has: a --set would otherwise start a new, incomplete one, reported under
/// another key.
void checkNamedTable(const std::string& key, const std::string& where,
                     const config::ConfigSchema& schema, const config::Config& base) {
  for (const std::string& collection : schema.collections()) {
    const auto dot = key.find('.', collection.size() + 1);
    if (key.rfind(collection + ".", 0) != 0 || dot == std::string::npos) continue;
    const std::string name = key.substr(collection.size() + 1, dot - collection.size() - 1);
    const auto tables = base.resolved().find(collection);
    std::vector<std::string> names, keys;
    if (tables != base.resolved().end() && tables->is_object()) {
      for (const auto& [n, value] : tables->items()) {
        if (n == name) return;
        names.push_back(n);
        keys.push_back(collection + "." + n + key.substr(dot));
      }
    }
    const auto match = config::closestMatch(key, keys);
    throw InputError(
        where, "",
        fmt::format("a key of a table of the base configuration: it has no [{}.{}] "
                    "(its [{}.*] are: {}){}",
                    collection, name, collection,
                    names.empty() ? "(none)" : fmt::format("{}", fmt::join(names, ", ")),
                    match ? fmt::format("; did you mean '{}'?", *match) : ""));
  }
}

/// Every value a parameter lists (or the bounds of its range) loaded into the base
/// configuration: a bad value is an error before any case runs, named by its place in the study.
void checkStudyValues(const config::SweepDefinition& study, const BaseFile& base,
                      const config::Config& base_config, const fs::path& file) {
  const config::ConfigSchema& schema = base.schema;
  for (const auto& p : study.parameters) {
    const std::string where = "study.parameters." + p.key;
    if (!schema.findKey(p.key) && !schema.aliasTarget(p.key)) {  // an old key: converted
      base.load({p.key + "=0"});                                 // throws with did-you-mean
      throw InputError(where, "", "a key of the base configuration");
    }
    checkNamedTable(p.key, where, schema, base_config);
    std::vector<std::pair<std::string, nlohmann::json>> probes;
    if (p.linspace_num > 0) {
      probes = {{where + ".min", p.valueAt(0)}, {where + ".max", p.valueAt(p.linspace_num - 1)}};
    } else if (p.distribution == StudyDistribution::kValues) {
      for (std::size_t i = 0; i < p.values.size(); ++i)
        probes.push_back({fmt::format("{}[{}]", where, i), p.values[i]});
    } else if (p.distribution == StudyDistribution::kNormal) {
      probes = {{where + ".mean", p.mean}};
    } else {
      probes = {{where + ".min", p.min}, {where + ".max", p.max}};
    }
    for (const auto& [label, value] : probes) {
      std::vector<std::string> overrides = study.set;
      overrides.push_back(p.key + "=" + config::tomlLiteral(value));
      try {
        base.load(overrides);
      } catch (const InputError& e) {
        if (e.key() != p.key) throw;
        std::string why = e.allowed();
        const auto at = why.rfind("; --set)");
        if (at != std::string::npos) why.replace(at, 8, "; " + file.string() + ")");
        throw InputError(label, config::tomlLiteral(value), why);
      }
    }
  }
}

/// A --set of a swept key would be overridden by every case: refused, with the way to do it.
void rejectSweptOverrides(const config::SweepDefinition& study, const CommandOptions& options) {
  for (const auto& assignment : options.overrides) {
    const std::string key = assignment.substr(0, assignment.find('='));
    for (const auto& p : study.parameters) {
      if (p.key != key) continue;
      throw InputError("--set", assignment,
                       fmt::format("not a swept key: {} is set by study.parameters in every case; "
                                   "change the parameter itself, e.g. --set "
                                   "'study.parameters.\"{}\"=[...]'",
                                   key, key));
    }
  }
}

/// The journal of an interrupted sweep (finished cases, no summary written after them) is not
/// discarded silently: --resume continues it, --overwrite discards it. A completed sweep's
/// results are replaced like any command's (its summary.json is newer than its journal).
void refuseToDiscardJournal(const fs::path& journal, const CommandOptions& options) {
  std::error_code ec;
  if (options.resume || options.overwrite || !fs::exists(journal, ec)) return;
  const fs::path summary = journal.parent_path() / "summary.json";
  if (fs::exists(summary, ec) &&
      fs::last_write_time(summary, ec) >= fs::last_write_time(journal, ec))
    return;
  std::ifstream in(journal);
  long long lines = 0;
  for (std::string line; std::getline(in, line);) lines += !line.empty();
  if (lines <= 1) return;  // only the header: nothing finished
  throw InputError("--out", journal.parent_path().string(),
                   fmt::format("a folder without an interrupted sweep: its journal holds {} "
                               "finished case(s) of a sweep that did not complete; pass --resume "
                               "to continue it or --overwrite to discard it and start again",
                               lines - 1));
}

/// Memory of the gathered records and of the running cases, and the time of all cases.
RunEstimate estimateSweep(const config::SweepDefinition& study, const config::Config& base,
                          int workers) {
  const double cases = static_cast<double>(study.caseCount());
  const double p = static_cast<double>(study.parameters.size());
  const double o = static_cast<double>(study.outputs.size());
  // Per case: its record (~130 B + values + outputs + status and message), the HDF5 and CSV
  // copies made when gathering (one 40 B cell per column), the pending index.
  const double per_case = 450.0 + 100.0 * p + 60.0 * o;
  const RunEstimate one = estimateCommand(study.command, base);
  RunEstimate e;
  e.key = study.design == StudyDesign::kRandom ? "study.samples" : "study.parameters";
  e.value = fmt::format("{:g} cases", cases);
  e.bytes = cases * per_case + workers * one.bytes;
  e.seconds = cases * one.seconds / std::max(1, workers);
  e.basis = fmt::format("{:g} cases × {:g} B gathered{}", cases, per_case,
                        one.seconds > 0 ? fmt::format(", {} each on {} worker(s)",
                                                      formatDuration(one.seconds), workers)
                                        : "");
  return e;
}

/// The study's keys that the base command renamed (seed_key, swept parameters): warned once and
/// rewritten, except a swept key whose unit changed, which each case reads and converts.
void applyRenamedStudyKeys(config::SweepDefinition& study,
                           const config::ConfigSchema& base_schema) {
  for (std::string* key : {&study.seed_key}) {
    if (const std::string* renamed = base_schema.aliasTarget(*key)) {
      warn(fmt::format("study.seed_key: {} is deprecated: write {}", *key, *renamed));
      *key = *renamed;
    }
  }
  for (auto& p : study.parameters) {
    const std::string* renamed = base_schema.aliasTarget(p.key);
    if (!renamed) continue;
    if (const config::ValueConversion* c = config::renameConversion(p.key, *renamed)) {
      // Its values are in the old unit: each case reads the old key and converts it (the
      // cases' own notes are not shown, so this is the one warning of the run).
      warn(
          fmt::format("study.parameters.{} is deprecated: write {} (value {}); the cases read "
                      "these values converted",
                      p.key, *renamed, c->text));
      continue;
    }
    warn(fmt::format("study.parameters.{} is deprecated: write {}", p.key, *renamed));
    p.key = *renamed;
  }
}

/// sweep.h5, sweep.csv, the summary (its status, warnings per failed case, output statistics)
/// and the plots of a finished sweep; the exit code.
int writeSweepResults(const CommandOptions& options, const config::SweepDefinition& study,
                      const config::Config& base,
                      const std::vector<analysis::SweepCaseRecord>& records, long long resumed,
                      long long computed, const std::string& workers, double elapsed,
                      const fs::path& folder, const fs::path& cases_dir) {
  const long long total = study.caseCount();
  std::error_code ec;
  if (fs::is_empty(cases_dir, ec)) fs::remove(cases_dir, ec);  // nothing kept
  io::ResultWriter writer(folder);
  // The journal is not listed among the summary's files: a later run's ResultWriter removes
  // listed files, and the journal must survive for --resume.
  analysis::writeSweepHdf5(writer.pathFor("sweep.h5"), study, records, base.resolved().dump());
  writer.recordFile("sweep.h5");
  writer.writeCsv("sweep.csv", analysis::sweepTable(study, records));
  long long failed = 0;
  std::map<std::string, long long> by_status;
  for (const auto& r : records) {
    ++by_status[r.status];
    failed += r.status != "ok";
  }
  io::RunSummary summary;
  summary.command = "sweep";
  summary.config_source = options.config_file.string();
  summary.config = {{"study", study.resolved}, {"base_config", base.resolved()}};
  summary.seed = study.seed;
  summary.status = failed == 0 ? "ok" : "cases_failed";
  summary.wall_time_s = elapsed;
  summary.numerical_failure = failed > 0;  // exit code 1
  for (const auto& r : records) {
    if (r.status != "ok" && summary.warnings.size() < 20)
      summary.warnings.push_back(fmt::format("case {}: {}: {}", r.index, r.status, r.message));
  }
  summary.results = {{"cases", total},
                     {"by_status", by_status},
                     {"resumed", resumed},
                     {"computed", computed},
                     {"workers", workers},
                     {"wall_time_s", elapsed},
                     {"journal", "sweep_journal.jsonl"},
                     {"outputs", outputStatistics(study, records)}};
  auto path = writer.writeSummary(summary);
  if (study.plots) {
    for (const auto& file : drawPlots("sweep", writer.folder())) writer.recordFile(file);
    path = writer.writeSummary(summary);
  }
  if (failed > 0) {
    std::cerr << fmt::format("geardyn sweep: {} of {} cases did not succeed (see sweep.csv)\n",
                             failed, total);
  }
  report(options,
         fmt::format("sweep of `{}`: {} cases ({} computed, {} resumed, {} failed) in "
                     "{:.3g} s\nresults: {}\n",
                     study.command, total, computed, resumed, failed, elapsed, path.string()));
  return failed == 0 ? kExitOk : kExitNumericalFailure;
}

}  // namespace

int runSweep(const CommandOptions& options) {
  std::unique_ptr<MpiWorld> mpi;
  if (launchedByMpi()) mpi = std::make_unique<MpiWorld>();
  const bool root = !mpi || mpi->rank() == 0;
  config::SweepDefinition study =
      config::loadSweepDefinition(options.config_file, options.overrides);
  const auto commands = allCommands();
  const Command& command = findCommand(commands, study.command);
  // The base configuration with the study's fixed overrides must load: a typo in a key fails here,
  // before any case runs (each case's own values are checked by the case).
  const BaseFile base_file(command, study.base);
  const config::ConfigSchema& base_schema = base_file.schema;
  const config::Config base = base_file.load(study.set);
  for (const auto& note : base.notes()) warn(note);
  applyRenamedStudyKeys(study, base_schema);
  rejectSweptOverrides(study, options);
  checkStudyValues(study, base_file, base, options.config_file);
  if (!study.seed_key.empty() && !base_schema.findKey(study.seed_key))
    throw InputError("study.seed_key", "\"" + study.seed_key + "\"",
                     "a key of the base configuration");

  const fs::path folder = options.resultFolder();
  const fs::path cases_dir = folder / "cases";
  const long long total = study.caseCount();
  int threads = options.threads > 0
                    ? options.threads
                    : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  if (mpi && options.threads == 0) threads = 1;  // one worker per rank unless told otherwise

  std::vector<analysis::SweepCaseRecord> records;
  std::vector<bool> have;
  std::vector<long long> pending;
  std::unique_ptr<analysis::SweepJournal> journal;
  long long resumed = 0;
  std::exception_ptr setup_error;
  if (root) {
    try {
      // Before anything of the size of the study is allocated (the cases themselves are
      // generated one at a time, when they run).
      checkRunEstimate(estimateSweep(study, base, threads * (mpi ? mpi->size() : 1)), options,
                       "sweep");
      refuseToDiscardJournal(folder / "sweep_journal.jsonl", options);
      fs::create_directories(cases_dir);
      // A command that reads other files than its base (train's gearbox) has them in the
      // fingerprint too: editing the gearbox file invalidates the journal.
      journal = std::make_unique<analysis::SweepJournal>(
          folder / "sweep_journal.jsonl",
          study.fingerprint(command.load_file ? base.resolved().dump() : ""), options.resume);
    } catch (...) {
      setup_error = std::current_exception();
    }
  }
  // Every rank stops together when rank 0 cannot start (e.g. nothing to resume).
  if (mpi && !mpi->agree(!setup_error) && !setup_error)
    throw InputError("sweep", "", "a sweep rank 0 can start (see its message)");
  if (setup_error) std::rethrow_exception(setup_error);
  if (root) {
    records.resize(static_cast<std::size_t>(total));
    have.assign(static_cast<std::size_t>(total), false);
    for (const auto& r : journal->previous()) {
      if (r.index < 0 || r.index >= total || have[r.index]) continue;
      records[r.index] = r;
      have[r.index] = true;
      ++resumed;
    }
    for (long long i = 0; i < total; ++i)
      if (!have[i]) pending.push_back(i);
  }

  const auto computed = static_cast<long long>(pending.size());
  ProgressReporter progress("sweep", "cases", root && ProgressReporter::enabledFor(options));
  long long finished = resumed, failed_so_far = 0;
  if (root && !options.quiet) {
    std::cerr << fmt::format(
        "sweep: {} cases of `{}` ({}), {} already done, {} to run on {}\n", total, study.command,
        toString(study.design), resumed, pending.size(),
        mpi ? fmt::format("{} MPI ranks", mpi->size()) : fmt::format("{} threads", threads));
  }
  const CaseFunction run_case = [&](long long index) {
    return runCase(base_file, study, index, cases_dir);
  };
  const DoneFunction done = [&](const analysis::SweepCaseRecord& r) {
    journal->append(r);
    records[r.index] = r;
    have[r.index] = true;
    failed_so_far += r.status != "ok";
    progress.update(static_cast<double>(++finished), static_cast<double>(total), failed_so_far);
  };
  // The first case runs alone: outputs that are not in its results are a mistake in the study
  // (exit 2), found before the other cases run.
  std::exception_ptr probe_error;
  if (root && !pending.empty()) {
    try {
      const analysis::SweepCaseRecord first = run_case(pending.front());
      done(first);
      pending.erase(pending.begin());
      if (first.status == "missing_output")
        throw InputError("study.outputs", fmt::format("(case {})", first.index), first.message);
    } catch (...) {
      probe_error = std::current_exception();
    }
  }
  if (mpi && !mpi->agree(!probe_error) && !probe_error)
    throw InputError("study.outputs", "", "pointers into the results (see rank 0)");
  if (probe_error) std::rethrow_exception(probe_error);
  if (mpi) {
    mpi->runCases(pending, threads, run_case, done);
  } else {
    runCasesOnThreads(pending, threads, run_case, done);
  }
  if (!root) return kExitOk;

  return writeSweepResults(
      options, study, base, records, resumed, computed,
      mpi ? fmt::format("{} MPI ranks", mpi->size()) : fmt::format("{} threads", threads),
      progress.elapsed(), folder, cases_dir);
}

}  // namespace geardyn::cli
