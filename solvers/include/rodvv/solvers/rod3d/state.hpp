#pragma once
// The configuration of a discrete elastic rod (model.hpp): vertex positions, one material angle
// per edge, and the reference frames the angles are measured from (ALGORITHMS.md §5).
//
// Reference frames are updated by parallel transport: when the rod moves (a Newton step, a time
// step), the reference director a1^j of each edge is transported from its old tangent to its new
// one (Bergou et al. 2010, "time-parallel" transport), and the reference twist of each interior
// vertex - the signed angle about t^i from the space-parallel transport of a1^{i-1} to a1^i - is
// updated continuously (unwrapped to the branch nearest its previous value), so that a rod may hold
// any number of turns. The material frame m1 = cos(theta) a1 + sin(theta) a2, a2 = t x a1.
#include <cstddef>
#include <vector>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/rod3d/model.hpp"

namespace rodvv::solvers::rod3d {

struct RodState {
  std::vector<Vec3> position;            // x_0 .. x_N
  std::vector<double> angle;             // theta^0 .. theta^{N-1}
  std::vector<Vec3> reference_director;  // a1^j, unit, normal to t^j
  std::vector<double> reference_twist;   // at vertices 0 .. N (entries 0 and N unused, 0)
  std::vector<double> multiplier;        // inextensible rods: axial force of each edge (else empty)

  std::size_t elements() const noexcept { return angle.size(); }
};

// Parallel transport of v from the unit vector `from` to the unit vector `to` (the rotation about
// from x to taking from to to): c v + b x v + (b.v) b / (1 + c), b = from x to, c = from.to.
// Requires from.to > -1.
Vec3 parallel_transport(const Vec3& from, const Vec3& to, const Vec3& v);

// The signed angle from a to b about the unit axis n (a, b normal to n): atan2((a x b).n, a.b).
double signed_angle(const Vec3& a, const Vec3& b, const Vec3& n);

// A state on the polyline `positions` (N + 1 points, edges of non-zero length) with the material
// frame of edge 0 given by the unit director m1_first (normal to t^0) and the material frames of
// the others by space-parallel transport along the rod, turned by `angles` (empty: zero) about
// their tangents: a1^0 = m1_first, a1^j = transport of a1^{j-1}, reference twist 0.
// Throws InputError ("positions", "m1_first", "angles") on bad input.
RodState make_state(const std::vector<Vec3>& positions, const Vec3& m1_first,
                    const std::vector<double>& angles = {});

// The straight rest state of the model: root at model.root.position (or the origin for a free
// root), along the root frame's tangent, material frames = the root frame (turned by the root's
// imposed rotation).
RodState make_straight_state(const RodModel& model);

// Tangent, and the material frame (t, m1, m2) as columns, of edge j.
Vec3 edge_tangent(const RodState& state, std::size_t j);
Mat3 material_frame(const RodState& state, std::size_t j);

// Moves the reference frames of `state` to the current edge tangents (parallel transport from the
// tangents `previous_tangents` they were defined on) and updates the reference twist continuously.
// Returns the largest change of a reference twist (rad): the energy's derivatives assume it stays
// below pi/2 per update (discrete_energy.hpp), which the solvers' step control enforces.
double transport_reference_frames(RodState& state, const std::vector<Vec3>& previous_tangents);

std::vector<Vec3> edge_tangents(const RodState& state);

}  // namespace rodvv::solvers::rod3d
