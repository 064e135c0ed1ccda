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

#include "command.h"
#include "geardyn/error.h"
#include "geardyn/io/config.h"
#include "geardyn/io/result_writer.h"
#include "geardyn/io/sweep_io.h"
#include "plotting.h"
#include "sweep_runner.h"

namespace geardyn::cli {
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

/// Runs one case in-process into its own folder and reads its summary.
io::SweepCaseRecord runCase(const Command& command, const io::ConfigSchema& schema,
                            const io::SweepDefinition& study, long long index,
                            const fs::path& cases_dir) {
  const StudyCase c = study.caseAt(index);
  io::SweepCaseRecord r;
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
    const auto config = io::loadConfigFile(o.config_file, schema, o.overrides);
    const int code = command.run(config, o);
    const auto summary = nlohmann::json::parse(std::ifstream(o.out_dir / "summary.json"));
    // Success is the command's exit code 0; otherwise its own status ("max_periods", …).
    const std::string status = summary.value("status", std::string("failed"));
    r.status = code == kExitOk ? "ok" : (status == "ok" ? "failed" : status);
    std::vector<std::string> missing;
    for (std::size_t k = 0; k < study.outputs.size(); ++k) {
      bool ok = false;
      r.outputs[k] = io::outputValue(summary["results"], study.outputs[k].pointer, &ok);
      if (!ok) missing.push_back(study.outputs[k].pointer);
    }
    if (!missing.empty()) {
      if (r.status == "ok") r.status = "missing_output";
      r.message = fmt::format("no number at {} in results", fmt::join(missing, ", "));
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

/// Progress on stderr at most once a second: done/total, rate, ETA.
class Progress {
 public:
  Progress(long long total, long long already, bool quiet)
      : total_(total), done_(already), start_done_(already), quiet_(quiet) {}
  void tick(bool failed) {
    ++done_;
    failed_ += failed;
    const auto now = std::chrono::steady_clock::now();
    if (quiet_ || (now - last_ < std::chrono::seconds(1) && done_ < total_)) return;
    last_ = now;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double rate = (done_ - start_done_) / std::max(elapsed, 1e-9);
    const double eta = rate > 0 ? (total_ - done_) / rate : 0.0;
    std::cerr << fmt::format("sweep: {}/{} cases ({} failed), {:.3g} cases/s, ETA {:.0f} s\n",
                             done_, total_, failed_, rate, eta);
  }
  double elapsed() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }
  long long failed() const { return failed_; }

 private:
  long long total_, done_, start_done_, failed_ = 0;
  bool quiet_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now(), last_{};
};

nlohmann::ordered_json outputStatistics(const io::SweepDefinition& study,
                                        const std::vector<io::SweepCaseRecord>& records) {
  nlohmann::ordered_json stats = nlohmann::ordered_json::object();
  for (std::size_t k = 0; k < study.outputs.size(); ++k) {
    double sum = 0, sum2 = 0, lo = INFINITY, hi = -INFINITY;
    long long n = 0;
    for (const auto& r : records) {
      const double x = r.outputs[k];
      if (r.status != "ok" || !std::isfinite(x)) continue;
      sum += x, sum2 += x * x, lo = std::min(lo, x), hi = std::max(hi, x), ++n;
    }
    if (n == 0) {
      stats[study.outputs[k].name] = {{"count", 0}};
      continue;
    }
    const double mean = sum / n;
    stats[study.outputs[k].name] = {
        {"count", n},
        {"mean", mean},
        {"std", n > 1 ? std::sqrt(std::max(0.0, (sum2 - n * mean * mean) / (n - 1))) : 0.0},
        {"min", lo},
        {"max", hi}};
  }
  return stats;
}

}  // namespace

int runSweep(const CommandOptions& options) {
  std::unique_ptr<MpiWorld> mpi;
  if (launchedByMpi()) mpi = std::make_unique<MpiWorld>();
  const bool root = !mpi || mpi->rank() == 0;
  const io::SweepDefinition study = io::loadSweepDefinition(options.config_file, options.overrides);
  const auto commands = allCommands();
  const Command& command = findCommand(commands, study.command);
  // The base configuration with the study's fixed overrides must load: a typo in a key fails here,
  // before any case runs (each case's own values are checked by the case).
  const auto base_schema =
      command.schema_for_file ? command.schema_for_file(study.base) : command.schema();
  const io::Config base = io::loadConfigFile(study.base, base_schema, study.set);
  for (const auto& p : study.parameters) {
    if (!base_schema.findKey(p.key)) {
      io::loadConfigFile(study.base, base_schema, {p.key + "=0"});  // throws with did-you-mean
      throw InputError("study.parameters." + p.key, "", "a key of the base configuration");
    }
  }
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

  std::vector<io::SweepCaseRecord> records(static_cast<std::size_t>(total));
  std::vector<bool> have(static_cast<std::size_t>(total), false);
  std::vector<long long> pending;
  std::unique_ptr<io::SweepJournal> journal;
  long long resumed = 0;
  std::exception_ptr setup_error;
  if (root) {
    try {
      fs::create_directories(cases_dir);
      journal = std::make_unique<io::SweepJournal>(folder / "sweep_journal.jsonl",
                                                   study.fingerprint(), options.resume);
    } catch (...) {
      setup_error = std::current_exception();
    }
  }
  // Every rank stops together when rank 0 cannot start (e.g. nothing to resume).
  if (mpi && !mpi->agree(!setup_error) && !setup_error)
    throw InputError("--resume", "", "a sweep rank 0 can start (see its message)");
  if (setup_error) std::rethrow_exception(setup_error);
  if (root) {
    for (const auto& r : journal->previous()) {
      if (r.index < 0 || r.index >= total || have[r.index]) continue;
      records[r.index] = r;
      have[r.index] = true;
      ++resumed;
    }
    for (long long i = 0; i < total; ++i)
      if (!have[i]) pending.push_back(i);
  }

  Progress progress(total, resumed, options.quiet || !root);
  if (root && !options.quiet) {
    std::cerr << fmt::format(
        "sweep: {} cases of `{}` ({}), {} already done, {} to run on {}\n", total, study.command,
        toString(study.design), resumed, pending.size(),
        mpi ? fmt::format("{} MPI ranks", mpi->size()) : fmt::format("{} threads", threads));
  }
  const CaseFunction run_case = [&](long long index) {
    return runCase(command, base_schema, study, index, cases_dir);
  };
  const DoneFunction done = [&](const io::SweepCaseRecord& r) {
    journal->append(r);
    records[r.index] = r;
    have[r.index] = true;
    progress.tick(r.status != "ok");
  };
  if (mpi) {
    mpi->runCases(pending, threads, run_case, done);
  } else {
    runCasesOnThreads(pending, threads, run_case, done);
  }
  if (!root) return kExitOk;

  const double elapsed = progress.elapsed();
  std::error_code ec;
  if (fs::is_empty(cases_dir, ec)) fs::remove(cases_dir, ec);  // nothing kept
  io::ResultWriter writer(folder);
  // The journal is not listed among the summary's files: a later run's ResultWriter removes
  // listed files, and the journal must survive for --resume.
  io::writeSweepHdf5(writer.pathFor("sweep.h5"), study, records, base.resolved().dump());
  writer.recordFile("sweep.h5");
  writer.writeCsv("sweep.csv", io::sweepTable(study, records));
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
  for (const auto& r : records) {
    if (r.status != "ok" && summary.warnings.size() < 20)
      summary.warnings.push_back(fmt::format("case {}: {}: {}", r.index, r.status, r.message));
  }
  summary.results = {{"cases", total},
                     {"by_status", by_status},
                     {"resumed", resumed},
                     {"computed", static_cast<long long>(pending.size())},
                     {"workers", mpi ? fmt::format("{} MPI ranks", mpi->size())
                                     : fmt::format("{} threads", threads)},
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
  report(options, fmt::format("sweep of `{}`: {} cases ({} computed, {} resumed, {} failed) in "
                              "{:.3g} s\nresults: {}\n",
                              study.command, total, pending.size(), resumed, failed, elapsed,
                              path.string()));
  return failed == 0 ? kExitOk : kExitNumericalFailure;
}

}  // namespace geardyn::cli
