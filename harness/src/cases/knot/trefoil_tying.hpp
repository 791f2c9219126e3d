#pragma once
// How rodvv ties an open trefoil (overhand) knot in a rod before relaxing it (knot/trefoil-nodal).
//
// The trefoil is the closure of the two-strand braid sigma_1^3. The strands wind about the x-axis
// at distance `strand_offset` through `half_twists` half turns over |x| <= braid_half_length; two
// stadium-shaped arcs of radius `loop_radius` in the plane z = 0 close them, one above (y > 0) and
// one below. The lower arc is cut at its middle and its two cut ends are drawn out into straight
// tails of length `tail_length`, one each way along x, passing each other `tail_offset` above and
// below the arc's plane (a crossing of the two tails alone, which a closing arc at infinity would
// undo by a Reidemeister I move, so the knot type is the braid closure's: a trefoil for 3 half
// twists, the unknot for 1). The curve is then turned by pi about z so that it starts at -x.
//
// The rod's vertices are placed on this curve by rod_on_curve (a clamped root, a free tip).
#include <cstddef>
#include <vector>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/rod3d/model.hpp"
#include "rodvv/solvers/rod3d/state.hpp"
#include "rod_on_curve.hpp"

namespace rodvv::harness::knot_cases {

struct BraidClosure {
  int half_twists = 3;             // odd: one component (3: trefoil, 1: unknot)
  double strand_offset = 0.0;      // distance of each strand from the braid axis
  double braid_half_length = 0.0;  // the braid spans |x| <= this
  double loop_radius = 0.0;        // radius of the closing arcs' ends
  double tail_offset = 0.0;        // the tails pass this far above and below the arcs' plane
  double tail_length = 0.0;        // each tail's length
};

// InputError unless every length is finite and > 0 and half_twists is odd and >= 1.
void validate(const BraidClosure& knot);
// The curve above, densely sampled (400 points per piece), from the root's tail end (at -x, tangent
// e_x) to the tip's (at +x). Does not validate.
std::vector<Vec3> braid_closure_curve(const BraidClosure& knot);
// The nodal rod's vertices on it; InputError also for elements < 3.
TiedRod tie_braid_closure(const BraidClosure& knot, std::size_t elements);

// The tied rod as the knot cases pull it: inextensible, bending B about both axes, twisting C, root
// clamped on its tail (t = e_x, m1 = e_z), tip free under the dead pull T e_x, self-contact `contact`;
// the start state has the root's frame carried along by parallel transport.
struct PulledKnot {
  solvers::rod3d::RodModel model;
  solvers::rod3d::RodState start;
};
PulledKnot pull_tied_rod(const TiedRod& tied, double B, double C, double T, const solvers::rod3d::SelfContact& contact);

}  // namespace rodvv::harness::knot_cases
