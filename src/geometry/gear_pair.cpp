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

// A function-try-block: an error caused by an implausible value (a length in mm) says so.
GearPair::GearPair(const GearPairSpec& spec) try : spec_(spec) {
  const GearSpec& g1 = spec.pinion;
  const GearSpec& g2 = spec.gear;
  g1.validate("pinion");
  g2.validate("gear");
  warnings_ = plausibilityNotes(spec);

  // --- the two members must be cut by the same rack --------------------------------------
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

  // --- operating centre distance and pressure angle --------------------------------------
  // Zero-backlash mesh of the profile-shifted teeth (ISO 21771 eq. 61):
  // inv α_wt = inv α_t + 2 tan α_n (x₁ + x₂) / (z₁ + z₂).
  const double inv_tight = involute(alpha_t_) + 2.0 * std::tan(alpha_n) *
                                                    (g1.profile_shift + g2.profile_shift) /
                                                    (g1.teeth + g2.teeth);
  if (inv_tight <= 0.0) {
    throw InputError("gear.profile_shift", fmt::format("{:g}", g2.profile_shift),
                     "the sum of the profile shifts is so negative that the teeth cannot mesh "
                     "without overlapping at any centre distance");
  }
  a_tight_ = (m1.rb + m2.rb) / std::cos(inverseInvolute(inv_tight));
  if (spec.centre_distance) {
    a_w_ = *spec.centre_distance;
    if (!std::isfinite(a_w_) || a_w_ <= m1.rb + m2.rb) {
      throw InputError(
          "pair.centre_distance", fmt::format("{:g} m", a_w_),
          fmt::format("must exceed the sum of the base radii r_b1 + r_b2 = {}", mm(m1.rb + m2.rb)));
    }
  } else {
    a_w_ = a_tight_;
  }
  alpha_wt_ = std::acos((m1.rb + m2.rb) / a_w_);

  // Backlash on the operating pitch circle: pitch minus the two tooth thicknesses there.
  const double r_w1 = m1.rb / std::cos(alpha_wt_);
  const double r_w2 = m2.rb / std::cos(alpha_wt_);
  j_wt_ = 2.0 * kPi * r_w1 / g1.teeth - toothThicknessAt(m1, alpha_t_, r_w1) -
          toothThicknessAt(m2, alpha_t_, r_w2);
  j_bn_ = j_wt_ * std::cos(alpha_wt_) * std::cos(beta_b_);
  if (j_wt_ < -1e-9 * m_n) {
    throw InputError("pair.centre_distance", fmt::format("{:g} m", a_w_),
                     fmt::format("must be at least the tight-mesh centre distance {} of these "
                                 "profile shifts: closer, the teeth would overlap",
                                 mm(a_tight_)));
  }

  // --- tip clearance, path of contact, interference ---------------------------------------
  const auto check_clearance = [&](const char* name, double ra, double rf_mate) {
    const double clearance = a_w_ - ra - rf_mate;
    if (clearance < 0.0) {
      throw InputError("pair.centre_distance", fmt::format("{:g} m", a_w_),
                       fmt::format("the {} tip circle (r_a = {}) reaches the mate's root circle "
                                   "(r_f = {}): tip clearance {}",
                                   name, mm(ra), mm(rf_mate), mm(clearance)));
    }
    return clearance;
  };
  pinion_.tip_clearance = check_clearance("pinion", m1.ra, m2.rf);
  gear_.tip_clearance = check_clearance("gear", m2.ra, m1.rf);

  line_of_action_ = a_w_ * std::sin(alpha_wt_);
  // Roll distances along the line of action: pinion quantities from T₁, gear ones from T₂.
  const double rho_a1 = std::sqrt(m1.ra * m1.ra - m1.rb * m1.rb);  // T₁ → pinion tip point
  const double rho_a2 = std::sqrt(m2.ra * m2.ra - m2.rb * m2.rb);  // T₂ → gear tip point
  const double roll_form1 = rackFormRoll(g1, m1, alpha_t_);
  const double roll_form2 = rackFormRoll(g2, m2, alpha_t_);
  // Roll distance of the true form circle r_Ff (where the profile becomes involute): the end of
  // the rack's straight flank, or, with undercut, where the fillet cuts the involute back
  // (geometry/rack_generation.h). Contact on the involutes cannot begin below it.
  const auto form_roll = [](const GearSpec& g, const MemberRadii& m) {
    const double r_ff = trueFormRadius(generatingRack(g));
    return std::sqrt(std::max(0.0, r_ff * r_ff - m.rb * m.rb));
  };
  const double roll_ff1 = form_roll(g1, m1);
  const double roll_ff2 = form_roll(g2, m2);
  // The mate's tip meets the line of action at line_of_action − ρ_a(mate) from a member's T.
  // Without undercut, closer to T than the form point the mate's tip would sweep material the
  // generating rack left standing: tip-root interference (error). With undercut the rack cut
  // beyond T and the fillet cuts the involute back down to r_Ff: a mate tip reaching below r_Ff
  // passes through the undercut, the involutes touch only from r_Ff (warning with the numbers;
  // whether the tip clears the undercut fillet is not checked), unless it reaches further
  // beyond T than the rack's flank end did (error, as before).
  const auto check_interference = [&](const char* name, const char* mate, const GearSpec& mate_spec,
                                      double mate_tip_roll, double roll_form, double roll_ff,
                                      const MemberRadii& m) {
    if (mate_tip_roll < roll_form - 1e-12 * m.r) {
      // Beyond T (undercut) the tip follows the line of action further than the rack's flank
      // end: it sweeps deeper than the rack cut the undercut.
      const std::string reach =
          roll_form >= 0.0
              ? fmt::format(
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
  };
  const double gear_tip_from_t1 = line_of_action_ - rho_a2;
  const double pinion_tip_from_t2 = line_of_action_ - rho_a1;
  const bool into_undercut1 =
      check_interference("pinion", "gear", g2, gear_tip_from_t1, roll_form1, roll_ff1, m1);
  const bool into_undercut2 =
      check_interference("gear", "pinion", g1, pinion_tip_from_t2, roll_form2, roll_ff2, m2);
  const double contact_begin = std::max(gear_tip_from_t1, roll_ff1);                    // from T₁
  const double contact_end = line_of_action_ - std::max(pinion_tip_from_t2, roll_ff2);  // from T₁
  // ε_α the uncut involutes would give (contact from the tips, or from T): for the warning.
  const double uncut_length =
      (line_of_action_ - std::max(pinion_tip_from_t2, 0.0)) - std::max(gear_tip_from_t1, 0.0);
  const auto warn_undercut_contact = [&](const char* name, const char* mate, double mate_tip_roll,
                                         double roll_ff, const MemberRadii& m) {
    const std::string where =
        mate_tip_roll >= 0.0
            ? fmt::format("the {} flank at d = {}", name, mm(2.0 * std::hypot(m.rb, mate_tip_roll)))
            : fmt::format("{} beyond the {} base-circle tangent point on the line of action",
                          mm(-mate_tip_roll), name);
    warnings_.push_back(fmt::format(
        "the {} tip reaches {}, below the true form diameter d_Ff = {} of the {} undercut flank: "
        "the involutes touch only from d_Ff, which shortens the path of contact (transverse "
        "contact ratio {:.4f}, against {:.4f} on the uncut involute); the tip passes through the "
        "undercut, its clearance to the fillet is not checked",
        mate, where, mm(2.0 * std::hypot(m.rb, roll_ff)), name,
        (contact_end - contact_begin) / p_bt_, uncut_length / p_bt_));
  };
  if (into_undercut1) warn_undercut_contact("pinion", "gear", gear_tip_from_t1, roll_ff1, m1);
  if (into_undercut2) warn_undercut_contact("gear", "pinion", pinion_tip_from_t2, roll_ff2, m2);
  path_length_ = contact_end - contact_begin;
  if (spec.driver == Driver::kPinion) {
    path_start_ = contact_begin;  // a driving pinion meets the gear tip first
    path_end_ = contact_end;
  } else {
    path_start_ = contact_end;
    path_end_ = contact_begin;
  }

  // --- contact ratios ----------------------------------------------------------------------
  eps_alpha_ = path_length_ / p_bt_;
  face_width_ = std::min(g1.face_width, g2.face_width);
  eps_beta_ = face_width_ * std::sin(beta) / (kPi * m_n);
  if (spec.centre_distance && eps_alpha_ + eps_beta_ < 1.0) {
    // The centre distance the user gave pulls the teeth out of reach of each other.
    throw InputError(
        "pair.centre_distance", fmt::format("{:g} m", a_w_),
        fmt::format("too large for these gears: the path of contact is {} long (contact ratio "
                    "{:.4g} < 1), the tip circles r_a1 + r_a2 = {} leave the teeth out of reach; "
                    "the tight-mesh centre distance is {}",
                    mm(path_length_), eps_alpha_ + eps_beta_, mm(m1.ra + m2.ra), mm(a_tight_)));
  }
  if (eps_alpha_ + eps_beta_ < 1.0) {
    throw InputError(
        "pinion, gear", fmt::format("contact ratio {:.6g}", eps_alpha_ + eps_beta_),
        fmt::format("the total contact ratio must be at least 1 (transverse {:.6g}, overlap "
                    "{:.6g}): one tooth pair leaves contact before the next one enters, so the "
                    "pair cannot mesh continuously; raise the addendum, the number of teeth, the "
                    "face width or the helix angle{}",
                    eps_alpha_, eps_beta_,
                    into_undercut1 || into_undercut2
                        ? fmt::format(" (the undercut, which starts the involute at the true "
                                      "form circle, shortens the path of contact: ε_α would be "
                                      "{:.6g} on the uncut involute; profile shift avoids it)",
                                      uncut_length / p_bt_)
                        : std::string()));
  }
  if (eps_alpha_ < 1.0) {
    warnings_.push_back(fmt::format(
        "transverse contact ratio {:.4f} < 1: continuous meshing relies on the overlap ratio "
        "{:.4f}",
        eps_alpha_, eps_beta_));
  }

  // --- per member: radii, form circle, undercut, tip thickness, mass --------------------------
  const auto fill_member = [&](const char* name, const GearSpec& g, const MemberRadii& m,
                               double r_w, double roll_sap, double roll_form, double roll_ff,
                               GearGeometry& out) {
    out.transverse_module = m_t;
    out.pitch_radius = m.r;
    out.base_radius = m.rb;
    out.tip_radius = m.ra;
    out.root_radius = m.rf;
    out.operating_pitch_radius = r_w;
    // Start of active profile: where the path of contact begins on this member's flank.
    out.active_profile_start_radius = std::hypot(m.rb, roll_sap);
    out.undercut = roll_form < -1e-12 * m.r;
    out.form_radius = std::hypot(m.rb, roll_ff);
    if (out.undercut) {
      const double z_min = 2.0 * (g.rackStraightFlankDepth() / g.normal_module - g.profile_shift) *
                           std::cos(beta) / std::pow(std::sin(alpha_t_), 2);
      warnings_.push_back(fmt::format(
          "{} is undercut ({} teeth < {:.2f}, the limit for x = {:g}): the involute is cut away "
          "below the true form diameter d_Ff = {} (base circle d_b = {}); start of active "
          "profile d_Nf = {}",
          name, g.teeth, z_min, g.profile_shift, mm(2.0 * out.form_radius), mm(2.0 * m.rb),
          mm(2.0 * out.active_profile_start_radius)));
    }
    out.tip_thickness_normal = m.s_an;
    if (out.tip_thickness_normal < kThinTipFraction * m_n) {
      warnings_.push_back(
          fmt::format("{}: tip thickness {} is below 0.2 m_n = {} (thin, pointed tip)", name,
                      mm(out.tip_thickness_normal), mm(kThinTipFraction * m_n)));
    }
    const GearBodyMass body = gearBodyMass(g);
    out.mass = body.mass;
    out.polar_inertia = body.polar_inertia;
    out.diametral_inertia = body.diametral_inertia;
  };
  fill_member("pinion", g1, m1, r_w1, contact_begin, roll_form1, roll_ff1, pinion_);
  fill_member("gear", g2, m2, r_w2, line_of_action_ - contact_end, roll_form2, roll_ff2, gear_);

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
