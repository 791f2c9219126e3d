#pragma once
// The oracle of the inverse cases: the natural strain of a CONTINUOUS Kirchhoff rod that holds a
// given strain field kappa(s) in equilibrium (ALGORITHMS.md §3.1 before discretisation),
//
//   kappa0(s) = kappa(s) - C^-1 R(s)^T m(s),
//   m(s) = int_s^L (r(u) - r(s)) x rho S g du + (r(L) - r(s)) x F + M
//        = ((P(L) - P(s)) - (L - s) r(s)) x rho S g + (r(L) - r(s)) x F + M,   P(s) = int_0^s r,
//
// m(s) the internal moment the distal part exerts across s (its balance with the dead loads), C =
// diag(GJ, EI1, EI2). The centreline comes from R' = R [kappa]x, r' = R e0, P' = r integrated by
// Boost.Odeint's Runge-Kutta-Fehlberg 7(8) at 1e-14 (absolute and relative): no Super-Helix element,
// kinematics or generalised force is used, so a wrong sign, factor or index there is seen.
#include <functional>
#include <vector>

#include "rodvv/common/eigen_types.hpp"

namespace rodvv::harness::inverse_cases {

struct ContinuousRod {
  double length = 1.0;
  Vec3 stiffness = Vec3::Ones();  // (GJ, EI1, EI2)
  double line_density = 1.0;
  Vec3 gravity = Vec3::Zero();
  Vec3 root_position = Vec3::Zero();
  Mat3 root_frame = Mat3::Identity();
  Vec3 end_force = Vec3::Zero(), end_moment = Vec3::Zero();
  std::function<Vec3(double s)> strain;  // kappa(s) = (twist, kappa1, kappa2), material components
};

// kappa0 at the stations (increasing, in [0, L]).
std::vector<Vec3> continuous_rest_strain(const ContinuousRod& rod, const std::vector<double>& stations);

}  // namespace rodvv::harness::inverse_cases
