#include "geardyn/geometry/gear_pair.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>

#include "geardyn/error.h"
#include "geardyn/geometry/involute.h"
#include "geardyn/geometry/rack_generation.h"
#include "geardyn/units.h"

namespace geardyn {
namespace {

constexpr double kPi = std::numbers::pi;
using geardyn::units::kDegree;
/// Relative tolerance for "equal" design data of the two members (module, pressure angle, helix).
constexpr double kSameDesignTolerance = 1e-9;
/// Normal tip thickness below which ISO practice (and every gear handbook) warns of a weak,
/// hardening-sensitive tip: 0.2 m_n.
constexpr double kThinTipFraction = 0.2;

std::string mm(double metres) {
  return fmt::format("{:.6g} mm", metres * 1e3);
}

/// The part of the geometry that depends on one gear alone (reference, base, tip, root radii).
struct MemberRadii {
  double r, rb, ra, rf;
  double s_t;   // transverse tooth thickness on the reference circle [m]
  double s_an;  // normal tooth thickness on the tip circle [m]
};

double toothThicknessAt(const MemberRadii& m, double alpha_t, double radius);

MemberRadii memberRadii(const GearSpec& g, const std::string& name, double m_t, double alpha_t) {
  MemberRadii radii{};
  radii.r = 0.5 * g.teeth * m_t;
  radii.rb = radii.r * std::cos(alpha_t);
  radii.ra = radii.r + (g.addendum_coefficient + g.profile_shift) * g.normal_module +
             g.tip_radius_modification;
  radii.rf = radii.r - (g.dedendum_coefficient - g.profile_shift) * g.normal_module;
  // ISO 21771 eq. (41): s_t = m_t (π/2 + 2 x tan α_n).
  radii.s_t = m_t * (0.5 * kPi + 2.0 * g.profile_shift * std::tan(g.normal_pressure_angle));
  if (radii.rf <= 0.0) {
    throw InputError(name + ".dedendum_coefficient", fmt::format("{:g}", g.dedendum_coefficient),
                     fmt::format("root radius r_f = {} must be positive", mm(radii.rf)));
  }
  if (radii.rf <= 0.5 * g.bore_diameter) {
    throw InputError(
        name + ".bore_diameter", fmt::format("{:g}", g.bore_diameter),
        fmt::format("bore must be smaller than the root diameter d_f = {}", mm(2.0 * radii.rf)));
  }
  if (radii.ra <= radii.rb) {
    throw InputError(name + ".tip_radius_modification",
                     fmt::format("{:g}", g.tip_radius_modification),
                     fmt::format("tip radius r_a = {} must exceed the base radius r_b = {}: the "
                                 "tooth would have no involute flank",
                                 mm(radii.ra), mm(radii.rb)));
  }
  // Tip thickness, normal section: s_an = s_at cos β_a with tan β_a = tan β r_a / r.
  const double beta = std::abs(g.helix_angle);
  radii.s_an = toothThicknessAt(radii, alpha_t, radii.ra) *
               std::cos(std::atan(std::tan(beta) * radii.ra / radii.r));
  if (radii.s_an <= 0.0) {
    throw InputError(name + ".profile_shift", fmt::format("{:g}", g.profile_shift),
                     fmt::format("the tooth comes to a point below its tip circle (tip thickness "
                                 "{}): reduce the profile shift or the addendum",
                                 mm(radii.s_an)));
  }
  return radii;
}

/// Roll distance from T (along the line of action) at which the rack-generated involute starts:
/// the generating rack's straight flank ends h_FfP − x m_n below the gear's reference line and
/// meets the line of action (h_FfP − x m_n) / sin α_t from the pitch point, which is r sin α_t
/// from T (ISO 21771 §5.4). Negative: the rack cuts beyond the interference point T, i.e. the
/// tooth is undercut.
double rackFormRoll(const GearSpec& g, const MemberRadii& m, double alpha_t) {
  const double rack_tip_height = g.rackStraightFlankDepth() - g.profile_shift * g.normal_module;
  return m.r * std::sin(alpha_t) - rack_tip_height / std::sin(alpha_t);
}

/// Transverse arc tooth thickness at radius `radius` on the involute (ISO 21771 eq. 47).
double toothThicknessAt(const MemberRadii& m, double alpha_t, double radius) {
  const double alpha_y = std::acos(m.rb / radius);
  return 2.0 * radius * (m.s_t / (2.0 * m.r) + involute(alpha_t) - involute(alpha_y));
}

}  // namespace

std::string toString(Driver driver) {
  return driver == Driver::kPinion ? "pinion" : "gear";
}

Driver parseDriver(const std::string& text, const std::string& key) {
  if (text == "pinion") return Driver::kPinion;
  if (text == "gear") return Driver::kGear;
  throw InputError(key, "\"" + text + "\"", "must be \"pinion\" or \"gear\"");
}

/// Values outside the usual engineering ranges: a module of 3 is 3 m, not 3 mm (SI units).
static std::vector<std::string> plausibilityNotes(const GearPairSpec& spec) {
  std::vector<std::string> notes = plausibilityNotes(spec.pinion, "pinion");
  for (auto& note : plausibilityNotes(spec.gear, "gear")) notes.push_back(std::move(note));
  return notes;
}

namespace {

/// The two members must be cut by the same rack: equal normal module and pressure angle, and
/// (external helical pair) equal helix angles of opposite hand.
void checkSameRack(const GearSpec& g1, const GearSpec& g2) {
  if (std::abs(g2.normal_module - g1.normal_module) > kSameDesignTolerance * g1.normal_module) {
    throw InputError("gear.module", fmt::format("{:g}", g2.normal_module),
                     fmt::format("must equal pinion.module = {:g}: gears of different normal "
                                 "modules cannot mesh",
                                 g1.normal_module));
  }
  if (std::abs(g2.normal_pressure_angle - g1.normal_pressure_angle) > kSameDesignTolerance) {
    throw InputError("gear.pressure_angle_deg",
                     fmt::format("{:g}", g2.normal_pressure_angle / kDegree),
                     fmt::format("must equal pinion.pressure_angle_deg = {:g}",
                                 g1.normal_pressure_angle / kDegree));
  }
  if (std::abs(g2.helix_angle + g1.helix_angle) > kSameDesignTolerance) {
    throw InputError("gear.helix_angle_deg", fmt::format("{:g}", g2.helix_angle / kDegree),
                     fmt::format("an external helical pair needs equal helix angles of opposite "
                                 "hand: expected {:g} (pinion.helix_angle_deg = {:g})",
                                 -g1.helix_angle / kDegree, g1.helix_angle / kDegree));
  }
}

/// Centre distance, working pressure angle and backlash of the mounted pair.
struct OperatingMesh {
  double a_tight;     ///< zero-backlash centre distance of the profile-shifted teeth [m]
  double a_w;         ///< operating centre distance [m]
  double alpha_wt;    ///< transverse working pressure angle [rad]
  double r_w1, r_w2;  ///< operating pitch radii [m]
  double j_wt;        ///< circumferential backlash on the operating pitch circle [m]
};

OperatingMesh operatingMesh(const GearPairSpec& spec, const MemberRadii& m1, const MemberRadii& m2,
                            double alpha_t) {
  const GearSpec& g1 = spec.pinion;
  const GearSpec& g2 = spec.gear;
  OperatingMesh out{};
  // Zero-backlash mesh of the profile-shifted teeth (ISO 21771 eq. 61):
  // inv α_wt = inv α_t + 2 tan α_n (x₁ + x₂) / (z₁ + z₂).
  const double inv_tight = involute(alpha_t) + 2.0 * std::tan(g1.normal_pressure_angle) *
                                                   (g1.profile_shift + g2.profile_shift) /
                                                   (g1.teeth + g2.teeth);
  if (inv_tight <= 0.0) {
    throw InputError("gear.profile_shift", fmt::format("{:g}", g2.profile_shift),
                     "the sum of the profile shifts is so negative that the teeth cannot mesh "
                     "without overlapping at any centre distance");
  }
  out.a_tight = (m1.rb + m2.rb) / std::cos(inverseInvolute(inv_tight));
  if (spec.centre_distance) {
    out.a_w = *spec.centre_distance;
    if (!std::isfinite(out.a_w) || out.a_w <= m1.rb + m2.rb) {
      throw InputError(
          "pair.centre_distance", fmt::format("{:g} m", out.a_w),
          fmt::format("must exceed the sum of the base radii r_b1 + r_b2 = {}", mm(m1.rb + m2.rb)));
    }
  } else {
    out.a_w = out.a_tight;
  }
  out.alpha_wt = std::acos((m1.rb + m2.rb) / out.a_w);

  // Backlash on the operating pitch circle: pitch minus the two tooth thicknesses there.
  out.r_w1 = m1.rb / std::cos(out.alpha_wt);
  out.r_w2 = m2.rb / std::cos(out.alpha_wt);
  out.j_wt = 2.0 * kPi * out.r_w1 / g1.teeth - toothThicknessAt(m1, alpha_t, out.r_w1) -
             toothThicknessAt(m2, alpha_t, out.r_w2);
  if (out.j_wt < -1e-9 * g1.normal_module) {
    throw InputError("pair.centre_distance", fmt::format("{:g} m", out.a_w),
                     fmt::format("must be at least the tight-mesh centre distance {} of these "
                                 "profile shifts: closer, the teeth would overlap",
                                 mm(out.a_tight)));
  }
  return out;
}

/// a_w − r_a − r_f(mate) [m]; an error when the tip reaches the mate's root circle.
double tipClearance(const char* name, double a_w, double ra, double rf_mate) {
  const double clearance = a_w - ra - rf_mate;
  if (clearance < 0.0) {
    throw InputError("pair.centre_distance", fmt::format("{:g} m", a_w),
                     fmt::format("the {} tip circle (r_a = {}) reaches the mate's root circle "
                                 "(r_f = {}): tip clearance {}",
                                 name, mm(ra), mm(rf_mate), mm(clearance)));
  }
  return clearance;
}

/// Roll distance of the true form circle r_Ff (where the profile becomes involute): the end of
/// the rack's straight flank, or, with undercut, where the fillet cuts the involute back
/// (geometry/rack_generation.h). Contact on the involutes cannot begin below it.
double formCircleRoll(const GearSpec& g, const MemberRadii& m) {
  const double r_ff = trueFormRadius(generatingRack(g));
  return std::sqrt(std::max(0.0, r_ff * r_ff - m.rb * m.rb));
}

/// One member's flank against the mate's tip. The mate's tip meets the line of action at
/// line_of_action − ρ_a(mate) from the member's T. Without undercut, closer to T than the form
/// point the mate's tip would sweep material the generating rack left standing: tip-root
/// interference (error). With undercut the rack cut beyond T and the fillet cuts the involute
/// back down to r_Ff: a mate tip reaching below r_Ff passes through the undercut, the involutes
/// touch only from r_Ff (a warning with the numbers; whether the tip clears the undercut fillet
/// is not checked), unless it reaches further beyond T than the rack's flank end did (error).
/// Returns whether the mate's tip reaches into the undercut.
bool checkTipInterference(const char* name, const char* mate, const GearSpec& mate_spec,
                          double mate_tip_roll, double roll_form, double roll_ff,
                          const MemberRadii& m) {
  if (mate_tip_roll < roll_form - 1e-12 * m.r) {
    // Beyond T (undercut) the tip follows the line of action further than the rack's flank
    // end: it sweeps deeper than the rack cut the undercut.
    const std::string reach =
        roll_form >= 0.0 ? fmt::format(
                               "reaches the {} flank at d = {}, below its involute form diameter "
                               "d_Ff = {} (where the generating rack's straight flank ends)",
                               name, mm(2.0 * std::hypot(m.rb, mate_tip_roll)),
                               mm(2.0 * std::hypot(m.rb, roll_form)))
                         : fmt::format(
                               "reaches {} beyond the {} base-circle tangent point on the line of "
                               "action, further than the generating rack's straight flank ({})",
                               mm(-mate_tip_roll), name, mm(-roll_form));
    throw InputError(std::string(mate) + ".addendum_coefficient",
                     fmt::format("{:g}", mate_spec.addendum_coefficient),
                     fmt::format("tip interference: the {} tip {}, so it would hit the {} "
                                 "fillet; reduce the {} addendum or add {} profile shift",
                                 mate, reach, name, mate, name));
  }
  return roll_form < 0.0 && mate_tip_roll < roll_ff;
}

/// The path of contact on the line of action, roll distances from the pinion's T₁.
struct ContactPath {
  double line_of_action;          ///< T₁T₂ [m]
  double begin, end;              ///< where contact begins and ends, from T₁ [m]
  double uncut_length;            ///< the path the uncut involutes would give [m]
  double roll_form1, roll_form2;  ///< rackFormRoll per member [m]
  double roll_ff1, roll_ff2;      ///< formCircleRoll per member [m]
  bool undercut_contact;          ///< a tip reaches into the mate's undercut
};

/// The path of contact, with the tip-interference checks and the warnings for tips that reach
/// into an undercut flank (they shorten the path; ε_α with and without the undercut named).
ContactPath contactPath(const GearSpec& g1, const GearSpec& g2, const MemberRadii& m1,
                        const MemberRadii& m2, double alpha_t, double a_w, double alpha_wt,
                        double p_bt, std::vector<std::string>& warnings) {
  ContactPath path{};
  path.line_of_action = a_w * std::sin(alpha_wt);
  // Roll distances along the line of action: pinion quantities from T₁, gear ones from T₂.
  const double rho_a1 = std::sqrt(m1.ra * m1.ra - m1.rb * m1.rb);  // T₁ → pinion tip point
  const double rho_a2 = std::sqrt(m2.ra * m2.ra - m2.rb * m2.rb);  // T₂ → gear tip point
  path.roll_form1 = rackFormRoll(g1, m1, alpha_t);
  path.roll_form2 = rackFormRoll(g2, m2, alpha_t);
  path.roll_ff1 = formCircleRoll(g1, m1);
  path.roll_ff2 = formCircleRoll(g2, m2);
  const double gear_tip_from_t1 = path.line_of_action - rho_a2;
  const double pinion_tip_from_t2 = path.line_of_action - rho_a1;
  const bool into_undercut1 = checkTipInterference("pinion", "gear", g2, gear_tip_from_t1,
                                                   path.roll_form1, path.roll_ff1, m1);
  const bool into_undercut2 = checkTipInterference("gear", "pinion", g1, pinion_tip_from_t2,
                                                   path.roll_form2, path.roll_ff2, m2);
  path.begin = std::max(gear_tip_from_t1, path.roll_ff1);
  path.end = path.line_of_action - std::max(pinion_tip_from_t2, path.roll_ff2);
  // ε_α the uncut involutes would give (contact from the tips, or from T): for the warning.
  path.uncut_length =
      (path.line_of_action - std::max(pinion_tip_from_t2, 0.0)) - std::max(gear_tip_from_t1, 0.0);
  path.undercut_contact = into_undercut1 || into_undercut2;
  const auto warn_undercut_contact = [&](const char* name, const char* mate, double mate_tip_roll,
                                         double roll_ff, const MemberRadii& m) {
    const std::string where =
        mate_tip_roll >= 0.0
            ? fmt::format("the {} flank at d = {}", name, mm(2.0 * std::hypot(m.rb, mate_tip_roll)))
            : fmt::format("{} beyond the {} base-circle tangent point on the line of action",
                          mm(-mate_tip_roll), name);
    warnings.push_back(fmt::format(
        "the {} tip reaches {}, below the true form diameter d_Ff = {} of the {} undercut flank: "
        "the involutes touch only from d_Ff, which shortens the path of contact (transverse "
        "contact ratio {:.4f}, against {:.4f} on the uncut involute); the tip passes through the "
        "undercut, its clearance to the fillet is not checked",
        mate, where, mm(2.0 * std::hypot(m.rb, roll_ff)), name, (path.end - path.begin) / p_bt,
        path.uncut_length / p_bt));
  };
  if (into_undercut1) warn_undercut_contact("pinion", "gear", gear_tip_from_t1, path.roll_ff1, m1);
  if (into_undercut2)
    warn_undercut_contact("gear", "pinion", pinion_tip_from_t2, path.roll_ff2, m2);
  return path;
}

/// The total contact ratio must reach 1 (an error naming the centre distance when the user's
/// pulls the teeth apart, the gears' data otherwise); ε_α < 1 is a warning.
void checkContactRatios(const GearPairSpec& spec, double eps_alpha, double eps_beta,
                        const ContactPath& path, double p_bt, double a_w, double a_tight,
                        double tip_radii_sum, std::vector<std::string>& warnings) {
  const double path_length = path.end - path.begin;
  if (spec.centre_distance && eps_alpha + eps_beta < 1.0) {
    // The centre distance the user gave pulls the teeth out of reach of each other.
    throw InputError(
        "pair.centre_distance", fmt::format("{:g} m", a_w),
        fmt::format("too large for these gears: the path of contact is {} long (contact ratio "
                    "{:.4g} < 1), the tip circles r_a1 + r_a2 = {} leave the teeth out of reach; "
                    "the tight-mesh centre distance is {}",
                    mm(path_length), eps_alpha + eps_beta, mm(tip_radii_sum), mm(a_tight)));
  }
  if (eps_alpha + eps_beta < 1.0) {
    throw InputError(
        "pinion, gear", fmt::format("contact ratio {:.6g}", eps_alpha + eps_beta),
        fmt::format("the total contact ratio must be at least 1 (transverse {:.6g}, overlap "
                    "{:.6g}): one tooth pair leaves contact before the next one enters, so the "
                    "pair cannot mesh continuously; raise the addendum, the number of teeth, the "
                    "face width or the helix angle{}",
                    eps_alpha, eps_beta,
                    path.undercut_contact
                        ? fmt::format(" (the undercut, which starts the involute at the true "
                                      "form circle, shortens the path of contact: ε_α would be "
                                      "{:.6g} on the uncut involute; profile shift avoids it)",
                                      path.uncut_length / p_bt)
                        : std::string()));
  }
  if (eps_alpha < 1.0) {
    warnings.push_back(fmt::format(
        "transverse contact ratio {:.4f} < 1: continuous meshing relies on the overlap ratio "
        "{:.4f}",
        eps_alpha, eps_beta));
  }
}

/// One member's radii, form circle, undercut, tip thickness and body mass (its tip clearance is
/// the pair's), with the undercut and thin-tip warnings.
GearGeometry memberGeometry(const char* name, const GearSpec& g, const MemberRadii& m, double m_t,
                            double alpha_t, double r_w, double roll_sap, double roll_form,
                            double roll_ff, double tip_clearance,
                            std::vector<std::string>& warnings) {
  GearGeometry out;
  out.transverse_module = m_t;
  out.pitch_radius = m.r;
  out.base_radius = m.rb;
  out.tip_radius = m.ra;
  out.root_radius = m.rf;
  out.operating_pitch_radius = r_w;
  out.tip_clearance = tip_clearance;
  // Start of active profile: where the path of contact begins on this member's flank.
  out.active_profile_start_radius = std::hypot(m.rb, roll_sap);
  out.undercut = roll_form < -1e-12 * m.r;
  out.form_radius = std::hypot(m.rb, roll_ff);
  if (out.undercut) {
    const double z_min = 2.0 * (g.rackStraightFlankDepth() / g.normal_module - g.profile_shift) *
                         std::cos(std::abs(g.helix_angle)) / std::pow(std::sin(alpha_t), 2);
    warnings.push_back(fmt::format(
        "{} is undercut ({} teeth < {:.2f}, the limit for x = {:g}): the involute is cut away "
        "below the true form diameter d_Ff = {} (base circle d_b = {}); start of active "
        "profile d_Nf = {}",
        name, g.teeth, z_min, g.profile_shift, mm(2.0 * out.form_radius), mm(2.0 * m.rb),
        mm(2.0 * out.active_profile_start_radius)));
  }
  out.tip_thickness_normal = m.s_an;
  if (out.tip_thickness_normal < kThinTipFraction * g.normal_module) {
    warnings.push_back(fmt::format("{}: tip thickness {} is below 0.2 m_n = {} (thin, pointed tip)",
                                   name, mm(out.tip_thickness_normal),
                                   mm(kThinTipFraction * g.normal_module)));
  }
  const GearBodyMass body = gearBodyMass(g);
  out.mass = body.mass;
  out.polar_inertia = body.polar_inertia;
  out.diametral_inertia = body.diametral_inertia;
  return out;
}

}  // namespace

// A function-try-block: an error caused by an implausible value (a length in mm) says so.
GearPair::GearPair(const GearPairSpec& spec) try : spec_(spec) {
  const GearSpec& g1 = spec.pinion;
  const GearSpec& g2 = spec.gear;
  g1.validate("pinion");
  g2.validate("gear");
  warnings_ = plausibilityNotes(spec);
  checkSameRack(g1, g2);

  const double m_n = g1.normal_module;
  const double alpha_n = g1.normal_pressure_angle;
  const double beta = std::abs(g1.helix_angle);
  const double m_t = m_n / std::cos(beta);
  alpha_t_ = std::atan(std::tan(alpha_n) / std::cos(beta));
  beta_b_ = std::atan(std::tan(beta) * std::cos(alpha_t_));
  p_bt_ = kPi * m_t * std::cos(alpha_t_);
  p_bn_ = kPi * m_n * std::cos(alpha_n);
  gear_ratio_ = static_cast<double>(g2.teeth) / g1.teeth;

  const MemberRadii m1 = memberRadii(g1, "pinion", m_t, alpha_t_);
  const MemberRadii m2 = memberRadii(g2, "gear", m_t, alpha_t_);
  a_ref_ = m1.r + m2.r;

  const OperatingMesh op = operatingMesh(spec, m1, m2, alpha_t_);
  a_tight_ = op.a_tight;
  a_w_ = op.a_w;
  alpha_wt_ = op.alpha_wt;
  j_wt_ = op.j_wt;
  j_bn_ = j_wt_ * std::cos(alpha_wt_) * std::cos(beta_b_);

  const double clearance1 = tipClearance("pinion", a_w_, m1.ra, m2.rf);
  const double clearance2 = tipClearance("gear", a_w_, m2.ra, m1.rf);
  const ContactPath path = contactPath(g1, g2, m1, m2, alpha_t_, a_w_, alpha_wt_, p_bt_, warnings_);
  line_of_action_ = path.line_of_action;
  path_length_ = path.end - path.begin;
  // A driving pinion meets the gear tip first.
  path_start_ = spec.driver == Driver::kPinion ? path.begin : path.end;
  path_end_ = spec.driver == Driver::kPinion ? path.end : path.begin;

  eps_alpha_ = path_length_ / p_bt_;
  face_width_ = std::min(g1.face_width, g2.face_width);
  eps_beta_ = face_width_ * std::sin(beta) / (kPi * m_n);
  checkContactRatios(spec, eps_alpha_, eps_beta_, path, p_bt_, a_w_, a_tight_, m1.ra + m2.ra,
                     warnings_);

  pinion_ = memberGeometry("pinion", g1, m1, m_t, alpha_t_, op.r_w1, path.begin, path.roll_form1,
                           path.roll_ff1, clearance1, warnings_);
  gear_ = memberGeometry("gear", g2, m2, m_t, alpha_t_, op.r_w2, line_of_action_ - path.end,
                         path.roll_form2, path.roll_ff2, clearance2, warnings_);

  if (spec.pinion_speed_rpm) {
    const double n1 = *spec.pinion_speed_rpm;
    if (!std::isfinite(n1) || n1 < 0.0) {
      throw InputError("pair.speed_rpm", fmt::format("{:g}", n1), "must be finite and >= 0");
    }
    mesh_frequency_ = g1.teeth * n1 / 60.0;
    if (auto note = speedPlausibilityNote(n1, "pair.speed_rpm"); !note.empty())
      warnings_.push_back(std::move(note));
  }
} catch (const InputError& error) {
  const auto notes = plausibilityNotes(spec);
  if (notes.empty()) throw;
  throw InputError(error.key(), error.value(), error.allowed() + "; note: " + notes.front());
}

namespace {

/// `text` with every path "from.…" that starts a word (not "x.from.…" nor "xfrom.…") renamed.
std::string renamePaths(const std::string& text, const std::string& from, const std::string& to) {
  const std::string head = from + ".";
  std::string out;
  std::size_t at = 0;
  for (std::size_t hit = text.find(head); hit != std::string::npos;
       hit = text.find(head, hit + 1)) {
    const bool starts_word =
        hit == 0 || !(std::isalnum(static_cast<unsigned char>(text[hit - 1])) ||
                      text[hit - 1] == '_' || text[hit - 1] == '.');
    if (!starts_word) continue;
    out += text.substr(at, hit - at) + to + ".";
    at = hit + head.size();
  }
  return out + text.substr(at);
}

std::string renamed(std::string text, const PairKeyNames& names) {
  if (text == "pinion" || text == "gear" || text == "pair") {
    return text == "pinion" ? names.pinion : text == "gear" ? names.gear : names.pair;
  }
  // One pass per name on the original spellings: a renamed path never contains another's head
  // at a word start ("gears.z1." does not start with "gear.").
  text = renamePaths(text, "pinion", names.pinion);
  text = renamePaths(text, "gear", names.gear);
  return renamePaths(text, "pair", names.pair);
}

}  // namespace

InputError renamedForPair(const InputError& error, const PairKeyNames& names) {
  return InputError(renamed(error.key(), names), error.value(), renamed(error.allowed(), names));
}

GearPair makeGearPair(const GearPairSpec& spec, const std::string& pinion_key,
                      const std::string& gear_key, const std::string& pair_key) {
  try {
    return GearPair(spec);
  } catch (const InputError& error) {
    throw renamedForPair(error, {pinion_key, gear_key, pair_key});
  }
}

}  // namespace geardyn
