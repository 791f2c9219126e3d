#pragma once
// A nodal rod laid on a dense curve (the knot family's tying, trefoil_tying.hpp, plectoneme_tying.hpp):
// the rod's vertices at equal arclength steps along the curve, ghost vertices of clamped ends on the
// lines of the curve's end segments.
#include <cstddef>
#include <vector>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/rod3d/model.hpp"

namespace rodvv::harness::knot_cases {

struct TiedRod {
  double length = 0.0;          // L, the arclength of the whole curve
  std::vector<Vec3> vertices;   // N + 1 vertices
};

// N = elements edges of rest length ebar = L / (N - c/2), c the number of clamped ends (the root is
// clamped; the tip too if clamped_tip): vertex i at arclength (i - 1/2) ebar (solvers/rod3d/model.hpp),
// so that a clamped end's edge is centred on the curve's end point. The edges are chords, a little
// shorter than ebar where the curve bends, which the first Newton steps of the statics correct.
// InputError: fewer than 3 elements or 2 curve points.
TiedRod rod_on_curve(const std::vector<Vec3>& curve, std::size_t elements, bool clamped_tip);

// The knot cases' rod on a laid curve: N = vertices - 1 edges, the curve's length, inextensible,
// bending B about both axes, twisting C, no twist inertia (statics), self-contact `contact`; the
// supports and loads are the caller's.
solvers::rod3d::RodModel isotropic_rod_on(const TiedRod& laid, double B, double C,
                                          const solvers::rod3d::SelfContact& contact);

// 0 -> 1 over u in [0, 1] with zero slope at both ends (1/2 - 1/2 cos(pi u); 0 below, 1 above): how the
// tyings ease a curve from one shape into another.
double ease(double u);

}  // namespace rodvv::harness::knot_cases
