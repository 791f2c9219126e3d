#include "rodvv/solvers/elastica2d/lagrangian.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/solvers/elastica2d/arc_geometry.hpp"
#include "rodvv/solvers/elastica2d/compliance.hpp"

namespace rodvv::solvers::elastica2d {

namespace {

double sample(const std::function<double(double)>& f, double fallback, double s) {
  return f ? f(s) : fallback;
}

void check_sample(const char* name, double value, double s, bool positive) {
  if (std::isfinite(value) && (!positive || value > 0.0)) return;
  throw InputError(name, std::string("invalid parameter '") + name + "' = " + format_value(value) +
                             " at s = " + format_value(s) + ": must be a finite number" +
                             (positive ? " > 0" : "") + " everywhere on [0, L]");
}

}  // namespace

DiscreteLagrangian::DiscreteLagrangian(const Problem& problem, const Discretisation& discretisation)
    : problem_(problem), scheme_(discretisation.scheme), n_(discretisation.elements) {
  validate(problem);
  validate(discretisation);
  h_ = problem.length / static_cast<double>(n_);
  const double h = h_;
  axial_compliance_ = 1.0 / problem.axial_stiffness;  // exactly 0 for +infinity
  shear_compliance_ = 1.0 / problem.shear_stiffness;

  node_ei_.resize(n_ + 1);
  node_khat_.resize(n_ + 1);
  for (std::size_t i = 0; i <= n_; ++i) {
    const double s = i == n_ ? problem.length : static_cast<double>(i) * h;
    node_ei_[i] = sample(problem.bending_stiffness, 1.0, s);
    node_khat_[i] = sample(problem.natural_curvature, 0.0, s);
    check_sample("bending_stiffness", node_ei_[i], s, true);
    check_sample("natural_curvature", node_khat_[i], s, false);
  }

  // Boundary rows (dof indices filled once the offset is known).
  enum class Dof { X, Y, Angle };
  struct Pending {
    bool at_start;
    Dof dof;
    double target;
  };
  std::vector<Pending> pending;
  auto add_end = [&](const RodEnd& end, bool at_start) {
    switch (end.support) {
      case Support::Free:
        break;
      case Support::Pinned:
        pending.push_back({at_start, Dof::X, end.x});
        pending.push_back({at_start, Dof::Y, end.y});
        break;
      case Support::Clamped:
        pending.push_back({at_start, Dof::X, end.x});
        pending.push_back({at_start, Dof::Y, end.y});
        if (scheme_ == Scheme::Arcs) pending.push_back({at_start, Dof::Angle, end.angle});
        break;
      case Support::Sliding:
        pending.push_back({at_start, Dof::Y, end.y});
        break;
    }
  };
  add_end(problem.start, true);
  std::size_t start_rows = pending.size();
  add_end(problem.end, false);
  offset_ = start_rows;
  const std::size_t last_node = scheme_ == Scheme::Polygon ? 2 : 3;
  const std::size_t end_first = offset_ + 5 * n_ + last_node;
  size_ = end_first + (pending.size() - start_rows);
  for (std::size_t k = 0; k < pending.size(); ++k) {
    const Pending& p = pending[k];
    const std::size_t node = p.at_start ? 0 : n_;
    std::size_t dof = 0;
    if (p.dof == Dof::X) dof = x(node);
    if (p.dof == Dof::Y) dof = y(node);
    if (p.dof == Dof::Angle) dof = angle(node);
    rows_.push_back({dof, p.target});
    row_index_.push_back(p.at_start ? k : end_first + (k - start_rows));
  }

  // Bending terms (w / 2)(c0 a_j0 + c1 a_j1 - b)^2.
  if (scheme_ == Scheme::Polygon) {
    for (std::size_t i = 1; i < n_; ++i)  // interior vertex i between edges i-1 and i
      bending_.push_back({i, i - 1, 1.0, -1.0, node_ei_[i] / h, h * node_khat_[i]});
    // Clamps: the prescribed angle at distance h/2 from the first/last edge midpoint.
    if (problem.start.support == Support::Clamped)
      bending_.push_back({0, 0, 1.0, 0.0, 2.0 * node_ei_[0] / h,
                          problem.start.angle + 0.5 * h * node_khat_[0]});
    if (problem.end.support == Support::Clamped)
      bending_.push_back({n_ - 1, n_ - 1, -1.0, 0.0, 2.0 * node_ei_[n_] / h,
                          0.5 * h * node_khat_[n_] - problem.end.angle});
  } else {
    for (std::size_t e = 0; e < n_; ++e) {
      const double s = (static_cast<double>(e) + 0.5) * h;
      const double ei = sample(problem.bending_stiffness, 1.0, s);
      const double khat = sample(problem.natural_curvature, 0.0, s);
      check_sample("bending_stiffness", ei, s, true);
      check_sample("natural_curvature", khat, s, false);
      bending_.push_back({e + 1, e, 1.0, -1.0, ei / h, h * khat});
    }
  }
  // Bending terms store angle numbers j; convert to z indices.
  for (BendingTerm& t : bending_) {
    t.j0 = angle(t.j0);
    t.j1 = angle(t.j1);
  }
}

bool DiscreteLagrangian::is_multiplier(std::size_t index) const noexcept {
  if (index < offset_) return true;
  const std::size_t local = index - offset_;
  if (local >= 5 * n_) return local >= 5 * n_ + (scheme_ == Scheme::Polygon ? 2 : 3);
  return local % 5 >= 3;
}

double DiscreteLagrangian::node_weight(std::size_t i) const noexcept {
  return (i == 0 || i == n_) ? 0.5 * h_ : h_;
}

std::size_t DiscreteLagrangian::chord_angle(std::size_t edge, int k) const noexcept {
  return angle(edge + static_cast<std::size_t>(k));
}

DiscreteLagrangian::Chord DiscreteLagrangian::chord(const Eigen::VectorXd& z,
                                                    std::size_t edge) const {
  Chord c;
  const double h = h_;
  if (scheme_ == Scheme::Polygon) {
    const double a = z[angle(edge)];
    const Eigen::Vector2d t(std::cos(a), std::sin(a));
    const Eigen::Vector2d nrm(-t.y(), t.x());
    c.g = h * t;
    c.d[0] = h * nrm;
    c.dd[0][0] = -h * t;
    return c;
  }
  const double a = z[angle(edge)], b = z[angle(edge + 1)];
  const double u = b - a, m = 0.5 * (a + b);
  const SincDerivatives sd = sinc_derivatives(0.5 * u);
  const double S = sd.value, S1 = 0.5 * sd.first, S2 = 0.25 * sd.second;  // d/du of sinc(u/2)
  const Eigen::Vector2d t(std::cos(m), std::sin(m));
  const Eigen::Vector2d nrm(-t.y(), t.x());
  const Eigen::Vector2d gu = h * S1 * t, gm = h * S * nrm;
  const Eigen::Vector2d guu = h * S2 * t, gum = h * S1 * nrm, gmm = -h * S * t;
  c.g = h * S * t;
  c.d[0] = -gu + 0.5 * gm;
  c.d[1] = gu + 0.5 * gm;
  c.dd[0][0] = guu - gum + 0.25 * gmm;
  c.dd[1][1] = guu + gum + 0.25 * gmm;
  c.dd[0][1] = c.dd[1][0] = -guu + 0.25 * gmm;
  return c;
}

ElementCompliance DiscreteLagrangian::compliance(const Eigen::VectorXd& z, std::size_t edge) const {
  const double a0 = z[angle(edge)];
  const double a1 = scheme_ == Scheme::Polygon ? a0 : z[angle(edge + 1)];
  return element_compliance(scheme_, a0, a1, axial_compliance_, shear_compliance_);
}

Eigen::Matrix2d DiscreteLagrangian::potential_hessian(double px, double py) const {
  const Potential& v = problem_.potential;
  if (v.hessian) return v.hessian(px, py);
  // Central differences of the gradient, step cbrt(eps) * scale: error ~ eps^(2/3) relative.
  const double scale = 1.0 + std::max(std::abs(px), std::abs(py));
  const double d = std::cbrt(std::numeric_limits<double>::epsilon()) * scale;
  Eigen::Matrix2d hess;
  hess.col(0) = (v.gradient(px + d, py) - v.gradient(px - d, py)) / (2.0 * d);
  hess.col(1) = (v.gradient(px, py + d) - v.gradient(px, py - d)) / (2.0 * d);
  return 0.5 * (hess + hess.transpose());
}

double DiscreteLagrangian::energy(const Eigen::VectorXd& z) const {
  double e = 0.0;
  for (const BendingTerm& t : bending_) {
    const double r = t.c0 * z[t.j0] + t.c1 * z[t.j1] - t.b;
    e += 0.5 * t.w * r * r;
  }
  if (problem_.potential.active())
    for (std::size_t i = 0; i <= n_; ++i)
      e += lambda_ * node_weight(i) * problem_.potential.value(z[x(i)], z[y(i)]);
  const EndLoad& l0 = problem_.start.load;
  const EndLoad& l1 = problem_.end.load;
  e -= lambda_ * (l0.force_x * z[x(0)] + l0.force_y * z[y(0)] + l0.moment * z[start_angle()]);
  e -= lambda_ * (l1.force_x * z[x(n_)] + l1.force_y * z[y(n_)] + l1.moment * z[end_angle()]);
  return e;
}

double DiscreteLagrangian::value(const Eigen::VectorXd& z) const {
  double l = energy(z);
  for (std::size_t i = 0; i < n_; ++i) {
    const Chord c = chord(z, i);
    l += z[nx(i)] * (z[x(i + 1)] - z[x(i)] - c.g.x()) + z[ny(i)] * (z[y(i + 1)] - z[y(i)] - c.g.y());
    if (compliant()) {
      const Eigen::Vector2d n(z[nx(i)], z[ny(i)]);
      l -= 0.5 * h_ * n.dot(compliance(z, i).c * n);
    }
  }
  for (std::size_t k = 0; k < rows_.size(); ++k)
    l += z[row_index_[k]] * (z[rows_[k].dof] - rows_[k].target);
  return l;
}

Eigen::VectorXd DiscreteLagrangian::gradient(const Eigen::VectorXd& z) const {
  Eigen::VectorXd g = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(size_));
  for (const BendingTerm& t : bending_) {
    const double r = t.w * (t.c0 * z[t.j0] + t.c1 * z[t.j1] - t.b);
    g[t.j0] += r * t.c0;
    g[t.j1] += r * t.c1;
  }
  const EndLoad& l0 = problem_.start.load;
  const EndLoad& l1 = problem_.end.load;
  g[x(0)] -= lambda_ * l0.force_x;
  g[y(0)] -= lambda_ * l0.force_y;
  g[start_angle()] -= lambda_ * l0.moment;
  g[x(n_)] -= lambda_ * l1.force_x;
  g[y(n_)] -= lambda_ * l1.force_y;
  g[end_angle()] -= lambda_ * l1.moment;
  if (problem_.potential.active())
    for (std::size_t i = 0; i <= n_; ++i) {
      const Eigen::Vector2d dv = problem_.potential.gradient(z[x(i)], z[y(i)]);
      const double w = lambda_ * node_weight(i);
      g[x(i)] += w * dv.x();
      g[y(i)] += w * dv.y();
    }
  const int arity = chord_arity();
  for (std::size_t i = 0; i < n_; ++i) {
    const Chord c = chord(z, i);
    const Eigen::Vector2d n(z[nx(i)], z[ny(i)]);
    g[nx(i)] += z[x(i + 1)] - z[x(i)] - c.g.x();
    g[ny(i)] += z[y(i + 1)] - z[y(i)] - c.g.y();
    g[x(i + 1)] += n.x();
    g[y(i + 1)] += n.y();
    g[x(i)] -= n.x();
    g[y(i)] -= n.y();
    for (int k = 0; k < arity; ++k) g[chord_angle(i, k)] -= n.dot(c.d[k]);
    if (compliant()) {  // - h/2 n^T C n
      const ElementCompliance e = compliance(z, i);
      const Eigen::Vector2d cn = h_ * (e.c * n);
      g[nx(i)] -= cn.x();
      g[ny(i)] -= cn.y();
      for (int k = 0; k < arity; ++k) g[chord_angle(i, k)] -= 0.5 * h_ * n.dot(e.d[k] * n);
    }
  }
  for (std::size_t k = 0; k < rows_.size(); ++k) {
    g[row_index_[k]] += z[rows_[k].dof] - rows_[k].target;
    g[rows_[k].dof] += z[row_index_[k]];
  }
  return g;
}

Eigen::SparseMatrix<double> DiscreteLagrangian::hessian(const Eigen::VectorXd& z) const {
  using T = Eigen::Triplet<double>;
  std::vector<T> triplets;
  triplets.reserve(4 * bending_.size() + 24 * n_ + 4 * (n_ + 1) + 2 * rows_.size());
  auto idx = [](std::size_t i) { return static_cast<Eigen::Index>(i); };
  auto sym = [&](std::size_t i, std::size_t j, double v) {
    triplets.emplace_back(idx(i), idx(j), v);
    if (i != j) triplets.emplace_back(idx(j), idx(i), v);
  };
  for (const BendingTerm& t : bending_) {
    triplets.emplace_back(idx(t.j0), idx(t.j0), t.w * t.c0 * t.c0);
    if (t.c1 != 0.0) {
      sym(t.j0, t.j1, t.w * t.c0 * t.c1);
      triplets.emplace_back(idx(t.j1), idx(t.j1), t.w * t.c1 * t.c1);
    }
  }
  if (problem_.potential.active())
    for (std::size_t i = 0; i <= n_; ++i) {
      const Eigen::Matrix2d hv = lambda_ * node_weight(i) * potential_hessian(z[x(i)], z[y(i)]);
      triplets.emplace_back(idx(x(i)), idx(x(i)), hv(0, 0));
      triplets.emplace_back(idx(x(i)), idx(y(i)), hv(0, 1));
      triplets.emplace_back(idx(y(i)), idx(x(i)), hv(1, 0));
      triplets.emplace_back(idx(y(i)), idx(y(i)), hv(1, 1));
    }
  const int arity = chord_arity();
  for (std::size_t i = 0; i < n_; ++i) {
    const Chord c = chord(z, i);
    const Eigen::Vector2d n(z[nx(i)], z[ny(i)]);
    sym(nx(i), x(i + 1), 1.0);
    sym(ny(i), y(i + 1), 1.0);
    sym(nx(i), x(i), -1.0);
    sym(ny(i), y(i), -1.0);
    for (int k = 0; k < arity; ++k) {
      sym(nx(i), chord_angle(i, k), -c.d[k].x());
      sym(ny(i), chord_angle(i, k), -c.d[k].y());
      for (int l = 0; l < arity; ++l)
        triplets.emplace_back(idx(chord_angle(i, k)), idx(chord_angle(i, l)), -n.dot(c.dd[k][l]));
    }
    if (compliant()) {  // second derivatives of - h/2 n^T C(angles) n
      const ElementCompliance e = compliance(z, i);
      triplets.emplace_back(idx(nx(i)), idx(nx(i)), -h_ * e.c(0, 0));
      sym(nx(i), ny(i), -h_ * e.c(0, 1));
      triplets.emplace_back(idx(ny(i)), idx(ny(i)), -h_ * e.c(1, 1));
      for (int k = 0; k < arity; ++k) {
        const Eigen::Vector2d dn = h_ * (e.d[k] * n);
        sym(nx(i), chord_angle(i, k), -dn.x());
        sym(ny(i), chord_angle(i, k), -dn.y());
        for (int l = 0; l < arity; ++l)
          triplets.emplace_back(idx(chord_angle(i, k)), idx(chord_angle(i, l)),
                                -0.5 * h_ * n.dot(e.dd[k][l] * n));
      }
    }
  }
  for (std::size_t k = 0; k < rows_.size(); ++k) sym(row_index_[k], rows_[k].dof, 1.0);
  Eigen::SparseMatrix<double> hess(idx(size_), idx(size_));
  hess.setFromTriplets(triplets.begin(), triplets.end());
  return hess;
}

}  // namespace rodvv::solvers::elastica2d
