// Sliding sleeve and elastica arm scale (PHYSICS.md §6). See sleeve.hpp for the setting.
//
// One free arm (clamp angle theta0, tip angle beta, both below the horizontal) in the half-angle
// variables a = (pi/2 - theta0)/2 and b = (pi/2 - beta)/2, 0 < b < a, c = a - b = (beta - theta0)/2:
//   modulus k = cos b, complementary modulus k' = sin b (accurate for beta -> pi/2);
//   lambda l = K(k) - F(psi0, k) = F(chi, k) by the addition theorem F(psi0) + F(chi) = K for
//   tan(psi0) tan(chi) = 1/k' (DLMF 19.11.1 with F(theta) = K), where
//     sin chi = sqrt(sin(a + b) sin c) / (sin a cos b),  cos chi = tan b / tan a,
//     Delta(chi) = sqrt(1 - k^2 sin^2 chi) = sin b / sin a,
//   (PHYSICS.md §3.5 and elastica.cpp are a = pi/4); no cancellation for small or large l.
//   lambda x = 2 k cos psi0 = 2 sqrt(sin(a + b) sin c)    (= sqrt(2 (sin beta - sin theta0)));
//   lambda w = lambda l - 2 [E(k) - E(psi0, k)],  E(k) - E(psi0, k) = E(chi, k) - k^2 sin chi sin psi0
//   (DLMF 19.11.2 with E(theta) = E), sin psi0 = cos a / cos b.
// The root variable is b when the tip is far from the clamp angle (b < a/2) and c otherwise, so that
// both pi/2 - beta and beta - theta0 come out with small relative errors (as elastica.cpp does for
// phi_L and pi/2 - phi_L).
#include "rodvv/references/sleeve.hpp"

#include <boost/math/tools/roots.hpp>
#include <boost/math/tools/toms748_solve.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>

#include "bracketed_root.hpp"
#include "elliptic.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/references/elastica.hpp"

namespace rodvv::references {
namespace {

using detail::solve_bracketed;
using std::numbers::pi;

// pi/2 = kHalfPiHi + kHalfPiLo: the low part keeps pi/2 - theta0 accurate near theta0 -> pi/2.
constexpr double kHalfPiHi = 0.5 * pi;
constexpr double kHalfPiLo = 6.123233995736766036e-17;
// Smallest b = (pi/2 - beta)/2 allowed: cos^2 chi + Delta^2 ~ b^2 stays above the lower argument
// limit of GSL's R_D (2/DBL_MAX^(2/3) ~ 6e-206). sqrt(P/B) l ~ ln(8/b) + ... <= ~230.
constexpr double kMinB = 1e-100;

// The scaled state of one arm (lengths times lambda = sqrt(P/B)).
struct ArmState {
  double scaled_length;  // lambda l
  double scaled_extent;  // lambda x
  double scaled_drop;    // lambda w
  double beta;           // tip angle
  double sin_beta;
};

// a = (pi/2 - theta0)/2 in (0, pi/2); b + c = a with b, c >= 0, one of them the exact variable.
struct HalfAngles {
  double theta0;
  double a;
  double b;
  double c;
  bool b_exact;
};

// sin chi, cos chi, Delta(chi) of the addition theorem (see the top of the file).
struct Amplitude {
  double sin_chi;
  double cos_chi;
  double delta;
  double root;  // sqrt(sin(a + b) sin c) = sqrt((sin beta - sin theta0)/2)
};

Amplitude amplitude(const HalfAngles& h) {
  const double sa = std::sin(h.a);
  const double ca = std::cos(h.a);
  const double sb = std::sin(h.b);
  const double cb = std::cos(h.b);
  const double root = std::sqrt(std::sin(h.a + h.b) * std::sin(h.c));
  return {root / (sa * cb), (sb * ca) / (cb * sa), sb / sa, root};
}

// lambda l = F(chi, k): the residual of the root solves (no E needed).
double scaled_length(const HalfAngles& h) {
  const Amplitude am = amplitude(h);
  return detail::incomplete_f(am.sin_chi, am.cos_chi, am.delta);
}

ArmState arm_state(const HalfAngles& h) {
  const Amplitude am = amplitude(h);
  const double ca = std::cos(h.a);
  const double k = std::cos(h.b);
  ArmState s{};
  s.scaled_length = detail::incomplete_f(am.sin_chi, am.cos_chi, am.delta);
  const double e_chi = detail::incomplete_e(am.sin_chi, am.cos_chi, am.delta, k);
  s.scaled_extent = 2.0 * am.root;
  // k^2 sin chi sin psi0 = cos^2 b sin chi cos a / cos b.
  s.scaled_drop = s.scaled_length - 2.0 * (e_chi - k * ca * am.sin_chi);
  if (h.b_exact) {
    s.beta = (kHalfPiHi - 2.0 * h.b) + kHalfPiLo;
    s.sin_beta = std::cos(2.0 * h.b);
  } else {
    s.beta = h.theta0 + 2.0 * h.c;
    s.sin_beta = std::sin(s.beta);
  }
  return s;
}

HalfAngles from_b(double theta0, double a, double b) { return {theta0, a, b, a - b, true}; }
HalfAngles from_c(double theta0, double a, double c) { return {theta0, a, a - c, c, false}; }

double half_complement(double theta0) { return 0.5 * ((kHalfPiHi - theta0) + kHalfPiLo); }

// The half angles of the arm whose scaled length is `target` > 0 (F decreasing in b, increasing in c).
HalfAngles solve_arm(double theta0, double target) {
  const double a = half_complement(theta0);
  const double mid = 0.5 * a;
  const double at_mid = scaled_length(from_b(theta0, a, mid)) - target;
  if (at_mid == 0.0) return from_b(theta0, a, mid);
  if (at_mid > 0.0) {
    // c in (0, a/2): the residual is -target at c = 0.
    const auto f = [&](double c) { return scaled_length(from_c(theta0, a, c)) - target; };
    return from_c(theta0, a, solve_bracketed("inclined arm (beta - theta0)", f, 0.0, mid, -target, at_mid));
  }
  // b in (kMinB, a/2): F ~ ln(8/b) for small b, so a geometric scan (factor 16) brackets the root
  // before TOMS 748 (which would otherwise bisect for long on (1e-40, a/2)).
  const auto f = [&](double b) { return scaled_length(from_b(theta0, a, b)) - target; };
  double hi = mid;
  double f_hi = at_mid;
  double lo = hi / 16.0;
  double f_lo = f(lo);
  while (!(f_lo > 0.0) && lo > kMinB) {
    hi = lo;
    f_hi = f_lo;
    lo = std::max(lo / 16.0, kMinB);
    f_lo = f(lo);
  }
  if (!(f_lo > 0.0))
    throw InputError("length", "invalid parameter 'length': sqrt(P/B) l = " + format_value(target) +
                                   " is too long, pi/2 - beta would be below 2e-100 (P l^2/B must be "
                                   "<= about 5e4)");
  if (f_hi == 0.0) return from_b(theta0, a, hi);
  return from_b(theta0, a, solve_bracketed("inclined arm (pi/2 - beta)", f, lo, hi, f_lo, f_hi));
}

InclinedArmTip make_tip(const InclinedArm& arm, double length, const ArmState& s) {
  const double lambda = std::sqrt(arm.P / arm.B);
  InclinedArmTip out;
  out.length = length;
  out.tip_angle = s.beta;
  out.extent = s.scaled_extent / lambda;
  out.drop = s.scaled_drop / lambda;
  out.exit_moment = std::sqrt(arm.P * arm.B) * s.scaled_extent;  // B lambda sqrt(2 (sb - st0)) = P x
  out.invariant = arm.P * s.sin_beta;
  return out;
}

void validate(const InclinedArm& arm) {
  require_open_interval("theta0", arm.theta0, -0.5 * pi, 0.5 * pi);
  require_positive("P", arm.P);
  require_positive("B", arm.B);
}

// The tip state without validation (callers validated); length >= 0.
InclinedArmTip arm_tip(const InclinedArm& arm, double length) {
  const double target = std::sqrt(arm.P / arm.B) * length;
  if (target == 0.0) {
    // l = 0: the tip is the exit, beta = theta0 (also when lambda l underflows).
    const double a = half_complement(arm.theta0);
    ArmState s = arm_state(from_c(arm.theta0, a, 0.0));
    s.scaled_length = 0.0;
    s.scaled_extent = 0.0;
    s.scaled_drop = 0.0;
    return make_tip(arm, length, s);
  }
  return make_tip(arm, length, arm_state(solve_arm(arm.theta0, target)));
}

void validate(const SleeveArm& arm) {
  require_positive("P", arm.P);
  require_positive("B", arm.B);
}

void validate(const ArmScale& s) {
  require_open_interval("alpha", s.alpha, -0.5 * pi, 0.5 * pi);
  require_positive("P1", s.P1);
  require_positive("P2", s.P2);
  require_positive("B", s.B);
  require_positive("L", s.L);
  require_positive("sleeve_length", s.sleeve_length);
  if (!(s.sleeve_length < s.L))
    throw InputError("sleeve_length", "invalid parameter 'sleeve_length' = " + format_value(s.sleeve_length) +
                                          ": a sleeve longer than the rod (must be in the open interval "
                                          "(0, L) = (0, " + format_value(s.L) + "))");
}

}  // namespace

// ---------------------------------------------------------------------------------------------
InclinedArmTip inclined_arm_tip(const InclinedArm& arm, double length) {
  validate(arm);
  require_non_negative("length", length);
  return arm_tip(arm, length);
}

// ---------------------------------------------------------------------------------------------
// §6.1: theta0 = 0 (a = pi/4) and sin(phi_tip) = S/P given: b and c follow without iteration.
SleeveEquilibrium sleeve_equilibrium(const SleeveArm& arm, double S) {
  validate(arm);
  if (!std::isfinite(S) || !(S > 0.0 && S < arm.P))
    throw InputError("S", "invalid parameter 'S' = " + format_value(S) +
                              ": the pull must be in the open interval (0, P) = (0, " + format_value(arm.P) +
                              ") (sin(phi_tip) = S/P < 1)");
  const double a = half_complement(0.0);
  const double ratio = S / arm.P;
  // phi_tip = 2c; c = asin(S/P)/2 is accurate below phi_tip = pi/4, and b = asin(sqrt((1 - S/P)/2))
  // (1 - S/P = (P - S)/P, no cancellation) above.
  const HalfAngles h = ratio < std::sqrt(0.5) ? from_c(0.0, a, 0.5 * std::asin(ratio))
                                              : from_b(0.0, a, std::asin(std::sqrt(0.5 * (arm.P - S) / arm.P)));
  const ArmState s = arm_state(h);
  const double lambda = std::sqrt(arm.P / arm.B);
  SleeveEquilibrium out;
  out.free_length = s.scaled_length / lambda;
  out.tip_angle = s.beta;
  out.exit_moment = std::sqrt(arm.P * arm.B) * s.scaled_extent;
  out.tension_jump = out.exit_moment * out.exit_moment / (2.0 * arm.B);
  out.invariant = S;
  out.tip_x = s.scaled_extent / lambda;
  out.tip_y = -s.scaled_drop / lambda;
  return out;
}

SleeveEquilibrium sleeve_equilibrium_for_length(const SleeveArm& arm, double free_length) {
  validate(arm);
  require_positive("free_length", free_length);
  const CantileverTip tip = cantilever_tip(TipLoadedCantilever{free_length, arm.B, arm.P});
  SleeveEquilibrium out;
  out.free_length = free_length;
  out.tip_angle = tip.phi_L;
  out.invariant = tip.H;                                         // P sin(phi_tip)
  out.tip_x = std::sqrt(2.0 * arm.B * tip.H) / arm.P;            // sqrt(2 B sin(phi_tip) / P)
  out.tip_y = -tip.w;
  out.exit_moment = arm.P * out.tip_x;                           // moment of the tip load at the exit
  out.tension_jump = out.exit_moment * out.exit_moment / (2.0 * arm.B);
  return out;
}

// ---------------------------------------------------------------------------------------------
// §6.2: f(l1) = P1 sin beta1(l1) - P2 sin beta2(l_free - l1), strictly increasing in l1.
ArmScaleEquilibrium arm_scale_equilibrium(const ArmScale& scale) {
  validate(scale);
  const InclinedArm arm1{scale.alpha, scale.P1, scale.B};
  const InclinedArm arm2{-scale.alpha, scale.P2, scale.B};
  const double free = scale.L - scale.sleeve_length;
  const auto f = [&](double l1) {
    return arm_tip(arm1, l1).invariant - arm_tip(arm2, free - l1).invariant;
  };
  double f_lo = 0.0;
  double f_hi = 0.0;
  try {
    f_lo = f(0.0);
    f_hi = f(free);
  } catch (const InputError& e) {
    // An arm as long as the whole free length is too long for the closed form: name L.
    throw InputError("L", "invalid parameter 'L' = " + format_value(scale.L) +
                              ": too long for the loads and stiffness (" + e.what() + ")");
  }
  const char* method = "arm scale equilibrium (l1)";
  if (!(f_lo < 0.0))
    throw ArmPulledIn(2, method,
                      std::string(method) + ": no equilibrium with both arms outside the sleeve: arm 2 is "
                          "pulled fully into the sleeve (P1 sin(alpha) >= P2 sin(beta2) even with l1 = 0; "
                          "residual " + format_value(f_lo) + ")",
                      f_lo);
  if (!(f_hi > 0.0))
    throw ArmPulledIn(1, method,
                      std::string(method) + ": no equilibrium with both arms outside the sleeve: arm 1 is "
                          "pulled fully into the sleeve (P1 sin(beta1) <= -P2 sin(alpha) even with l2 = 0; "
                          "residual " + format_value(f_hi) + ")",
                      f_hi);
  const double l1 = solve_bracketed(method, f, 0.0, free, f_lo, f_hi);
  const double l2 = free - l1;
  const InclinedArmTip t1 = arm_tip(arm1, l1);
  const InclinedArmTip t2 = arm_tip(arm2, l2);
  // Exits at -/+ d sleeve_length/2; arm 1 runs towards -x, arm 2 towards +x; drops are downward.
  const double half = 0.5 * scale.sleeve_length;
  const double cx = half * std::cos(scale.alpha);
  const double cy = half * std::sin(scale.alpha);
  ArmScaleEquilibrium out;
  out.arm1 = {l1, t1.tip_angle, t1.exit_moment, -cx - t1.extent, -cy - t1.drop};
  out.arm2 = {l2, t2.tip_angle, t2.exit_moment, cx + t2.extent, cy - t2.drop};
  out.axial_force = t1.invariant;
  out.sleeve_shift = l2 - l1;
  return out;
}

}  // namespace rodvv::references
