#pragma once
// A sliding clamp at the tip of a Super-Helix (statics only; RodModel::tip_guide): the tip is free to
// slide along the guide's axis, the line through `point` along e = frame.col(0), and its material frame
// is held at `frame` - a rod held at a constant tension and link, as in magnetic tweezers, and the
// nodal rod's EndCondition::slides. The Super-Helix's tip is otherwise free, and its reduced
// coordinates cannot clamp it, so stiff springs hold it (a penalty): the energy
//
//   E = k / 2 |P (r_tip - point)|^2 + k_r (3 - tr(frame^T R_tip)),     P = I - e e^T,
//
// zero on the guide, vanishing with its gradient there; for a small rotation theta of the tip frame
// away from `frame`, k_r (3 - tr) = k_r |theta|^2 + O(theta^4). Whatever the springs' compliance, the
// equilibrium is exact for the loads they carry: the solution struct takes the guide's reaction into
// n(s) (solution.cpp), so H and the laws are checked on what the rod carries; the compliance only lets
// the tip stray by (reaction / k) from the axis and turn by about (reaction moment / 2 k_r). The statics
// does not ramp the springs: start it near the guide (a naturally curved rod whose natural shape ends
// a radian off the clamp's frame did not converge from there at k = 1e8, and did from the straight rod).
//
// Derivatives (world rotation vectors: dR_tip = [Theta dq]x R_tip, kinematics.hpp). With
// w = k P (r - point) and X = R_tip frame^T,
//   dE/dq = T^T w + Theta^T g,       g = k_r vee(X - X^T)      (tr([a]x X) = -a . vee(X - X^T)),
//   d2E/dq2 = k T^T P T + Theta^T G Theta + D(w, g),
// where T, Theta are the tip's 3 x 3N translation and rotation Jacobians, G e_i = k_r vee([e_i]x X +
// X^T [e_i]x) (the rate of g as the tip frame turns), and D(w, g) = d(T^T w + Theta^T g)/dq at fixed
// w, g: the load stiffness of a dead tip force w and moment g (load_stiffness.hpp). Neither D(w, g)
// nor Theta^T G Theta is symmetric; their sum is (tested against central differences).
#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"
#include "rodvv/solvers/superhelix/model.hpp"

namespace rodvv::solvers::superhelix {

// What the guide exerts on the rod's tip (world): force -w, moment -g.
struct TipGuideReaction {
  Vec3 force = Vec3::Zero();
  Vec3 moment = Vec3::Zero();
};

bool has_tip_guide(const RodModel& model);  // stiffness > 0
TipGuideReaction tip_guide_reaction(const TipGuide& guide, const Kinematics& kinematics);
double tip_guide_energy(const TipGuide& guide, const Kinematics& kinematics);
VecX tip_guide_gradient(const TipGuide& guide, const Kinematics& kinematics);  // dE/dq, 3N
MatX tip_guide_hessian(const TipGuide& guide, const Kinematics& kinematics);   // d2E/dq2, 3N x 3N

}  // namespace rodvv::solvers::superhelix
