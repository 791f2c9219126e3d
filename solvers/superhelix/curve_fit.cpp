#include "rodvv/solvers/superhelix/curve_fit.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/time_budget.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"

namespace rodvv::solvers::superhelix {

namespace {

constexpr double kMaxTurning = std::numbers::pi / 3.0;  // 60 degrees

void check_points(const std::vector<Vec3>& points, std::size_t elements) {
  if (points.size() < 3)
    throw InputError("points", "invalid parameter 'points': need at least 3 points, got " + std::to_string(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!points[i].allFinite()) throw InputError("points", "invalid parameter 'points': point " + std::to_string(i) + " is not finite");
  double length = 0.0;
  for (std::size_t i = 1; i < points.size(); ++i) length += (points[i] - points[i - 1]).norm();
  for (std::size_t i = 1; i < points.size(); ++i)
    if (!((points[i] - points[i - 1]).norm() > 1e-12 * length))
      throw InputError("points", "invalid parameter 'points': points " + std::to_string(i - 1) + " and " +
                                     std::to_string(i) + " coincide (repeated point)");
  for (std::size_t i = 1; i + 1 < points.size(); ++i) {
    const Vec3 a = (points[i] - points[i - 1]).normalized(), b = (points[i + 1] - points[i]).normalized();
    const double turning = std::atan2(a.cross(b).norm(), a.dot(b));
    if (turning > kMaxTurning)
      throw InputError("points", "invalid parameter 'points': the polyline turns by " +
                                     format_value(turning * 180.0 / std::numbers::pi) + " degrees at point " +
                                     std::to_string(i) + " (at most 60: a kink, not a smooth curve a rod can fit)");
  }
  const std::size_t m = points.size() - 1;
  if (elements < 1 || 3 * elements + 2 > 2 * m)
    throw InputError("elements", "invalid parameter 'elements' = " + std::to_string(elements) + ": must be in [1, " +
                                     std::to_string((2 * m - 2) / 3) + "] for " + std::to_string(points.size()) +
                                     " points (3 N + 2 <= 2 M unknowns beyond the arc lengths)");
}

// The unknowns x = [q (3N) | L | a, b | s_1 .. s_{M-1}] and what is fixed.
struct Layout {
  std::size_t n = 1, m = 2;  // elements, last point index
  Vec3 first_chord, u, v, reference;
  Eigen::Index length() const { return Eigen::Index(3 * n); }
  Eigen::Index angles() const { return Eigen::Index(3 * n + 1); }
  Eigen::Index arc(std::size_t i) const { return Eigen::Index(3 * n + 3 + i - 1); }  // i = 1 .. m-1
  Eigen::Index size() const { return Eigen::Index(3 * n + 3 + m - 1); }
};

RodModel model_of(const Layout& layout, const Vec3& root, const VecX& x) {
  RodModel model;
  model.elements = layout.n;
  model.length = x[layout.length()];
  model.root_position = root;
  const Vec3 n0 = (layout.first_chord + x[layout.angles()] * layout.u + x[layout.angles() + 1] * layout.v).normalized();
  const Vec3 n1 = (layout.reference - layout.reference.dot(n0) * n0).normalized();
  model.root_frame << n0, n1, n0.cross(n1);
  model.gauss_points = 1;
  return model;
}

double arc_of(const Layout& layout, const VecX& x, std::size_t i) {
  if (i == 0) return 0.0;
  if (i == layout.m) return x[layout.length()];
  return std::clamp(x[layout.arc(i)], 0.0, x[layout.length()]);
}

void locate(const RodModel& model, double s, std::size_t& e, double& sigma) {
  const double ell = element_length(model);
  e = std::min(static_cast<std::size_t>(std::max(s, 0.0) / ell), model.elements - 1);
  sigma = s - double(e) * ell;
}

VecX residual(const Layout& layout, const std::vector<Vec3>& points, const VecX& x) {
  const RodModel model = model_of(layout, points[0], x);
  const Kinematics kinematics(model, x.head(Eigen::Index(3 * layout.n)));
  VecX e(Eigen::Index(3 * layout.m));
  for (std::size_t i = 1; i <= layout.m; ++i) {
    std::size_t element = 0;
    double sigma = 0.0;
    locate(model, arc_of(layout, x, i), element, sigma);
    e.segment<3>(Eigen::Index(3 * (i - 1))) = kinematics.position(element, sigma) - points[i];
  }
  return e;
}

MatX jacobian(const Layout& layout, const std::vector<Vec3>& points, const VecX& x) {
  const RodModel model = model_of(layout, points[0], x);
  const Kinematics kinematics(model, x.head(Eigen::Index(3 * layout.n)));
  MatX J = MatX::Zero(Eigen::Index(3 * layout.m), x.size());
  for (std::size_t i = 1; i <= layout.m; ++i) {
    std::size_t element = 0;
    double sigma = 0.0;
    locate(model, arc_of(layout, x, i), element, sigma);
    const auto rows = Eigen::Index(3 * (i - 1));
    J.block(rows, 0, 3, Eigen::Index(3 * layout.n)) = kinematics.position_jacobian(element, sigma);
    if (i < layout.m) J.block<3, 1>(rows, layout.arc(i)) = kinematics.frame(element, sigma).col(0);
  }
  // L and the root angles: central differences (step cbrt(eps) of their scale).
  const double scale[3] = {x[layout.length()], 1.0, 1.0};
  for (int k = 0; k < 3; ++k) {
    const Eigen::Index column = layout.length() + k;
    const double step = 6e-6 * scale[k];
    VecX plus = x, minus = x;
    plus[column] += step;
    minus[column] -= step;
    J.col(column) = (residual(layout, points, plus) - residual(layout, points, minus)) / (2.0 * step);
  }
  return J;
}

// Levenberg-Marquardt on one level; returns the iterations.
std::size_t levenberg_marquardt(const Layout& layout, const std::vector<Vec3>& points, VecX& x,
                                const CurveFitOptions& options) {
  VecX e = residual(layout, points, x);
  double cost = e.squaredNorm(), damping = 1e-3;
  const double floor = 1e-30 * (points.back() - points.front()).squaredNorm();
  for (std::size_t iteration = 1; iteration <= options.max_iterations; ++iteration) {
    check_time_budget("superhelix curve fit (Levenberg-Marquardt)", iteration, std::sqrt(cost));
    const MatX J = jacobian(layout, points, x);
    const MatX normal = J.transpose() * J;
    const VecX gradient = J.transpose() * e;
    // First-order optimality, scale-free: the residual orthogonal to every column of J.
    if (gradient.lpNorm<Eigen::Infinity>() <= options.tolerance * J.cwiseAbs().maxCoeff() * e.norm() || cost <= floor)
      return iteration - 1;
    bool accepted = false;
    while (damping < 1e12) {
      MatX damped = normal;
      damped.diagonal() += damping * normal.diagonal().cwiseMax(1e-12 * normal.diagonal().maxCoeff());
      const VecX step = -damped.ldlt().solve(gradient);
      const VecX trial = x + step;
      const VecX trial_e = residual(layout, points, trial);
      const double trial_cost = trial_e.squaredNorm();
      if (trial_cost < cost) {
        const double decrease = cost - trial_cost;
        x = trial;
        e = trial_e;
        cost = trial_cost;
        damping = std::max(damping * 0.1, 1e-15);
        accepted = true;
        if (step.norm() <= 1e-15 * (1.0 + x.norm()) || decrease <= 1e-15 * cost) return iteration;
        break;
      }
      damping *= 4.0;
    }
    if (!accepted) return iteration;  // no descent left: at the minimum to round-off
  }
  throw SolverError("superhelix curve fit (Levenberg-Marquardt)", "no convergence at N = " + std::to_string(layout.n),
                    options.max_iterations, std::sqrt(cost));
}

}  // namespace

CurveFit fit_super_helix(const std::vector<Vec3>& points, std::size_t elements, const CurveFitOptions& options) {
  check_points(points, elements);
  require_at_least("max_iterations", options.max_iterations, 1);
  require_open_interval("tolerance", options.tolerance, 0.0, 1.0);
  Layout layout;
  layout.m = points.size() - 1;
  layout.first_chord = (points[1] - points[0]).normalized();
  Eigen::Index axis = 0;
  layout.first_chord.cwiseAbs().minCoeff(&axis);
  layout.reference = Vec3::Unit(axis);
  layout.u = (layout.reference - layout.reference.dot(layout.first_chord) * layout.first_chord).normalized();
  layout.v = layout.first_chord.cross(layout.u);

  // Level N = 1 from the chords' straight line.
  std::vector<double> chord(points.size(), 0.0);
  for (std::size_t i = 1; i < points.size(); ++i) chord[i] = chord[i - 1] + (points[i] - points[i - 1]).norm();
  layout.n = 1;
  VecX x = VecX::Zero(layout.size());
  x[layout.length()] = chord.back();
  for (std::size_t i = 1; i < layout.m; ++i) x[layout.arc(i)] = chord[i];
  CurveFit fit;
  fit.iterations += levenberg_marquardt(layout, points, x, options);
  // Continuation: double N (or jump to it), each new element taking the strain of the old one it lies in.
  while (layout.n < elements) {
    const std::size_t next = std::min(2 * layout.n, elements);
    Layout finer = layout;
    finer.n = next;
    VecX y(finer.size());
    for (std::size_t e = 0; e < next; ++e) {
      const std::size_t old = std::min(static_cast<std::size_t>((double(e) + 0.5) * double(layout.n) / double(next)), layout.n - 1);
      y.segment<3>(Eigen::Index(3 * e)) = x.segment<3>(Eigen::Index(3 * old));
    }
    y.segment(finer.length(), finer.size() - finer.length()) = x.segment(layout.length(), x.size() - layout.length());
    layout = finer;
    x = y;
    fit.iterations += levenberg_marquardt(layout, points, x, options);
  }
  fit.model = model_of(layout, points[0], x);
  fit.model.gauss_points = RodModel{}.gauss_points;
  fit.q = x.head(Eigen::Index(3 * layout.n));
  fit.arc_length.resize(Eigen::Index(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i) fit.arc_length[Eigen::Index(i)] = arc_of(layout, x, i);
  const VecX e = residual(layout, points, x);
  for (std::size_t i = 0; i < layout.m; ++i) fit.max_distance = std::max(fit.max_distance, e.segment<3>(Eigen::Index(3 * i)).norm());
  fit.rms_distance = std::sqrt(e.squaredNorm() / double(layout.m));
  return fit;
}

}  // namespace rodvv::solvers::superhelix
