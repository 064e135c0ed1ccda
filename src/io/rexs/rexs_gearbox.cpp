/// REXS → gearbox description (rexs_gearbox.h): shafts, gears, parallel stages, bearings,
/// couplings and the operating point; planetary stages in rexs_planetary.cpp.

#include "geardyn/io/rexs/rexs_gearbox.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "geardyn/error.h"
#include "geardyn/geometry/gear_pair.h"
#include "geardyn/io/rexs/rexs_reader.h"
#include "rexs_mapping.h"

namespace geardyn::io::rexs {
namespace {

using namespace detail;

/// Types the mapping reads (directly or as data of another component).
const std::set<std::string> kUnderstood = {"gear_unit",
                                           "gear_casing",
                                           "shaft",
                                           "shaft_section",
                                           "cylindrical_gear",
                                           "ring_gear",
                                           "cylindrical_stage",
                                           "planetary_stage",
                                           "planet_carrier",
                                           "side_plate",
                                           "cylindrical_gear_flank",
                                           "cylindrical_stage_gear_data",
                                           "material",
                                           "external_load",
                                           "concept_bearing",
                                           "rolling_bearing_with_catalog_geometry",
                                           "rolling_bearing_with_detailed_geometry",
                                           "coupling",
                                           "switchable_coupling",
                                           "additional_mass"};

/// "worm_stage (1), lubricant (1)": components geardyn does not model.
std::string notModelled(const Document& doc) {
  std::map<std::string, int> count;
  for (const auto& c : doc.components)
    if (!kUnderstood.count(c.type)) ++count[c.type];
  std::string out;
  for (const auto& [type, n] : count)
    out += fmt::format("{}{} ({})", out.empty() ? "" : ", ", type, n);
  return out;
}

/// The attributes of component `id` in a load case over its base attributes.
const Component* inLoadCase(const io::rexs::LoadCase* lc, int id) {
  if (lc)
    for (const auto& c : lc->components)
      if (c.id == id) return &c;
  return nullptr;
}

struct Operating {
  int input = 0, output = 0;
  /// The shaft whose external load defines the torque (0: none); cases[].torque is that load's
  /// torque until it is carried over to the input (torqueOnInput).
  int torque_shaft = 0;
  std::vector<RexsLoadCaseSummary> cases;
};

/// Input shaft (defines_speed), output shaft (another torque-transmitting load), speed and
/// torque of each load case.
Operating operatingPoints(Model& model, const std::set<int>& shafts, const PlanetaryMapping& pm) {
  auto& read = model.read;
  Operating op;
  int torque_load = 0, torque_shaft = 0;
  for (const Component* s : model.ofType(kShaftTypes))
    if (read.boolean(*s, "defines_speed").value_or(false) && !op.input) op.input = s->id;
  auto bodyOf = [&](int id) { return pm.body_of.count(id) ? pm.body_of.at(id) : id; };
  std::vector<std::pair<int, int>> loads;  // (load, shaft)
  for (const Component* l : model.ofType({"external_load"})) {
    const auto shaft = model.assemblyOf(l->id, kShaftTypes);
    if (!shaft) continue;
    loads.emplace_back(l->id, bodyOf(*shaft));
    if (read.boolean(*l, "defines_torque").value_or(false) && !torque_load)
      torque_load = l->id, torque_shaft = bodyOf(*shaft);
  }
  const int speed_shaft = op.input;  // the component whose attributes give the speed
  if (op.input) op.input = bodyOf(op.input);
  if (!op.input) op.input = torque_shaft;
  if (!op.input && !shafts.empty()) op.input = *shafts.begin();
  for (const auto& [load, shaft] : loads) {
    if (shaft != op.input && !op.output &&
        read.boolean(model.component(load), "transmits_torque").value_or(false))
      op.output = shaft;
  }
  if (!op.output) {
    for (int s : shafts)
      if (s != op.input) op.output = s;
    read.warn(fmt::format("no external load marks the output shaft; {} takes the load torque",
                          op.output ? model.name(op.output) : "the input"));
  }
  if (!op.output) op.output = op.input;
  op.torque_shaft = torque_shaft;
  std::vector<const io::rexs::LoadCase*> cases;
  for (const auto& lc : model.doc.load_cases) cases.push_back(&lc);
  if (cases.empty()) cases.push_back(nullptr);
  for (const auto* lc : cases) {
    RexsLoadCaseSummary s;
    s.id = lc ? lc->id : 0;
    const Component& in = model.component(speed_shaft ? speed_shaft : op.input);
    const Component* in_lc = inLoadCase(lc, in.id);
    s.speed_rpm = (in_lc ? read.real(*in_lc, "rotational_speed") : std::nullopt)
                      .value_or(read.real(in, "rotational_speed", 0.0));
    if (torque_load) {
      const Component* l_lc = inLoadCase(lc, torque_load);
      s.torque =
          (l_lc ? read.real(*l_lc, "torque_around_u_axis") : std::nullopt)
              .value_or(read.real(model.component(torque_load), "torque_around_u_axis", 0.0));
    }
    for (const auto& u : model.doc.components)
      if (u.type == "gear_unit")
        if (const Component* g = inLoadCase(lc, u.id))
          s.time_fraction = read.real(*g, "operating_time_fraction", 0.0);
    op.cases.push_back(s);
  }
  return op;
}

std::string renderToml(const std::vector<TomlSection>& sections, const std::string& header) {
  std::string out = header;
  for (const auto& s : sections) {
    out += "\n";
    if (!s.comment.empty()) out += "# " + s.comment + "\n";
    out += "[" + s.header + "]\n";
    for (const auto& l : s.lines) {
      std::string line = l.key + " = " + l.value;
      if (!l.comment.empty())
        line += std::string(std::max<int>(1, 40 - int(line.size())), ' ') + "# " + l.comment;
      out += line + "\n";
    }
  }
  return out;
}

/// The operating point of the chosen load case ([operating_point]); the file's load cases into
/// `result`. The torque of a load on another shaft than the input is carried over to the input
/// through the kinematics of the sections written so far.
void addOperatingPoint(GearboxSections& out, const RexsImportOptions& options, RexsImport& result) {
  Model& model = out.model;
  auto& read = model.read;
  const Document& doc = model.doc;
  auto& sections = out.sections;
  const PlanetaryMapping& pm = out.pm;
  const std::set<int>& shafts = out.shafts;
  Operating op = operatingPoints(model, shafts, pm);
  std::string torque_note = "external_load torque_around_u_axis";
  if (op.torque_shaft && op.torque_shaft != op.input) {
    // The torque is given on another shaft (e.g. the output): carried over to the input by the
    // power balance of the lossless train, T_in = −T_B ω_B / ω_in, with ω_B / ω_in from the
    // kinematics of the description being written.
    std::optional<double> ratio;
    try {
      TomlSection probe{"operating_point", "", {}};
      probe.add("input", tomlString(model.name(op.input)));
      probe.add("output", tomlString(model.name(op.output)));
      std::vector<TomlSection> all = sections;
      all.push_back(probe);
      if (!options.speed_ratio) {
        throw InputError("speed_ratio", "(none)",
                         "the gearbox kinematics (config::importRexsGearbox supplies them)");
      }
      ratio = options.speed_ratio(renderToml(all, ""), doc.source, model.name(op.torque_shaft));
    } catch (const InputError& e) {
      read.warn(
          fmt::format("the torque is defined on shaft {} but the speed on {}, and the "
                      "speed ratio between them is not known ({}): the operating torque "
                      "is written as 0 (set operating_point.torque)",
                      model.name(op.torque_shaft), model.name(op.input), e.what()));
    }
    for (auto& c : op.cases) c.torque = ratio ? -c.torque * *ratio : 0.0;
    torque_note = ratio ? fmt::format(
                              "-T x {:.6g}: the torque on {} carried to the input "
                              "(lossless power balance)",
                              *ratio, model.name(op.torque_shaft))
                        : "not known (see the warnings)";
  }
  for (const auto& c : op.cases)
    if (c.id != 0 || !doc.load_cases.empty()) result.load_cases.push_back(c);
  std::size_t chosen = 0;
  if (options.load_case) {
    chosen = op.cases.size();
    for (std::size_t i = 0; i < op.cases.size(); ++i)
      if (op.cases[i].id == *options.load_case) chosen = i;
    if (chosen == op.cases.size()) {
      std::string ids;
      for (const auto& c : op.cases) ids += (ids.empty() ? "" : ", ") + std::to_string(c.id);
      throw InputError("load_case", std::to_string(*options.load_case),
                       ids.empty() || ids == "0" ? "the file has no load spectrum"
                                                 : "one of the file's load cases: " + ids);
    }
  }
  const RexsLoadCaseSummary& lc = op.cases[chosen];
  result.load_case = lc.id;
  TomlSection opt{"operating_point",
                  lc.id ? fmt::format("load case {} of the load spectrum", lc.id)
                        : std::string("component attributes (no load spectrum)"),
                  {}};
  opt.add("input", tomlString(model.name(op.input)),
          fmt::format("shaft component {} (defines_speed)", op.input));
  opt.add("speed_rpm", tomlReal(lc.speed_rpm), "rotational_speed");
  opt.add("torque", tomlReal(lc.torque), torque_note);
  opt.add("output", tomlString(model.name(op.output)),
          fmt::format("shaft component {}", op.output));
  sections.push_back(std::move(opt));
  if (op.cases.size() > 1)
    result.warnings.push_back(fmt::format(
        "{}: {} load cases; the operating point is load case {} (geardyn import --load-case ID, "
        "or [gearbox] load_case = ID in an analysis file)",
        doc.source, op.cases.size(), lc.id));
}

/// The file's comment header: where it comes from and its load cases.
std::string importHeader(const Document& doc, const RexsImport& result) {
  std::string header = fmt::format(
      "# Gearbox description imported by geardyn from REXS {} ({}, written by {}).\n"
      "# Every value names the REXS component it comes from; docs/guide/rexs.md says what is\n"
      "# mapped, what is not and the defaults.\n",
      doc.version, doc.source, doc.application);
  if (doc.load_cases.empty())
    header += "# no load spectrum: speed and torque from the components' attributes\n";
  for (const auto& c : result.load_cases)
    header +=
        fmt::format("# load case {}: input {:g} rpm, {:g} N m, operating time fraction {:g}\n",
                    c.id, c.speed_rpm, c.torque, c.time_fraction);
  return header;
}

}  // namespace

RexsImport importRexsGearbox(const Document& doc, const RexsImportOptions& options) {
  io::rexs::checkReferences(doc);  // documents built in code have not been through the reader
  RexsImport result;
  Model model(doc, result.warnings);
  if (const std::string skipped = notModelled(doc); !skipped.empty())
    result.warnings.push_back(doc.source +
                              ": components geardyn does not model, left out: " + skipped);
  for (const auto& c : doc.components) {
    if (c.type == "worm_stage")
      result.warnings.push_back(fmt::format(
          "{}: worm stages are not modelled ({}); its shafts, bearings and loads are kept",
          doc.source, c.label()));
  }
  result.rexs_shafts = static_cast<int>(model.ofType(kShaftTypes).size());
  result.rexs_gears = static_cast<int>(model.ofType(kGearTypes).size());
  result.rexs_stages = static_cast<int>(model.ofType({"cylindrical_stage"}).size());
  result.rexs_planetary_stages = static_cast<int>(model.ofType({"planetary_stage"}).size());
  result.rexs_bearings = static_cast<int>(model.ofType(kBearingTypes).size());
  result.rexs_couplings = static_cast<int>(model.ofType(kCouplingTypes).size());

  GearboxSections out{model, mapPlanetaryStages(model), {}, {}, {}};
  addShafts(out);
  addGears(out);
  addParallelStages(out);
  for (auto& s : out.pm.sections) out.sections.push_back(std::move(s));
  addDisks(out);
  addBearingsAndCouplings(out, options.bearing_stiffness.value_or(kRexsDefaultBearingStiffness),
                          result.warnings);
  addOperatingPoint(out, options, result);

  std::vector<TomlSection> all;
  TomlSection gb{"gearbox", "", {}};
  std::string unit_name;
  for (const Component* u : model.ofType({"gear_unit"})) unit_name = u->name;
  gb.add(
      "name",
      tomlString(unit_name.empty() ? std::filesystem::path(doc.source).stem().string() : unit_name),
      unit_name.empty() ? "the file name" : "the gear unit's name");
  gb.add("dofs", tomlString("planar"),
         "rigid shafts; \"full\" with flexible = true shafts gives FE shafts (E, ν, sections)");
  all.push_back(std::move(gb));
  for (auto& s : out.sections) all.push_back(std::move(s));
  result.toml = renderToml(all, importHeader(doc, result));
  return result;
}

RexsImport importRexsFile(const std::filesystem::path& file, const RexsImportOptions& options) {
  std::vector<std::string> warnings;
  const io::rexs::Document doc = io::rexs::readRexsFile(file, warnings);
  RexsImport result = importRexsGearbox(doc, options);
  result.warnings.insert(result.warnings.begin(), warnings.begin(), warnings.end());
  return result;
}

}  // namespace geardyn::io::rexs
