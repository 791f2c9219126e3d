#pragma once
// Closed-form solutions of the nonlinear pendulum  theta'' = -omega^2 sin(theta)
// (PHYSICS.md §2; DLMF §22.19(i); Byrd & Friedman 1971, formulas 121-125).
//
// Units: theta in radians, time t in the unit of 1/omega. Energy per unit (m l^2):
//   E = 1/2 theta'^2 - omega^2 cos(theta)    (minimum -omega^2 at rest hanging down).
// Conventions: GSL's gsl_sf_elljac_e takes the parameter m = k^2; its ellint functions take the
// modulus k (PHYSICS.md §2.5). GSL's abort handler is switched off and every status is checked: a
// failing status throws rodvv::SolverError; an invalid parameter throws rodvv::InputError.
//
// Three families of motion:
//  - Libration, released from rest at theta0 in (0, pi):  sin(theta/2) = k cd(omega t, k), k = sin(theta0/2).
//    The cd form avoids the cancellation in K - omega t at large t.
//  - Rotation (circulation), theta(0) = 0, theta'(0) = v0 > 2 omega:  theta = 2 am(v0 t / 2, 2 omega / v0).
//  - Separatrix, theta(0) = 0, theta'(0) = 2 omega (E = omega^2):  theta = 2 arcsin(tanh(omega t)).
#include <optional>
#include <variant>

namespace rodvv::references {

struct PendulumState {
  double theta = 0.0;      // [rad]
  double theta_dot = 0.0;  // [rad / time]
};

// Released from rest at theta0; requires omega > 0 and 0 < theta0 < pi.
struct Libration {
  double omega = 1.0;
  double theta0 = 0.5;
};

// theta(0) = 0, theta'(0) = v0; requires omega > 0 and v0 > 2 omega.
struct Rotation {
  double omega = 1.0;
  double v0 = 3.0;
};

// theta(0) = 0, theta'(0) = 2 omega; requires omega > 0. theta -> pi as t -> infinity.
struct Separatrix {
  double omega = 1.0;
};

using PendulumMotion = std::variant<Libration, Rotation, Separatrix>;

PendulumState libration_state(const Libration& motion, double t);
double libration_period(const Libration& motion);  // 4 K(k) / omega
double libration_energy(const Libration& motion);  // -omega^2 cos(theta0)

PendulumState rotation_state(const Rotation& motion, double t);  // theta is unwrapped (grows without bound)
double rotation_period(const Rotation& motion);  // time for one full turn, 4 K(2 omega / v0) / v0
double rotation_energy(const Rotation& motion);  // v0^2 / 2 - omega^2

PendulumState separatrix_state(const Separatrix& motion, double t);
double separatrix_energy(const Separatrix& motion);  // omega^2

// Dispatch over the three families. period() is empty for the separatrix (infinite period).
PendulumState exact_state(const PendulumMotion& motion, double t);
PendulumState initial_state(const PendulumMotion& motion);
double energy(const PendulumMotion& motion);
std::optional<double> period(const PendulumMotion& motion);
double omega_of(const PendulumMotion& motion);

}  // namespace rodvv::references
