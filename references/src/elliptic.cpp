#include "elliptic.hpp"

#include <gsl/gsl_mode.h>
#include <gsl/gsl_sf_elljac.h>
#include <gsl/gsl_sf_ellint.h>
#include <gsl/gsl_sf_result.h>

#include <cmath>

#include "gsl_checked.hpp"

namespace rodvv::references::detail {
namespace {

double carlson_rf(double x, double y, double z) {
  gsl_handler_off();
  gsl_sf_result result{};
  check_gsl(gsl_sf_ellint_RF_e(x, y, z, GSL_PREC_DOUBLE, &result), "gsl_sf_ellint_RF_e");
  return result.val;
}

double carlson_rd(double x, double y, double z) {
  gsl_handler_off();
  gsl_sf_result result{};
  check_gsl(gsl_sf_ellint_RD_e(x, y, z, GSL_PREC_DOUBLE, &result), "gsl_sf_ellint_RD_e");
  return result.val;
}

}  // namespace

Jacobi jacobi(double u, double k, double kp) {
  if (kp < kLandenThreshold && kp > 0.0) {
    // Descending Landen transformation, DLMF 22.7.1-22.7.3 (Byrd & Friedman 163.01):
    //   k1 = (1 - k')/(1 + k'),  sn(u,k) = (1 + k1) sn(v,k1) / (1 + k1 sn^2(v,k1)),  v = u/(1 + k1),
    //   cn(u,k) = cn(v,k1) dn(v,k1) / (1 + k1 sn^2),   dn(u,k) = (1 - k1 sn^2)/(1 + k1 sn^2).
    const double one_plus_kp = 1.0 + kp;
    const double k1 = (1.0 - kp) / one_plus_kp;
    const double one_minus_k1 = 2.0 * kp / one_plus_kp;  // exact form of 1 - k1: no cancellation
    const double kp1 = 2.0 * std::sqrt(kp) / one_plus_kp;
    const Jacobi j = jacobi(u / (1.0 + k1), k1, kp1);
    const double k1_sn2 = k1 * j.sn * j.sn;
    const double denominator = 1.0 + k1_sn2;
    // 1 - k1 sn^2 = (1 - k1) + k1 cn^2: avoids the cancellation where k1 sn^2 -> 1 (dn -> k').
    return {(1.0 + k1) * j.sn / denominator, j.cn * j.dn / denominator,
            (one_minus_k1 + k1 * j.cn * j.cn) / denominator};
  }
  Jacobi j{};
  gsl_handler_off();
  check_gsl(gsl_sf_elljac_e(u, k * k, &j.sn, &j.cn, &j.dn), "gsl_sf_elljac_e");
  return j;
}

double complete_k(double kp) { return carlson_rf(0.0, kp * kp, 1.0); }

double complete_e(double kp) {
  // DLMF 19.25.1: E(k) = k'^2/3 [R_D(0, k'^2, 1) + R_D(0, 1, k'^2)]: two positive terms, no
  // cancellation as k -> 1 (unlike K - k^2/3 R_D(0, k'^2, 1)).
  const double kp2 = kp * kp;
  return kp2 / 3.0 * (carlson_rd(0.0, kp2, 1.0) + carlson_rd(0.0, 1.0, kp2));
}

double complete_k_minus_e(double k, double kp) { return k * k / 3.0 * carlson_rd(0.0, kp * kp, 1.0); }

double incomplete_f(double sin_phi, double cos_phi, double delta) {
  if (sin_phi == 0.0) return 0.0;
  return sin_phi * carlson_rf(cos_phi * cos_phi, delta * delta, 1.0);
}

double incomplete_e(double sin_phi, double cos_phi, double delta, double k) {
  if (sin_phi == 0.0) return 0.0;
  const double c2 = cos_phi * cos_phi;
  const double d2 = delta * delta;
  return sin_phi * carlson_rf(c2, d2, 1.0) -
         k * k * sin_phi * sin_phi * sin_phi / 3.0 * carlson_rd(c2, d2, 1.0);
}

Reduced reduce_half_period(double u, double K) {
  const double two_k = 2.0 * K;
  const double j = std::floor((u + K) / two_k);
  return {std::fma(-j, two_k, u), j};
}

JacobiEpsilon jacobi_epsilon(double u, double k, double kp, double K, double E) {
  const auto [r, j] = reduce_half_period(u, K);
  const Jacobi f = jacobi(r, k, kp);
  // For |r| <= K: am r in [-pi/2, pi/2], sin(am r) = sn r, cos(am r) = cn r >= 0 (clamped against
  // rounding), and delta = dn r.
  const double eps_r = incomplete_e(f.sn, std::fmax(f.cn, 0.0), f.dn, k);
  const double sign = std::fmod(j, 2.0) == 0.0 ? 1.0 : -1.0;
  return {sign * f.sn, sign * f.cn, f.dn, 2.0 * j * E + eps_r};
}

}  // namespace rodvv::references::detail
