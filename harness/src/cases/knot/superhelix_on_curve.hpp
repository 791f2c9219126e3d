#pragma once
// A Super-Helix laid on a dense curve (the knot family's tying for the reduced rod; the nodal rod's is
// rod_on_curve.hpp): N elements of equal length L / N, L the curve's arclength, root at the curve's
// start with its tangent, a uniform twist (q_0 = `twist` on every element, 0 by default). Element by element from the root, the
// curvatures (kappa1, kappa2) of the next element are those whose arc of length ell, leaving the
// previous element's end frame, ends closest to the curve's point at arclength (e + 1) ell (Gauss-Newton
// on the closed-form end point, superhelix/element.hpp): the rod tracks the curve instead of
// integrating its curvature, so the tying error does not accumulate along the rod. A G1 rod cannot
// follow a curve's curvature jumps exactly; it cuts across them by O(ell^2 |kappa jump|).
#include <cstddef>
#include <vector>

#include "rodvv/common/eigen_types.hpp"

namespace rodvv::harness::knot_cases {

struct LaidSuperHelix {
  double length = 0.0;
  Vec3 root_position = Vec3::Zero();
  Mat3 root_frame = Mat3::Identity();  // n0 = the curve's start tangent, n1 = `normal` made orthogonal to it
  VecX q;                              // 3N strains (twist the given one)
  double max_miss = 0.0;               // max over elements of |end point - curve point|
};

// InputError: fewer than 1 element or 2 curve points, a normal parallel to the start tangent, a twist
// not finite. With a twist the material frame turns about the tangent at that rate while (kappa1, kappa2)
// follow the curve; the end points track it as without one.
LaidSuperHelix superhelix_on_curve(const std::vector<Vec3>& curve, std::size_t elements, const Vec3& normal,
                                   double twist = 0.0);

}  // namespace rodvv::harness::knot_cases
