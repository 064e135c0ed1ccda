/// Study definition, journal and result files of `geardyn sweep` (see sweep_io.h).

#include "geardyn/config/sweep_config.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <toml++/toml.h>
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

#include "geardyn/config/did_you_mean.h"
#include "geardyn/config/toml_parse.h"
#include "geardyn/error.h"
#include "geardyn/io/atomic_file.h"

namespace geardyn::config {
namespace fs = std::filesystem;
namespace {

const std::vector<std::string> kStudyKeys = {
    "command",  "base", "design",  "samples",           "seed",
    "seed_key", "set",  "outputs", "keep_case_results", "parameters"};

[[noreturn]] void unknownKey(const std::string& section, const std::string& key,
                             const std::vector<std::string>& known) {
  const auto suggestion = closestMatch(key, known);
  throw InputError(section + "." + key, "",
                   suggestion ? fmt::format("an unknown key; did you mean '{}'?", *suggestion)
                              : fmt::format("an unknown key (known: {})", fmt::join(known, ", ")));
}

nlohmann::json toJson(const toml::node& node, const std::string& key) {
  if (auto v = node.as_integer()) return v->get();
  if (auto v = node.as_floating_point()) return v->get();
  if (auto v = node.as_boolean()) return v->get();
  if (auto v = node.as_string()) return v->get();
  throw InputError(key, "", "a number, string or boolean");
}

double number(const toml::node& node, const std::string& key) {
  if (auto v = node.as_integer()) return static_cast<double>(v->get());
  if (auto v = node.as_floating_point()) return v->get();
  throw InputError(key, "", "a number");
}

StudyParameter parameterOf(const std::string& key, const toml::node& node, StudyDesign design) {
  StudyParameter p;
  p.key = key;
  const std::string full = "study.parameters." + key;
  if (const toml::array* list = node.as_array()) {
    for (std::size_t i = 0; i < list->size(); ++i)
      p.values.push_back(toJson(*list->get(i), fmt::format("{}[{}]", full, i)));
  } else if (const toml::table* t = node.as_table()) {
    const bool has_distribution = t->contains("distribution");
    if (has_distribution) {
      const std::string name = t->get("distribution")->value_or(std::string());
      const std::vector<std::string> names{"uniform", "normal", "truncated_normal"};
      if (name == "uniform")
        p.distribution = StudyDistribution::kUniform;
      else if (name == "normal")
        p.distribution = StudyDistribution::kNormal;
      else if (name == "truncated_normal")
        p.distribution = StudyDistribution::kTruncatedNormal;
      else {
        const auto s = closestMatch(name, names);
        throw InputError(full + ".distribution", "\"" + name + "\"",
                         s ? fmt::format("one of uniform, normal, truncated_normal; did you mean "
                                         "'{}'?",
                                         *s)
                           : "one of uniform, normal, truncated_normal");
      }
      std::vector<std::string> allowed{"distribution"};
      if (p.distribution != StudyDistribution::kUniform)
        allowed.insert(allowed.end(), {"mean", "std"});
      if (p.distribution != StudyDistribution::kNormal)
        allowed.insert(allowed.end(), {"min", "max"});
      for (const auto& [k, v] : *t) {
        const std::string name_k(k.str());
        if (std::find(allowed.begin(), allowed.end(), name_k) == allowed.end())
          unknownKey(full, name_k, allowed);
        if (name_k == "distribution") continue;
        const double x = number(v, full + "." + name_k);
        if (name_k == "mean") p.mean = x;
        if (name_k == "std") p.std = x;
        if (name_k == "min") p.min = x;
        if (name_k == "max") p.max = x;
      }
      for (const auto& required : allowed)
        if (!t->contains(required)) throw InputError(full + "." + required, "", "required");
      if (design != StudyDesign::kRandom)
        throw InputError(full + ".distribution", "\"" + name + "\"",
                         "distributions need study.design = \"random\"");
    } else {
      const std::vector<std::string> allowed{"min", "max", "num"};
      for (const auto& [k, v] : *t) {
        if (std::find(allowed.begin(), allowed.end(), std::string(k.str())) == allowed.end())
          unknownKey(full, std::string(k.str()), allowed);
      }
      for (const auto& required : allowed)
        if (!t->contains(required)) throw InputError(full + "." + required, "", "required");
      const double lo = number(*t->get("min"), full + ".min");
      const double hi = number(*t->get("max"), full + ".max");
      for (const auto& [bound, x] : {std::pair{".min", lo}, std::pair{".max", hi}})
        if (!std::isfinite(x)) throw InputError(full + bound, fmt::format("{}", x), "finite");
      const auto* num = t->get("num")->as_integer();
      if (!num || num->get() < 1)
        throw InputError(full + ".num", "", "an integer >= 1 (number of values)");
      const long long n = num->get();
      // Integer endpoints with integral steps stay integers (for integer keys such as teeth).
      // The values are generated case by case (StudyParameter::valueAt), never stored.
      p.linspace_num = n;
      p.min = lo;
      p.max = hi;
      p.linspace_integers = t->get("min")->is_integer() && t->get("max")->is_integer() &&
                            (n == 1 || std::fmod(hi - lo, static_cast<double>(n - 1)) == 0.0);
    }
  } else {
    p.values.push_back(toJson(node, full));
  }
  p.validate(design);
  return p;
}

std::string fnv1a(const std::string& text) {
  std::uint64_t h = 1469598103934665603ULL;
  for (unsigned char c : text) h = (h ^ c) * 1099511628211ULL;
  return fmt::format("{:016x}", h);
}

std::string readText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

std::string tomlLiteral(const nlohmann::json& v) {
  if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
  if (v.is_number_integer()) return std::to_string(v.get<long long>());
  if (v.is_number()) {
    std::string s = fmt::format("{:.17g}", v.get<double>());
    if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
    return s;
  }
  std::string out = "\"";
  for (char c : v.get<std::string>()) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

ConfigSchema sweepSchema() {
  ConfigSchema schema(
      "sweep",
      "A study over any analysis command: `geardyn sweep FILE` (threads) or `mpirun -n N geardyn "
      "sweep FILE` (MPI ranks, dynamic work queue); `--resume` continues a killed run from "
      "sweep_journal.jsonl. [study.parameters] maps configuration keys of the base command to a "
      "list of values, to {min, max, num} (evenly spaced), or in a random design to {distribution "
      "= \"uniform\", min, max}, {distribution = \"normal\", mean, std} or {distribution = "
      "\"truncated_normal\", mean, std, min, max} (a list is then drawn from uniformly). Every "
      "case draws from its own stream seeded by (seed, case index): the same values whatever the "
      "threads or ranks. Over `train`, a parameter is any key of the analysis file or of its "
      "gearbox (named by [gearbox] file — TOML or REXS, whose load cases are the values of "
      "gearbox.load_case — or inline); a key inside a named table ([meshes.stage1]) must name "
      "one of the base's.");
  schema.string("title").defaultValue("").doc("free text copied into the summary");
  schema.section("study", "The study.");
  schema.string("study.command").required().doc("the analysis command run for every case");
  schema.string("study.base").required().doc("its configuration file, relative to this file");
  schema.string("study.design")
      .choices({"grid", "zip", "random"})
      .defaultValue("grid")
      .doc(
          "grid: full factorial (last parameter fastest); zip: the i-th values together; random: "
          "`samples` draws");
  schema.integer("study.samples").min(1).optional().doc("random: number of cases");
  schema.integer("study.seed").min(0).defaultValue(1).doc("study seed");
  schema.string("study.seed_key")
      .defaultValue("")
      .doc("a key of the base configuration set to each case's own seed (e.g. a Monte Carlo seed)");
  schema.stringList("study.set")
      .defaultValue(nlohmann::ordered_json::array())
      .doc("fixed overrides \"key=value\" of every case (the command line's --set adds to them)");
  schema.stringList("study.outputs")
      .required()
      .doc("\"name=/json/pointer\" (or just the pointer) into each case's summary results");
  schema.boolean("study.keep_case_results")
      .defaultValue(false)
      .doc("keep every case's own result folder under cases/");
  schema.section("study.parameters", "The swept keys (see above).");
  schema.section("output", "Output.");
  schema.boolean("output.plots").defaultValue(true).doc("sweep.png with matplotlib");
  return schema;
}

long long SweepDefinition::caseCount() const {
  return studyCaseCount(design, parameters, samples);
}

StudyCase SweepDefinition::caseAt(long long index) const {
  return studyCase(design, parameters, index, seed);
}

std::vector<std::string> SweepDefinition::overridesOf(const StudyCase& c) const {
  std::vector<std::string> o = set;
  for (std::size_t i = 0; i < parameters.size(); ++i)
    o.push_back(parameters[i].key + "=" + tomlLiteral(c.values[i]));
  if (!seed_key.empty()) o.push_back(fmt::format("{}={}", seed_key, c.seed >> 1));
  return o;
}

std::string SweepDefinition::fingerprint(const std::string& base_inputs) const {
  return fnv1a(resolved.dump() + "\n" + readText(base) + base_inputs);
}

namespace {

/// --set study.KEY=VALUE changes the study itself (study.parameters.<key> a swept key): applied
/// to `root`; the other --set values are returned, fixed overrides of the base configuration.
std::vector<std::string> applyStudySets(toml::table& root,
                                        const std::vector<std::string>& extra_set) {
  std::vector<std::string> base_set;
  for (const auto& e : extra_set) {
    const auto eq = e.find('=');
    if (e.rfind("study.", 0) != 0 || eq == std::string::npos) {
      base_set.push_back(e);
      continue;
    }
    const std::string path = e.substr(6, eq - 6), text = e.substr(eq + 1);
    toml::table parsed;
    const std::string document = "v = " + text;
    try {
      parsed = parseToml(document, "--set");
    } catch (const toml::parse_error&) {
      parsed.insert("v", text);  // a bare word is a string
    }
    if (!root["study"].as_table()) root.insert("study", toml::table{});
    toml::table* table = root["study"].as_table();
    std::string leaf = path;
    if (path.rfind("parameters.", 0) == 0) {
      if (!table->get("parameters")) table->insert("parameters", toml::table{});
      table = table->get("parameters")->as_table();
      leaf = path.substr(11);
      // The key may be quoted as in the file: study.parameters."model.mass".
      if (leaf.size() > 1 && leaf.front() == '"' && leaf.back() == '"')
        leaf = leaf.substr(1, leaf.size() - 2);
    }
    if (!table) throw InputError("--set", e, "study.parameters is a table in the file");
    parsed.get("v")->visit([&](auto&& value) { table->insert_or_assign(leaf, value); });
  }
  return base_set;
}

/// The file's top-level keys besides [study]: title and [output].
void readTopLevel(const toml::table& root, SweepDefinition& d) {
  for (const auto& [k, v] : root) {
    const std::string key(k.str());
    if (key == "title") {
      d.title = v.value_or(std::string());
    } else if (key == "output") {
      const toml::table* t = v.as_table();
      for (const auto& [ok, ov] : *t) {
        if (ok.str() != "plots") unknownKey("output", std::string(ok.str()), {"plots"});
        if (!ov.is_boolean()) throw InputError("output.plots", "", "true or false");
        d.plots = ov.value_or(true);
      }
    } else if (key != "study") {
      unknownKey("", key, {"title", "study", "output"});
    }
  }
}

/// [study]'s scalar keys (command, base, design, samples, seed, seed_key, keep_case_results, set),
/// with the command line's base overrides appended to `set`.
void readStudyKeys(const toml::table* study, const fs::path& file,
                   const std::vector<std::string>& base_set, SweepDefinition& d) {
  auto str = [&](const char* key, const std::string& fallback, bool required) {
    const toml::node* n = study->get(key);
    if (!n) {
      if (required) throw InputError(std::string("study.") + key, "", "required");
      return fallback;
    }
    if (!n->is_string()) throw InputError(std::string("study.") + key, "", "a string");
    return n->value_or(std::string());
  };
  d.command = str("command", "", true);
  const fs::path base = str("base", "", true);
  d.base = base.is_absolute() ? base : fs::absolute(file).parent_path() / base;
  if (!fs::exists(d.base)) throw InputError("study.base", d.base.string(), "an existing file");
  const std::string design = str("design", "grid", false);
  if (design == "grid")
    d.design = StudyDesign::kGrid;
  else if (design == "zip")
    d.design = StudyDesign::kZip;
  else if (design == "random")
    d.design = StudyDesign::kRandom;
  else
    throw InputError("study.design", "\"" + design + "\"", "one of grid, zip, random");
  if (const toml::node* n = study->get("samples")) {
    if (!n->is_integer()) throw InputError("study.samples", "", "an integer >= 1");
    d.samples = n->value_or(0LL);
  } else if (d.design == StudyDesign::kRandom) {
    throw InputError("study.samples", "", "required with design = \"random\"");
  }
  if (const toml::node* n = study->get("seed")) {
    if (!n->is_integer() || n->value_or(-1LL) < 0)
      throw InputError("study.seed", "", "an integer >= 0");
    d.seed = static_cast<std::uint64_t>(n->value_or(0LL));
  }
  d.seed_key = str("seed_key", "", false);
  if (const toml::node* n = study->get("keep_case_results")) {
    if (!n->is_boolean()) throw InputError("study.keep_case_results", "", "true or false");
    d.keep_case_results = n->value_or(false);
  }
  if (const toml::node* n = study->get("set")) {
    const toml::array* a = n->as_array();
    if (!a) throw InputError("study.set", "", "a list of \"key=value\" strings");
    for (const auto& e : *a) {
      if (!e.is_string()) throw InputError("study.set", "", "a list of \"key=value\" strings");
      d.set.push_back(e.value_or(std::string()));
    }
  }
  for (const auto& e : base_set) {
    d.set.push_back(e);
    // The sweep's own plots follow the command line's output.plots too.
    if (e.rfind("output.plots=", 0) == 0) d.plots = e.substr(13) == "true";
  }
}

/// study.outputs: "name=/json/pointer" or "/json/pointer" (named by the pointer), distinct names.
void readOutputs(const toml::table* study, SweepDefinition& d) {
  const toml::array* outputs = study->get("outputs") ? study->get("outputs")->as_array() : nullptr;
  if (!outputs || outputs->empty())
    throw InputError("study.outputs", "",
                     "a list of JSON pointers into results, e.g. \"/dynamic_factor\"");
  std::set<std::string> names;
  for (const auto& e : *outputs) {
    const std::string text = e.value_or(std::string());
    const auto eq = text.find('=');
    SweepOutput o{eq == std::string::npos ? "" : text.substr(0, eq),
                  eq == std::string::npos ? text : text.substr(eq + 1)};
    if (o.pointer.empty() || o.pointer[0] != '/')
      throw InputError("study.outputs", "\"" + text + "\"",
                       "\"name=/json/pointer\" or \"/json/pointer\" into the summary's results");
    if (o.name.empty()) {
      o.name = o.pointer.substr(1);
      std::replace(o.name.begin(), o.name.end(), '/', '.');
    }
    if (!names.insert(o.name).second)
      throw InputError("study.outputs", "\"" + o.name + "\"", "distinct output names");
    d.outputs.push_back(o);
  }
}

/// study.parameters in the order of the file (toml++ keeps tables sorted by key).
void readParameters(const toml::table* study, SweepDefinition& d) {
  const toml::table* params =
      study->get("parameters") ? study->get("parameters")->as_table() : nullptr;
  if (!params || params->empty())
    throw InputError("study.parameters", "",
                     "a table of swept keys, e.g. \"excitation.speed_rpm\" = [1000, 2000]");
  // In the order of the file (toml++ keeps tables sorted by key).
  std::vector<std::pair<std::pair<std::uint32_t, std::uint32_t>, std::string>> order;
  for (const auto& [k, v] : *params)
    order.push_back({{k.source().begin.line, k.source().begin.column}, std::string(k.str())});
  std::sort(order.begin(), order.end());
  for (const auto& [position, key] : order)
    d.parameters.push_back(parameterOf(key, *params->get(key), d.design));
  (void)d.caseCount();  // validates the design as a whole
}

/// The study as resolved (defaults filled in), recorded in the sweep's results.
nlohmann::ordered_json resolvedStudy(const SweepDefinition& d) {
  nlohmann::ordered_json params_json = nlohmann::ordered_json::object();
  for (const auto& p : d.parameters) {
    nlohmann::ordered_json j = {{"distribution", toString(p.distribution)}};
    if (p.linspace_num > 0)
      j["linspace"] = {{"min", p.min}, {"max", p.max}, {"num", p.linspace_num}};
    else if (p.distribution == StudyDistribution::kValues)
      j["values"] = p.values;
    if (p.distribution == StudyDistribution::kUniform ||
        p.distribution == StudyDistribution::kTruncatedNormal)
      j["min"] = p.min, j["max"] = p.max;
    if (p.distribution == StudyDistribution::kNormal ||
        p.distribution == StudyDistribution::kTruncatedNormal)
      j["mean"] = p.mean, j["std"] = p.std;
    params_json[p.key] = j;
  }
  nlohmann::ordered_json outputs_json = nlohmann::ordered_json::object();
  for (const auto& o : d.outputs) outputs_json[o.name] = o.pointer;
  return {{"title", d.title},        {"command", d.command},
          {"base", d.base.string()}, {"design", toString(d.design)},
          {"samples", d.samples},    {"seed", d.seed},
          {"seed_key", d.seed_key},  {"set", d.set},
          {"outputs", outputs_json}, {"parameters", params_json},
          {"cases", d.caseCount()}};
}

}  // namespace

SweepDefinition loadSweepDefinition(const fs::path& file,
                                    const std::vector<std::string>& extra_set) {
  toml::table root;
  try {
    root = parseTomlFile(file);
  } catch (const toml::parse_error& e) {
    if (!fs::exists(file)) throw InputError("config", file.string(), "an existing file");
    throw InputError("config", file.string(),
                     fmt::format("valid TOML ({} at line {})", std::string(e.description()),
                                 e.source().begin.line));
  }
  const std::vector<std::string> base_set = applyStudySets(root, extra_set);
  SweepDefinition d;
  readTopLevel(root, d);
  const toml::table* study = root["study"].as_table();
  if (!study) throw InputError("study", "", "a [study] section");
  for (const auto& [k, v] : *study) {
    if (std::find(kStudyKeys.begin(), kStudyKeys.end(), std::string(k.str())) == kStudyKeys.end())
      unknownKey("study", std::string(k.str()), kStudyKeys);
  }
  readStudyKeys(study, file, base_set, d);
  readOutputs(study, d);
  readParameters(study, d);
  d.resolved = resolvedStudy(d);
  return d;
}

}  // namespace geardyn::config
