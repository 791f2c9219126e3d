#include "rodvv/references/capstan.hpp"

#include <cmath>

#include "bracketed_root.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::references {

CapstanSolution capstan_with_bending(const Capstan& capstan) {
  require_positive("B", capstan.B);
  require_positive("R", capstan.R);
  require_positive("wrap_angle", capstan.wrap_angle);
  require_positive("pull_tension", capstan.pull_tension);
  if (!(std::isfinite(capstan.mu) && capstan.mu >= 0.0))
    throw InputError("mu", "invalid parameter 'mu' = " + format_value(capstan.mu) + ": must be finite and >= 0");
  const double mu = capstan.mu, beta = capstan.B / (2.0 * capstan.R * capstan.R), T_pull = capstan.pull_tension;
  if (!(beta < 2.0 * T_pull))
    throw InputError("B", "invalid parameter 'B' = " + format_value(capstan.B) + ": B / (2 R^2) = " +
                              format_value(beta) + " must be below 2 T_pull = " + format_value(2.0 * T_pull) +
                              " (a stiffer rod does not reach the cylinder's curvature: it does not wrap)");
  // A span of tail tension T leaves the cylinder turned by psi from its tail, cos psi = 1 - beta / T;
  // T sin psi = sqrt(2 beta T - beta^2) is its end's point contact force.
  const auto turn = [&](double T) { return std::acos(1.0 - beta / T); };
  const auto end_force = [&](double T) { return std::sqrt(std::max(0.0, 2.0 * beta * T - beta * beta)); };
  const double psi_pull = turn(T_pull);
  // The tension entering the contact on the pulling side, and with e^{mu phi_c} on the holding side.
  const double pulled_in = T_pull - beta + mu * end_force(T_pull);
  if (!(pulled_in > 0.0))
    throw InputError("B", "invalid parameter 'B' = " + format_value(capstan.B) + ": the tension entering the contact "
                              "on the pulling side, T_pull - B / (2 R^2) + mu P_pull = " + format_value(pulled_in) +
                              ", must be > 0 (the rod is too stiff for the pull to hold it on the cylinder)");
  const auto mismatch = [&](double T_hold) {
    const double held_in = T_hold - beta - mu * end_force(T_hold);
    return held_in - pulled_in * std::exp(mu * (capstan.wrap_angle - turn(T_hold) - psi_pull));
  };
  // held_in vanishes at T_lo = beta (1 + mu^2 + mu sqrt(1 + mu^2)) and grows above it, where the
  // mismatch is -pulled_in e^{..} < 0; the mismatch grows like T_hold, so doubling brackets a root.
  const double T_lo = beta * (1.0 + mu * mu + mu * std::sqrt(1.0 + mu * mu));
  double T_hi = std::max(2.0 * T_lo, T_pull * std::exp(mu * capstan.wrap_angle) + beta);
  double f_hi = mismatch(T_hi);
  for (int doubling = 0; doubling < 200 && !(f_hi > 0.0); ++doubling) f_hi = mismatch(T_hi *= 2.0);
  CapstanSolution solution;
  solution.hold_tension = detail::solve_bracketed("capstan_with_bending", mismatch, T_lo, T_hi, mismatch(T_lo), f_hi);
  solution.hold_turn = turn(solution.hold_tension);
  solution.pull_turn = psi_pull;
  solution.contact_angle = capstan.wrap_angle - solution.hold_turn - solution.pull_turn;
  solution.hold_end_force = end_force(solution.hold_tension);
  solution.pull_end_force = end_force(T_pull);
  solution.hold_offset = capstan.B / (2.0 * capstan.R * solution.hold_tension);
  solution.pull_offset = capstan.B / (2.0 * capstan.R * T_pull);
  if (!(solution.contact_angle > 0.0))
    throw InputError("wrap_angle", "invalid parameter 'wrap_angle' = " + format_value(capstan.wrap_angle) +
                                       ": the free spans alone turn by " +
                                       format_value(solution.hold_turn + solution.pull_turn) +
                                       " rad; the wrap must exceed it for the rod to touch the cylinder");
  return solution;
}

}  // namespace rodvv::references
