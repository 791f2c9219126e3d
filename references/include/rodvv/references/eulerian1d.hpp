#pragma once
// Exact solutions for the 1-D reference-map elastic bar (ALGORITHMS.md §6.1, §6.3).
//
// Model: a bar of reference length L0 and density rho0 (mass per reference length) with stress
// sigma = kappa (F - 1), F = dx/dX. In material coordinates the motion x(X, t) obeys the LINEAR
// wave equation rho0 x_tt = kappa x_XX, c = sqrt(kappa / rho0), with free ends (F = 1) or a rigid
// wall; so d'Alembert solutions with F > 0 are exact solutions of the nonlinear Eulerian problem
//   xi_t + v xi_x = 0,  rho (v_t + v v_x) = sigma_x,  rho = rho0 xi_x  (rho F = rho0),
// where xi(x, t) is the inverse of x(., t) (the reference map). Sources: d'Alembert (1747); the
// impact of a bar on a rigid wall: Graff, "Wave Motion in Elastic Solids" (1975) §1.4, or
// Johnson, "Impact Strength of Materials" (1972) §1.
//
// Units: any consistent set; lengths in the unit of L0, time in L0 / c when rho0 = kappa = L0 = 1.
// Four motions:
//  - RigidTranslation: x = x_left0 + X + v t + a t^2 / 2 (a: a uniform body acceleration, gravity; the
//    bar stays unstressed: free fall).
//  - StandingWave (free-free): x = x_left0 + X + A cos(pi X / L0) cos(pi c t / L0); ends
//    x_left0 + A cos(pi c t/L0) and x_left0 + L0 - A cos(pi c t/L0); period 2 L0/c; needs A pi/L0 < 1.
//  - SqueezeRelease: a bar compressed uniformly to F0 (0 < F0 < 1), centred at `center`, released
//    from rest with free ends. With E the odd 2 L0-periodic square wave of height F0 - 1 and
//    P(y) = int_0^y E:  x = x_left0 + X + [P(X - ct) + P(X + ct)]/2,  v = c [E(X + ct) - E(X - ct)]/2,
//    F = 1 + [E(X - ct) + E(X + ct)]/2 in {F0, 1, 2 - F0}; the length is a triangle wave between
//    F0 L0 and (2 - F0) L0 with period 2 L0/c.
//  - BarrierImpact: an unstressed bar moving at v0 > 0 towards a rigid wall at x = wall (on its
//    right). It touches at t0 = (wall - x_left0 - L0)/v0 and stays in contact for 2 L0/c; the wall
//    force is rho0 c v0 (the stress -rho0 c v0 of the compressive front, strain v0/c); the bar leaves
//    unstressed with velocity -v0 (impulse 2 rho0 L0 v0, kinetic energy recovered). Needs v0 < c.
// Outside the solid the reference map is continued linearly with the end stretch, as the solver's
// initial data are; the velocity there is the end velocity.
#include <variant>

namespace rodvv::references {

struct BarMaterial {
  double rho0 = 1.0;
  double kappa = 1.0;
  double length = 1.0;  // L0
};

struct RigidTranslation {
  BarMaterial material;
  double x_left0 = 0.0;  // position of X = 0 at t = 0
  double velocity = 0.0;      // at t = 0
  double acceleration = 0.0;  // a uniform body acceleration (gravity along +x)
};

struct StandingWave {
  BarMaterial material;
  double x_left0 = 0.0;  // rest position of X = 0
  double amplitude = 0.02;
};

struct SqueezeRelease {
  BarMaterial material;
  double center = 0.0;
  double stretch0 = 0.1;  // F0
};

struct BarrierImpact {
  BarMaterial material;
  double x_left0 = 0.0;  // position of X = 0 at t = 0
  double velocity = 0.1;  // v0 > 0, towards the wall
  double wall = 1.0;      // >= x_left0 + L0
};

using BarMotion = std::variant<RigidTranslation, StandingWave, SqueezeRelease, BarrierImpact>;

// Eulerian fields at a fixed point x.
struct BarPoint {
  bool solid = false;    // 0 <= xi <= L0
  double xi = 0.0;       // reference map
  double velocity = 0.0;
  double stretch = 1.0;  // F (end stretch outside the solid)
  double density = 0.0;  // rho0 / F inside, 0 outside
};

struct BarEnds {
  double left = 0.0;   // x(0, t)
  double right = 0.0;  // x(L0, t)
};

struct ImpactSummary {
  double contact_start = 0.0;     // t0
  double contact_duration = 0.0;  // 2 L0 / c
  double wall_force = 0.0;        // rho0 c v0 during contact
  double impulse = 0.0;           // 2 rho0 L0 v0
  double rebound_velocity = 0.0;  // -v0
};

// Throws InputError naming the parameter: rho0, kappa, length > 0; finite positions; amplitude with
// |A| pi / L0 < 1; 0 < stretch0 < 1; 0 < velocity < c and wall >= x_left0 + L0 for the impact.
void validate(const BarMotion& motion);

double bar_wave_speed(const BarMaterial& material);  // c = sqrt(kappa / rho0)
double bar_mass(const BarMaterial& material);        // rho0 L0 = integral of rho dx
// kinetic + elastic (+ the body force's potential - rho0 L0 a x_centre for a falling bar), conserved; at t = 0
double bar_energy(const BarMotion& motion);
BarMaterial material_of(const BarMotion& motion);

// Lagrangian description at material point X in [0, L0] and time t >= 0.
double bar_position(const BarMotion& motion, double X, double t);
double bar_velocity(const BarMotion& motion, double X, double t);
double bar_stretch(const BarMotion& motion, double X, double t);  // one-sided (right) value at a jump
BarEnds bar_ends(const BarMotion& motion, double t);

// Eulerian description: x(., t) is inverted by bisection on [0, L0] (monotone since F > 0), to
// within a few ulps of X.
BarPoint bar_eulerian_state(const BarMotion& motion, double x, double t);

ImpactSummary impact_summary(const BarrierImpact& impact);
double impact_wall_force(const BarrierImpact& impact, double t);

}  // namespace rodvv::references
