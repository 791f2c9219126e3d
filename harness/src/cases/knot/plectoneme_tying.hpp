#pragma once
// How rodvv lays a plectoneme in a rod before relaxing it (knot/plectoneme-nodal).
//
// Twisting a straight rod under tension by continuation of its end rotation until a ply forms takes
// thousands of pseudo-transient iterations (the ply grows by sliding rod out of the tails through the
// contact; knot/plectoneme-twisted-nodal does it once, at N = 200, and refines). For the convergence and
// angle studies the ply is laid out directly, near its equilibrium, and relaxed under its end loads:
//
//  - the tails lie on the x-axis, the root's on x < 0, the tip's on x > 0, each `tail_length` long;
//  - quarter circles of radius `junction_radius` in the plane z = 0 turn them into the two strands
//    of a ply along +y, 2R apart (R = `ply_radius`, the distance from a strand's axis to the ply
//    axis), `ply_length` long: strand 2 (the root's) at (-R cos phi, y, -R sin phi), strand 1 at
//    (R cos phi, y, R sin phi), with phi' = tan(theta(y)) / R, the helix angle theta(y) eased from 0
//    at both ends of the ply to `helix_angle` over a quarter of its length at each end (so the strands
//    leave the junction and enter the loop parallel to the ply axis); phi increasing with y winds a
//    LEFT-handed ply about +y ((x, z, y) is a left-handed frame);
//  - an end loop in the plane of the ply axis and the strands' separation at the ply's top, from
//    strand 2's end to strand 1's: X = R cos psi + W sin psi sin 2 psi across, Y = H_l sin psi up,
//    psi from pi to 0 (H_l = `loop_height`, W = `loop_bulge`: the loop is wider than the ply, as a
//    plectoneme's end loop is);
//  - (pull_laid_ply) the material frames twisted uniformly at a given rate from the space-parallel
//    transport of the root's director e_z along the rod.
//
// The rod's vertices are placed on this curve by rod_on_curve (both ends clamped).
#include <cstddef>
#include <vector>

#include "rod_on_curve.hpp"
#include "rodvv/solvers/rod3d/model.hpp"
#include "rodvv/solvers/rod3d/state.hpp"

namespace rodvv::harness::knot_cases {

struct PlyLayout {
  double ply_radius = 0.0;       // R > 0
  double helix_angle = 0.0;      // theta of the uniform part, 0 < theta < pi/4 (rad)
  double ply_length = 0.0;       // > 0
  double junction_radius = 0.0;  // > 0
  double loop_height = 0.0;      // > 0
  double loop_bulge = 0.0;       // >= 0
  double tail_length = 0.0;      // > 0
};

// The laid curve, densely sampled (2000 points per piece: chord error ~ (piece / 2000)^2 curvature).
// InputError naming the field unless every length is finite and positive (loop_bulge >= 0) and the helix
// angle in (0, pi/4).
std::vector<Vec3> plectoneme_curve(const PlyLayout& ply);
// The nodal rod's vertices on it (rod_on_curve, both ends clamped); InputError as above, or elements < 3.
TiedRod lay_plectoneme(const PlyLayout& ply, std::size_t elements);

// The laid rod as knot/plectoneme-nodal relaxes it: inextensible, bending B about both axes, twisting
// C, its material frames turned by `twist_rate` (rad per length, InputError unless finite) along it;
// the root clamped on its tail (t = e_x); the tip clamped with its twisted frame but sliding along its
// tail (the x-axis) under the dead pull `tension` e_x (solvers/rod3d/model.hpp: EndCondition::slides,
// a rod held at constant tension and link, as in magnetic tweezers), so that the ply's length and helix
// angle find the equilibrium of that tension; self-contact `contact`. The tip's clamp is the frame of
// the reference director turned by the laid twist's whole angle (tip.rotation, many turns), so the
// statics holds the laid link: with the twisted frame itself and no rotation, the clamp fixed the
// angle modulo 2 pi only and the statics' end path unwound the whole turns at its first step (measured
// 2026-12-07: the relaxations then took 3875 instead of 494 iterations at 30 degrees, N = 200).
struct PulledPly {
  solvers::rod3d::RodModel model;
  solvers::rod3d::RodState start;
};
// Clamps the tip of `model` where `state` has it, every turn counted: the frame of the state's reference
// director on the last edge (material angle 0), turned by the state's whole material angle there. The statics'
// end path follows a held angle turn by turn from the start's to the model's (statics.hpp), so a start in this
// state keeps its link; a clamp given the state's material frame and no rotation fixes the angle modulo 2 pi
// only, and the first step unwinds the whole turns.
void clamp_tip_with_its_turns(solvers::rod3d::RodModel& model, const solvers::rod3d::RodState& state);

PulledPly pull_laid_ply(const TiedRod& laid, double twist_rate, double B, double C, double tension,
                        const solvers::rod3d::SelfContact& contact);

}  // namespace rodvv::harness::knot_cases
