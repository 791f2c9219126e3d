#pragma once
// What the rod3d case files share beyond the case builder: a rod state laid on a given curve with
// given material frames, and the round-off gate of a rod loaded in a plane.
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "rodvv/harness/gate.hpp"
#include "rodvv/solvers/rod3d/model.hpp"
#include "rodvv/solvers/rod3d/state.hpp"

namespace rodvv::harness::rod3d_cases {

struct CurvePoint {
  Vec3 position;
  Mat3 frame;  // (t, m1, m2)
};
using Curve = std::function<CurvePoint(double s)>;

// The vertices at their arclengths (model.hpp: vertex_arclength) on the curve, and the material
// frame of each edge turned to the curve's m1 at the edge midpoint (projected normal to the edge).
inline solvers::rod3d::RodState state_on_curve(const solvers::rod3d::RodModel& model, const Curve& curve) {
  namespace rod = solvers::rod3d;
  std::vector<Vec3> x(model.elements + 1);
  for (std::size_t i = 0; i <= model.elements; ++i) x[i] = curve(rod::vertex_arclength(model, i)).position;
  const auto m1_at_edge = [&](std::size_t j) {
    const Vec3 t = (x[j + 1] - x[j]).normalized();
    const Vec3 m1 = curve(0.5 * (rod::vertex_arclength(model, j) + rod::vertex_arclength(model, j + 1))).frame.col(1);
    return Vec3((m1 - m1.dot(t) * t).normalized());
  };
  auto state = rod::make_state(x, m1_at_edge(0));
  for (std::size_t j = 0; j < model.elements; ++j)
    state.angle[j] = rod::signed_angle(state.reference_director[j], m1_at_edge(j), rod::edge_tangent(state, j));
  if (rod::is_inextensible(model)) state.multiplier.assign(model.elements, 0.0);
  return state;
}

// A rod loaded in a plane (tilted in space) leaves it by round-off only: the vertex forces carry ~N^3 eps
// and the softest out-of-plane mode has a stiffness ~1/N, so the drift goes as eps N^4 (h = 1/N); gated
// at every level, like a measured bound (mattiasson.cpp has the measurements).
inline GateSpec out_of_plane_round_off_gate(std::string rationale) {
  GateSpec gate = scaled_upper_bound_gate("out_of_plane", std::numeric_limits<double>::epsilon(), -4.0,
                                          GateScope::AllLevels, std::move(rationale));
  gate.measured = true;
  return gate;
}

}  // namespace rodvv::harness::rod3d_cases
