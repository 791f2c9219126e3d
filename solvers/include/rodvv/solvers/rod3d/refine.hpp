#pragma once
// Nested iteration for the nodal rod's statics: the equilibrium of a coarse rod carried over to a
// finer rod of the same problem, as the start of the fine solve. A relaxation from a laid-out shape
// (a knot to be tied, a ply to be settled) spends hundreds of pseudo-transient iterations on slow
// modes (a loop turning, a knot sliding); those motions do not depend on the resolution, so they are
// done once on a coarse rod, and the fine rod starts within the discretisation error of the coarse
// one, where Newton needs a few iterations (Briggs, Henson & McCormick, "A Multigrid Tutorial",
// ch. 3: nested iteration).
#include "rodvv/solvers/rod3d/model.hpp"
#include "rodvv/solvers/rod3d/state.hpp"

namespace rodvv::solvers::rod3d {

// The state of `fine_model` interpolating `coarse` (a state of `coarse_model`), both rods of the same
// length and end supports, the fine one with at least as many edges:
//  - positions: the cubic Hermite interpolant (Catmull-Rom tangents, one-sided second-order at the
//    ends) of the coarse vertices in their rest arclength (model.hpp: vertex_arclength), evaluated
//    at the fine vertices' - exact for a quadratic centreline, else O(ebar_coarse^3);
//  - material frames: the coarse material angle of each edge measured from the space-parallel
//    transport of edge 0's material director along the coarse rod (accumulated, so any number of
//    turns carries over), interpolated alike at the fine edges' midpoints, and applied from the same
//    director transported onto the fine edge 0 (make_state): the two polylines' transports differ by
//    O(ebar^2), as do the frames;
//  - the inextensibility multipliers (axial forces), interpolated alike.
// The fine rod's supports are placed by the statics' end path (statics.hpp), so a start that misses
// them by the interpolation error is fine. InputError naming "coarse" (state and model disagree, fewer
// than 3 edges, an edge reversed against its neighbour) or "fine_model" (other length or supports,
// fewer edges than the coarse rod).
RodState refine_state(const RodModel& coarse_model, const RodState& coarse, const RodModel& fine_model);

}  // namespace rodvv::solvers::rod3d
