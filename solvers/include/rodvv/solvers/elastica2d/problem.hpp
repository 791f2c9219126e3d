#pragma once
// A planar, inextensible, unshearable rod (Euler elastica) in static equilibrium: the problem
// description shared by the discrete solvers of this folder (PHYSICS.md §0 conventions).
//
//   t = (cos theta, sin theta), kappa = theta', m = EI(s) (kappa - kappa_hat(s)),
//   n(s) = force of (s, L] on [0, s], axial force (tension) n.t, external force per unit length
//   f = -grad V(x, y).
//
// Ends. Each end has a support condition:
//   Free     nothing prescribed; dead loads force_x, force_y, moment may act;
//   Pinned   position (x, y) prescribed, angle free; only the dead moment may act;
//   Clamped  position and angle prescribed; no dead load may act (the reactions carry it);
//   Sliding  a roller on the horizontal line y = const: y prescribed, x and the angle free;
//            dead force_x and moment may act.
// A dead load in a prescribed direction is rejected (InputError): the reaction carries it.
// A prescribed x (Pinned, Clamped) is displacement control; the reaction force there is part of
// the returned internal force at that end node (n(L) = total end force at s = L, -n(0) = total end
// force at s = 0).
// Dead loads are work terms: the end force F and couple M at s = L enter the potential energy as
// -F.r(L) - M theta(L), those at s = 0 as -F.r(0) - M theta(0) (both are forces ON the rod). So a
// cantilever clamped at s = 0 with an end couple M at s = L bends as theta = M s / EI.
//
// Extensible and shearable rod (planar Reissner / special Cosserat rod; Reissner 1972, ZAMP
// 23:795-804; Simo & Vu-Quoc 1986, CMAME 58:79-116). With a finite axial stiffness EA and/or shear
// stiffness GA, theta is the angle of the cross-section (director d3 = t(theta)), no longer the
// angle of r', and
//   r' = t + C(theta) n,   C = t t^T / EA + N N^T / GA    (N = e_z x t),
// i.e. stretch eps = n.t / EA and shear gamma = n.N / GA (strain energy 1/2 EA eps^2 + 1/2 GA
// gamma^2); the moment balance becomes m' + r' x n = 0. Both default to +infinity: the
// inextensible, unshearable elastica above (bit-identical results).
#include <Eigen/Core>
#include <functional>
#include <limits>

namespace rodvv::solvers::elastica2d {

enum class Support { Free, Pinned, Clamped, Sliding };

// Dead end load, acting ON the rod at that end (global axes; moment counter-clockwise).
struct EndLoad {
  double force_x = 0.0;
  double force_y = 0.0;
  double moment = 0.0;
};

struct RodEnd {
  Support support = Support::Free;
  double x = 0.0;      // prescribed x (Pinned, Clamped)
  double y = 0.0;      // prescribed y (Pinned, Clamped, Sliding)
  double angle = 0.0;  // prescribed tangent angle theta (Clamped)
  EndLoad load;        // only in the directions the support leaves free
};

// External potential V(x, y) per unit length (f = -grad V). value and gradient are required when
// the potential is used; hessian is optional (central differences of the gradient if empty).
struct Potential {
  std::function<double(double, double)> value;
  std::function<Eigen::Vector2d(double, double)> gradient;
  std::function<Eigen::Matrix2d(double, double)> hessian;

  bool active() const noexcept { return static_cast<bool>(value) || static_cast<bool>(gradient); }
};

struct Problem {
  double length = 1.0;                                // L > 0
  std::function<double(double)> bending_stiffness;    // EI(s) > 0; empty = constant 1
  std::function<double(double)> natural_curvature;    // kappa_hat(s); empty = constant 0
  Potential potential;                                // empty = no distributed load
  RodEnd start;                                       // s = 0
  RodEnd end;                                         // s = L
  // EA > 0 and GA > 0 (constant along the rod); +infinity = inextensible / unshearable.
  double axial_stiffness = std::numeric_limits<double>::infinity();
  double shear_stiffness = std::numeric_limits<double>::infinity();
};

// EI(s) and kappa_hat(s) with the defaults applied (no validation).
double bending_stiffness_at(const Problem& problem, double s);
double natural_curvature_at(const Problem& problem, double s);

// Throws rodvv::InputError naming the field ("length", "start.load.force_y", "potential.gradient",
// ...) for L <= 0 or non-finite, non-finite prescribed values or loads, dead loads in a
// prescribed direction, and EA or GA not in (0, +infinity] ("axial_stiffness", "shear_stiffness"). EI(s) and kappa_hat(s) are checked where a discretisation samples them.
void validate(const Problem& problem);

}  // namespace rodvv::solvers::elastica2d
