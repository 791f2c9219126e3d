#pragma once
// How rodvv lays a plectoneme in a rod before relaxing it (knot/plectoneme-nodal).
//
// Twisting a straight rod under tension by continuation of its end rotation until a ply forms was
// tried first (issue 12's notes): the twist-buckling branch is followed, but the ply then grows by
// sliding rod out of the tails through the contact, thousands of pseudo-transient iterations at
// N = 100, and under displacement control the h/2 step limit of the contact statics caps every
// step. Instead the ply is laid out directly, near its equilibrium, and relaxed with both ends
// clamped where the layout puts them (the tension is then a reaction, measured on the tails):
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
//  - the material frames twisted uniformly at the rate `twist_rate` (rad per length) from the
//    space-parallel transport of the root's director e_z along the rod.
//
// The rod's vertices are placed on this curve by rod_on_curve (both ends clamped).
#include <cstddef>

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
  double twist_rate = 0.0;       // finite
};

// InputError naming the field unless every length is finite and positive (loop_bulge >= 0), the helix
// angle in (0, pi/4), the twist rate finite, elements >= 3.
TiedRod lay_plectoneme(const PlyLayout& ply, std::size_t elements);

// The laid rod as knot/plectoneme-nodal relaxes it: inextensible, bending B about both axes, twisting
// C, both ends clamped where the layout puts them (root: t = e_x; tip: t = e_x, its material frame
// turned by the twist accumulated along the rod), self-contact `contact`, no loads.
struct ClampedPly {
  solvers::rod3d::RodModel model;
  solvers::rod3d::RodState start;
};
ClampedPly clamp_laid_rod(const TiedRod& laid, double twist_rate, double B, double C,
                          const solvers::rod3d::SelfContact& contact);

}  // namespace rodvv::harness::knot_cases
