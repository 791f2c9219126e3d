#include "rodvv/solvers/rod3d/state.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include <Eigen/Geometry>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::solvers::rod3d {

Vec3 parallel_transport(const Vec3& from, const Vec3& to, const Vec3& v) {
  const Vec3 b = from.cross(to);
  const double c = from.dot(to);
  return c * v + b.cross(v) + (b.dot(v) / (1.0 + c)) * b;
}

double signed_angle(const Vec3& a, const Vec3& b, const Vec3& n) {
  return std::atan2(a.cross(b).dot(n), a.dot(b));
}

namespace {

double unwrap_near(double raw, double previous) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  return raw + kTwoPi * std::round((previous - raw) / kTwoPi);
}

// Reference twist at interior vertex i from the directors and tangents of edges i-1, i.
double raw_reference_twist(const Vec3& t_prev, const Vec3& a_prev, const Vec3& t_next, const Vec3& a_next) {
  return signed_angle(parallel_transport(t_prev, t_next, a_prev), a_next, t_next);
}

}  // namespace

std::vector<Vec3> edge_tangents(const RodState& state) {
  std::vector<Vec3> t(state.elements());
  for (std::size_t j = 0; j < t.size(); ++j) t[j] = edge_tangent(state, j);
  return t;
}

Vec3 edge_tangent(const RodState& state, std::size_t j) {
  return (state.position[j + 1] - state.position[j]).normalized();
}

Mat3 material_frame(const RodState& state, std::size_t j) {
  const Vec3 t = edge_tangent(state, j);
  const Vec3& a1 = state.reference_director[j];
  const Vec3 a2 = t.cross(a1);
  const double c = std::cos(state.angle[j]), s = std::sin(state.angle[j]);
  Mat3 frame;
  frame.col(0) = t;
  frame.col(1) = c * a1 + s * a2;
  frame.col(2) = -s * a1 + c * a2;
  return frame;
}

RodState make_state(const std::vector<Vec3>& positions, const Vec3& m1_first, const std::vector<double>& angles) {
  if (positions.size() < 3)
    throw InputError("positions", "invalid parameter 'positions': need at least 3 points (2 edges), got " +
                                      std::to_string(positions.size()));
  const std::size_t n = positions.size() - 1;
  for (std::size_t i = 0; i <= n; ++i)
    for (int k = 0; k < 3; ++k) require_finite("positions", positions[i][k]);
  for (std::size_t j = 0; j < n; ++j)
    if (!((positions[j + 1] - positions[j]).norm() > 0.0))
      throw InputError("positions", "invalid parameter 'positions': edge " + std::to_string(j) + " has zero length");
  if (!angles.empty() && angles.size() != n)
    throw InputError("angles", "invalid parameter 'angles': must be empty or hold one angle per edge (" +
                                   std::to_string(n) + "), got " + std::to_string(angles.size()));
  for (double a : angles) require_finite("angles", a);
  for (int k = 0; k < 3; ++k) require_finite("m1_first", m1_first[k]);

  RodState state;
  state.position = positions;
  state.angle.assign(n, 0.0);
  if (!angles.empty()) state.angle = angles;
  state.reference_twist.assign(n + 1, 0.0);
  state.reference_director.resize(n);
  const Vec3 t0 = edge_tangent(state, 0);
  const Vec3 a0 = m1_first - m1_first.dot(t0) * t0;
  // A director within 1e-8 of normal to the tangent: a frame given to round-off, not a guess.
  if (std::abs(m1_first.norm() - 1.0) > 1e-8 || std::abs(m1_first.dot(t0)) > 1e-8)
    throw InputError("m1_first", "invalid parameter 'm1_first': must be a unit vector normal to the first edge "
                                 "(to 1e-8)");
  state.reference_director[0] = a0.normalized();
  for (std::size_t j = 1; j < n; ++j) {
    const Vec3 t_prev = edge_tangent(state, j - 1), t = edge_tangent(state, j);
    if (t_prev.dot(t) <= -1.0 + 1e-12)
      throw InputError("positions", "invalid parameter 'positions': the rod folds back on itself at vertex " +
                                        std::to_string(j));
    const Vec3 a = parallel_transport(t_prev, t, state.reference_director[j - 1]);
    state.reference_director[j] = (a - a.dot(t) * t).normalized();
  }
  return state;
}

RodState make_straight_state(const RodModel& model) {
  validate(model);
  const Mat3& frame = model.root.frame;
  const double ell = rest_edge_length(model);
  const Vec3 origin = (model.root.support == EndSupport::Free ? Vec3::Zero() : model.root.position) +
                      vertex_arclength(model, 0) * frame.col(0);
  std::vector<Vec3> positions(model.elements + 1);
  for (std::size_t i = 0; i <= model.elements; ++i) positions[i] = origin + double(i) * ell * frame.col(0);
  const std::vector<double> angles(model.elements, model.root.rotation);
  RodState state = make_state(positions, frame.col(1), angles);
  if (is_inextensible(model)) state.multiplier.assign(model.elements, 0.0);
  return state;
}

double transport_reference_frames(RodState& state, const std::vector<Vec3>& previous_tangents) {
  const std::size_t n = state.elements();
  std::vector<Vec3> t(n);
  for (std::size_t j = 0; j < n; ++j) {
    t[j] = edge_tangent(state, j);
    const Vec3 a = parallel_transport(previous_tangents[j], t[j], state.reference_director[j]);
    state.reference_director[j] = (a - a.dot(t[j]) * t[j]).normalized();  // re-orthonormalise (round-off)
  }
  double largest_change = 0.0;
  for (std::size_t i = 1; i < n; ++i) {
    const double updated = unwrap_near(
        raw_reference_twist(t[i - 1], state.reference_director[i - 1], t[i], state.reference_director[i]),
        state.reference_twist[i]);
    largest_change = std::max(largest_change, std::abs(updated - state.reference_twist[i]));
    state.reference_twist[i] = updated;
  }
  return largest_change;
}

}  // namespace rodvv::solvers::rod3d
