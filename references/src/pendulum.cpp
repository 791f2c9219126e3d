// Closed-form pendulum solutions (PHYSICS.md §2; DLMF §22.19(i), §22.7, §19.25; Byrd & Friedman 1971).
//
// Accuracy notes (measured against tests/data/pendulum_reference.csv, see the test for numbers):
//  * The complementary modulus k' is never formed as sqrt(1 - k^2): for libration k' = cos(theta0/2),
//    for rotation k' = sqrt((v0 - 2 omega)(v0 + 2 omega))/v0. Near the separatrix 1 - k^2 is tiny and
//    would carry a relative error eps/k'^2 (about 1e-10 at theta0 = 179.9 deg).
//  * GSL's elljac takes m = k^2 and forms sqrt(1 - m) itself, which re-introduces that error. For
//    k' < kLandenThreshold we therefore apply the descending Landen (Gauss) transformation
//    (DLMF 22.7.1-22.7.3; detail::jacobi in elliptic.cpp, shared with elastica.cpp), whose new
//    complementary modulus k1' = 2 sqrt(k')/(1 + k') is computed from
//    the accurate k', until k' is moderate; only then is GSL called.
//  * K(k) = R_F(0, k'^2, 1) (DLMF 19.25.1) with the accurate k'^2. This is the same Carlson integral
//    gsl_sf_ellint_Kcomp evaluates, but Kcomp takes k and recomputes 1 - k^2.
//  * The phase u is reduced modulo 2K (sn, cn change sign, dn is unchanged: DLMF 22.4.3), which
//    makes GSL work on |u| <= K and gives the rotation angle without the atan2 tie at u = (2j+1) 2K.
//  * Libration angle: tan(theta/2) = (k/k') cn(u) (from sin(theta/2) = k cd u and
//    cos(theta/2) = k' nd u, DLMF 22.6.1), evaluated as 2 atan2(k cn, k'). Unlike 2 asin(k cd u) it
//    stays well conditioned at the turning points when theta0 -> pi (asin' -> infinity near 1).
#include "rodvv/references/pendulum.hpp"

#include <cmath>
#include <numbers>

#include "elliptic.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::references {
namespace {

using std::numbers::pi;

using detail::complete_k;
using detail::jacobi;
using detail::Jacobi;
using detail::reduce_half_period;

// Modulus and accurate complementary modulus of the libration, k = sin(theta0/2), k' = cos(theta0/2).
struct Moduli {
  double k;
  double kp;
};

Moduli libration_moduli(const Libration& motion) {
  require_positive("omega", motion.omega);
  require_open_interval("theta0", motion.theta0, 0.0, pi);
  return {std::sin(0.5 * motion.theta0), std::cos(0.5 * motion.theta0)};
}

// Rotation modulus k~ = 2 omega / v0 and k~' = sqrt((v0 - 2 omega)(v0 + 2 omega)) / v0.
Moduli rotation_moduli(const Rotation& motion) {
  require_positive("omega", motion.omega);
  const double two_omega = 2.0 * motion.omega;
  require_greater("v0", motion.v0, two_omega);
  const double kp = std::sqrt((motion.v0 - two_omega) * (motion.v0 + two_omega)) / motion.v0;
  return {two_omega / motion.v0, kp};
}

template <class... Fs>
struct Overloaded : Fs... {
  using Fs::operator()...;
};
template <class... Fs>
Overloaded(Fs...) -> Overloaded<Fs...>;

}  // namespace

// ---------------------------------------------------------------------------------------------
// Libration (PHYSICS.md §2.1): sin(theta/2) = k cd(omega t), theta' = -2 k omega k' sd(omega t).
PendulumState libration_state(const Libration& motion, double t) {
  const auto [k, kp] = libration_moduli(motion);
  require_finite("t", t);
  const double K = complete_k(kp);
  const auto [r, j] = reduce_half_period(motion.omega * t, K);
  const Jacobi f = jacobi(r, k, kp);
  // sn(u) = (-1)^j sn(r), cn(u) = (-1)^j cn(r), dn(u) = dn(r)  (DLMF 22.4.3: shift by 2K).
  const double sign = std::fmod(j, 2.0) == 0.0 ? 1.0 : -1.0;
  const double sn = sign * f.sn;
  const double cn = sign * f.cn;
  // tan(theta/2) = (k/k') cn(u); k' > 0 keeps theta/2 in (-pi/2, pi/2).
  const double theta = 2.0 * std::atan2(k * cn, kp);
  // theta' = -2 omega k k' sn/dn: negative right after release (PHYSICS.md §2.4 table).
  const double theta_dot = -2.0 * motion.omega * k * kp * sn / f.dn;
  return {theta, theta_dot};
}

double libration_period(const Libration& motion) {
  const auto moduli = libration_moduli(motion);
  return 4.0 * complete_k(moduli.kp) / motion.omega;
}

double libration_energy(const Libration& motion) {
  libration_moduli(motion);  // validation only
  return -motion.omega * motion.omega * std::cos(motion.theta0);
}

// ---------------------------------------------------------------------------------------------
// Rotation (PHYSICS.md §2.2): theta = 2 am(v0 t/2, k~), theta' = v0 dn(v0 t/2, k~).
// am(j 2K + r) = j pi + am(r) (DLMF 22.16.2), and for |r| <= K, am(r) = atan2(sn r, cn r) with
// cn r >= 0, so theta is continuous and unwrapped; there is no round() tie at u = (2j+1) 2K.
PendulumState rotation_state(const Rotation& motion, double t) {
  const auto [k, kp] = rotation_moduli(motion);
  require_finite("t", t);
  const double K = complete_k(kp);
  const auto [r, j] = reduce_half_period(0.5 * motion.v0 * t, K);
  const Jacobi f = jacobi(r, k, kp);
  const double theta = 2.0 * pi * j + 2.0 * std::atan2(f.sn, f.cn);
  return {theta, motion.v0 * f.dn};
}

double rotation_period(const Rotation& motion) {
  const auto moduli = rotation_moduli(motion);
  return 4.0 * complete_k(moduli.kp) / motion.v0;
}

double rotation_energy(const Rotation& motion) {
  rotation_moduli(motion);  // validation only
  return 0.5 * motion.v0 * motion.v0 - motion.omega * motion.omega;
}

// ---------------------------------------------------------------------------------------------
// Separatrix (PHYSICS.md §2.3): theta = 2 asin(tanh(omega t)) = 2 gd(omega t) = 2 atan(sinh(omega t))
// (DLMF 4.23.39-4.23.41). The atan(sinh) form is accurate in relative terms for small omega t and
// in absolute terms as theta -> pi (sinh -> inf gives exactly pi/2); asin(tanh) would lose digits
// where tanh -> 1 and 4 atan(e^x) - pi cancels near t = 0.
PendulumState separatrix_state(const Separatrix& motion, double t) {
  require_positive("omega", motion.omega);
  require_finite("t", t);
  const double x = motion.omega * t;
  return {2.0 * std::atan(std::sinh(x)), 2.0 * motion.omega / std::cosh(x)};
}

double separatrix_energy(const Separatrix& motion) {
  require_positive("omega", motion.omega);
  return motion.omega * motion.omega;
}

// ---------------------------------------------------------------------------------------------
PendulumState exact_state(const PendulumMotion& motion, double t) {
  return std::visit(Overloaded{[t](const Libration& m) { return libration_state(m, t); },
                               [t](const Rotation& m) { return rotation_state(m, t); },
                               [t](const Separatrix& m) { return separatrix_state(m, t); }},
                    motion);
}

PendulumState initial_state(const PendulumMotion& motion) {
  return std::visit(Overloaded{[](const Libration& m) {
                                 libration_moduli(m);
                                 return PendulumState{m.theta0, 0.0};
                               },
                               [](const Rotation& m) {
                                 rotation_moduli(m);
                                 return PendulumState{0.0, m.v0};
                               },
                               [](const Separatrix& m) {
                                 require_positive("omega", m.omega);
                                 return PendulumState{0.0, 2.0 * m.omega};
                               }},
                    motion);
}

double energy(const PendulumMotion& motion) {
  return std::visit(Overloaded{[](const Libration& m) { return libration_energy(m); },
                               [](const Rotation& m) { return rotation_energy(m); },
                               [](const Separatrix& m) { return separatrix_energy(m); }},
                    motion);
}

std::optional<double> period(const PendulumMotion& motion) {
  return std::visit(Overloaded{[](const Libration& m) -> std::optional<double> {
                                 return libration_period(m);
                               },
                               [](const Rotation& m) -> std::optional<double> {
                                 return rotation_period(m);
                               },
                               [](const Separatrix& m) -> std::optional<double> {
                                 require_positive("omega", m.omega);
                                 return std::nullopt;
                               }},
                    motion);
}

double omega_of(const PendulumMotion& motion) {
  return std::visit([](const auto& m) { return m.omega; }, motion);
}

}  // namespace rodvv::references
