#include "rodvv/solvers/rod3d/discrete_energy.hpp"

#include <array>
#include <cmath>

#include <Eigen/Geometry>
#include <unsupported/Eigen/AutoDiff>

#include "rodvv/common/errors.hpp"

namespace rodvv::solvers::rod3d {

namespace {

constexpr int kStencil = 11;  // x_{i-1}, theta^{i-1}, x_i, theta^i, x_{i+1}
using StencilVector = Eigen::Matrix<double, kStencil, 1>;
using StencilMatrix = Eigen::Matrix<double, kStencil, kStencil>;
using Inner = Eigen::AutoDiffScalar<StencilVector>;
using Outer = Eigen::AutoDiffScalar<Eigen::Matrix<Inner, kStencil, 1>>;
template <typename T>
using V3 = Eigen::Matrix<T, 3, 1>;

// What a vertex stencil needs from the state it is linearised about.
struct VertexStencil {
  Vec3 t_prev, a_prev, t_next, a_next;  // tangents and reference directors of edges i-1, i
  double reference_twist = 0.0;
};

template <typename T>
V3<T> transport(const V3<T>& from, const V3<T>& to, const V3<T>& v) {
  const V3<T> b = from.cross(to);
  const T c = from.dot(to);
  return c * v + b.cross(v) + (b.dot(v) / (T(1.0) + c)) * b;
}

template <typename T>
V3<T> constant_vector(const Vec3& v) {
  return V3<T>(T(v[0]), T(v[1]), T(v[2]));
}

// (twist angle, kb.m1avg, kb.m2avg) of the stencil z = (x_{i-1}, th_{i-1}, x_i, th_i, x_{i+1}).
template <typename T>
V3<T> stencil_strain(const Eigen::Matrix<T, kStencil, 1>& z, const VertexStencil& st) {
  using std::asin;
  using std::cos;
  using std::sin;
  const V3<T> x0 = z.template segment<3>(0), x1 = z.template segment<3>(4), x2 = z.template segment<3>(8);
  const T th0 = z[3], th1 = z[7];
  const V3<T> e = x1 - x0, f = x2 - x1;
  const V3<T> te = e / e.norm(), tf = f / f.norm();
  // Reference directors carried from the state's tangents to the trial ones (time-parallel transport).
  const V3<T> ae = transport<T>(constant_vector<T>(st.t_prev), te, constant_vector<T>(st.a_prev));
  const V3<T> af = transport<T>(constant_vector<T>(st.t_next), tf, constant_vector<T>(st.a_next));
  const V3<T> be = te.cross(ae), bf = tf.cross(af);
  const T ce = cos(th0), se = sin(th0), cf = cos(th1), sf = sin(th1);
  const V3<T> m1 = ce * ae + se * be + cf * af + sf * bf;   // 2 x the average m1
  const V3<T> m2 = ce * be - se * ae + cf * bf - sf * af;   // 2 x the average m2
  const V3<T> kb = (T(2.0) / (T(1.0) + te.dot(tf))) * te.cross(tf);
  // Reference twist = the state's value + the signed angle, about tf, from the space-parallel
  // transport of ae (turned back by the state's reference twist) to af. Near the state this angle
  // is small, so asin of its sine is exact and smooth (|angle| < pi/2 is checked on every update).
  const T c0 = T(std::cos(st.reference_twist)), s0 = T(std::sin(st.reference_twist));
  const V3<T> p = transport<T>(te, tf, ae);
  const V3<T> p_turned = c0 * p + s0 * tf.cross(p);
  const T twist = th1 - th0 + T(st.reference_twist) + asin(p_turned.cross(af).dot(tf));
  return V3<T>(twist, T(0.5) * kb.dot(m1), T(0.5) * kb.dot(m2));
}

template <typename T>
T stencil_energy(const Eigen::Matrix<T, kStencil, 1>& z, const VertexStencil& st, const Vec3& stiffness,
                 const Vec3& natural_integrated, double voronoi) {
  const V3<T> k = stencil_strain<T>(z, st);
  T energy(0.0);
  for (int a = 0; a < 3; ++a) {
    const T d = k[a] - T(natural_integrated[a]);
    energy += T(0.5 * stiffness[a] / voronoi) * d * d;
  }
  return energy;
}

// One evaluation: the chart of `base` (its tangents, reference directors and twists), at the
// configuration base + dz (dz empty: at the base itself).
struct Context {
  const RodModel& model;
  const RodState& base;
  RodState state;  // the evaluated configuration (positions, angles, multipliers)
  DofLayout layout;
  double ell;
  std::vector<Vec3> tangent;

  Context(const RodModel& m, const RodState& b, const VecX* dz = nullptr)
      : model(m), base(b), state(b), layout(m), ell(rest_edge_length(m)) {
    if (b.position.size() != m.elements + 1 || b.angle.size() != m.elements ||
        b.reference_director.size() != m.elements || b.reference_twist.size() != m.elements + 1 ||
        (layout.multipliers && b.multiplier.size() != m.elements))
      throw InputError("state", "invalid parameter 'state': its sizes do not match the model's " +
                                    std::to_string(m.elements) + " elements");
    tangent = edge_tangents(b);
    if (dz) {
      if (dz->size() != Eigen::Index(layout.size()))
        throw InputError("dz", "invalid parameter 'dz': must hold " + std::to_string(layout.size()) + " values");
      for (std::size_t i = 0; i <= m.elements; ++i) state.position[i] += dz->segment<3>(Eigen::Index(layout.vertex(i)));
      for (std::size_t j = 0; j < m.elements; ++j) {
        state.angle[j] += (*dz)[Eigen::Index(layout.angle(j))];
        if (layout.multipliers) state.multiplier[j] += (*dz)[Eigen::Index(layout.multiplier(j))];
      }
    }
  }

  VertexStencil stencil(std::size_t i) const {
    return {tangent[i - 1], base.reference_director[i - 1], tangent[i], base.reference_director[i],
            base.reference_twist[i]};
  }
  StencilVector stencil_dofs(std::size_t i) const {
    StencilVector z;
    z.segment<3>(0) = state.position[i - 1];
    z[3] = state.angle[i - 1];
    z.segment<3>(4) = state.position[i];
    z[7] = state.angle[i];
    z.segment<3>(8) = state.position[i + 1];
    return z;
  }
  // Global index of local stencil dof k of vertex i.
  std::array<std::size_t, kStencil> stencil_index(std::size_t i) const {
    std::array<std::size_t, kStencil> index{};
    for (int k = 0; k < 3; ++k) {
      index[k] = layout.vertex(i - 1) + k;
      index[4 + k] = layout.vertex(i) + k;
      index[8 + k] = layout.vertex(i + 1) + k;
    }
    index[3] = layout.angle(i - 1);
    index[7] = layout.angle(i);
    return index;
  }
  double voronoi() const { return ell; }  // uniform rest edges: lbar_i = ebar
  Vec3 natural_integrated() const { return model.natural_strain * voronoi(); }
  double vertex_mass(std::size_t i) const {
    return model.line_density * ell * ((i == 0 || i == model.elements) ? 0.5 : 1.0);
  }
};

void stencil_gradient_hessian(const Context& c, std::size_t i, StencilVector& gradient, StencilMatrix* hessian) {
  const StencilVector z0 = c.stencil_dofs(i);
  if (!hessian) {
    Eigen::Matrix<Inner, kStencil, 1> z;
    for (int k = 0; k < kStencil; ++k) z[k] = Inner(z0[k], kStencil, k);
    const Inner e = stencil_energy<Inner>(z, c.stencil(i), c.model.stiffness, c.natural_integrated(), c.voronoi());
    gradient = e.derivatives();
    return;
  }
  Eigen::Matrix<Outer, kStencil, 1> z;
  for (int k = 0; k < kStencil; ++k) {
    z[k].value() = Inner(z0[k], kStencil, k);
    z[k].derivatives() = Eigen::Matrix<Inner, kStencil, 1>::Constant(Inner(0.0));
    z[k].derivatives()[k] = Inner(1.0);
  }
  const Outer e = stencil_energy<Outer>(z, c.stencil(i), c.model.stiffness, c.natural_integrated(), c.voronoi());
  gradient = e.value().derivatives();
  for (int a = 0; a < kStencil; ++a) hessian->row(a) = e.derivatives()[a].derivatives().transpose();
}

using Triplets = std::vector<Eigen::Triplet<double>>;

void add_block(Triplets& t, std::size_t row, std::size_t col, const Mat3& block) {
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      if (block(a, b) != 0.0) t.emplace_back(int(row + a), int(col + b), block(a, b));
}

// Internal forces and stiffness of the edges: stretching (extensible) or the constraints
// c_j = |e_j| - ebar (inextensible; the multiplier rows hold c_j).
void add_edges(const Context& c, VecX& r, Triplets* jac) {
  const auto& m = c.model;
  for (std::size_t j = 0; j < m.elements; ++j) {
    const Vec3 e = c.state.position[j + 1] - c.state.position[j];
    const double len = e.norm();
    const Vec3 t = e / len;
    const Mat3 transverse = (Mat3::Identity() - t * t.transpose()) / len;  // d t / d e
    const std::size_t a = c.layout.vertex(j), b = c.layout.vertex(j + 1);
    double tension;
    Mat3 stiffness;
    if (c.layout.multipliers) {
      tension = c.state.multiplier[j];
      stiffness = tension * transverse;
      const std::size_t k = c.layout.multiplier(j);
      r[k] += len - c.ell;
      if (jac)
        for (int q = 0; q < 3; ++q) {
          jac->emplace_back(int(k), int(b + q), t[q]);
          jac->emplace_back(int(k), int(a + q), -t[q]);
          jac->emplace_back(int(b + q), int(k), t[q]);
          jac->emplace_back(int(a + q), int(k), -t[q]);
        }
    } else {
      const double strain = len / c.ell - 1.0;
      tension = m.extensional_stiffness * strain;
      stiffness = (m.extensional_stiffness / c.ell) * t * t.transpose() + tension * transverse;
    }
    r.segment<3>(b) += tension * t;
    r.segment<3>(a) -= tension * t;
    if (jac) {
      add_block(*jac, b, b, stiffness);
      add_block(*jac, a, a, stiffness);
      add_block(*jac, a, b, -stiffness);
      add_block(*jac, b, a, -stiffness);
    }
  }
}

// Generalised loads times the load factor: residual -= Q, Jacobian -= dQ/dz.
void add_loads(const Context& c, double load_factor, VecX& r, Triplets* jac) {
  const auto& m = c.model;
  for (std::size_t i = 0; i <= m.elements; ++i) r.segment<3>(c.layout.vertex(i)) -= load_factor * c.vertex_mass(i) * m.gravity;
  r.segment<3>(c.layout.vertex(m.elements)) -= load_factor * m.end_force;
  if (m.end_moment.isZero(0.0)) return;
  // Dead moment M on the tip edge e: couple (M x e)/|e|^2 on (x_N, -x_{N-1}), M.t on theta^{N-1}.
  const std::size_t last = m.elements - 1;
  const Vec3 e = c.state.position[m.elements] - c.state.position[last];
  const double len2 = e.squaredNorm(), len = std::sqrt(len2);
  const Vec3 M = load_factor * m.end_moment;
  const Vec3 couple = M.cross(e) / len2;
  const std::size_t a = c.layout.vertex(last), b = c.layout.vertex(m.elements), th = c.layout.angle(last);
  r.segment<3>(b) -= couple;
  r.segment<3>(a) += couple;
  r[th] -= M.dot(e) / len;
  if (!jac) return;
  Mat3 cross_m;
  cross_m << 0, -M[2], M[1], M[2], 0, -M[0], -M[1], M[0], 0;
  const Mat3 dcouple = cross_m * (Mat3::Identity() / len2 - 2.0 * e * e.transpose() / (len2 * len2));
  add_block(*jac, b, b, -dcouple);
  add_block(*jac, b, a, dcouple);
  add_block(*jac, a, b, dcouple);
  add_block(*jac, a, a, -dcouple);
  const Vec3 t = e / len;
  const Vec3 dtwist = (M - M.dot(t) * t) / len;  // d(M.t)/de
  for (int q = 0; q < 3; ++q) {
    jac->emplace_back(int(th), int(b + q), -dtwist[q]);
    jac->emplace_back(int(th), int(a + q), dtwist[q]);
  }
}

void assemble(const Context& c, double load_factor, VecX& r, Triplets* jac) {
  r = VecX::Zero(Eigen::Index(c.layout.size()));
  StencilVector g;
  StencilMatrix h;
  for (std::size_t i = 1; i < c.model.elements; ++i) {
    stencil_gradient_hessian(c, i, g, jac ? &h : nullptr);
    const auto index = c.stencil_index(i);
    for (int a = 0; a < kStencil; ++a) {
      r[Eigen::Index(index[a])] += g[a];
      if (jac)
        for (int b = 0; b < kStencil; ++b)
          if (h(a, b) != 0.0) jac->emplace_back(int(index[a]), int(index[b]), h(a, b));
    }
  }
  add_edges(c, r, jac);
  add_loads(c, load_factor, r, jac);
}

}  // namespace

std::vector<Vec3> integrated_strains(const RodModel& model, const RodState& state) {
  validate(model);
  const Context c(model, state);
  std::vector<Vec3> k(model.elements + 1, Vec3::Zero());
  for (std::size_t i = 1; i < model.elements; ++i) k[i] = stencil_strain<double>(c.stencil_dofs(i), c.stencil(i));
  return k;
}

EnergyParts energy(const RodModel& model, const RodState& state) {
  validate(model);
  const Context c(model, state);
  EnergyParts parts;
  const Vec3 natural = c.natural_integrated();
  for (std::size_t i = 1; i < model.elements; ++i) {
    const Vec3 k = stencil_strain<double>(c.stencil_dofs(i), c.stencil(i)) - natural;
    parts.twisting += 0.5 * model.stiffness[0] * k[0] * k[0] / c.voronoi();
    parts.bending += 0.5 * (model.stiffness[1] * k[1] * k[1] + model.stiffness[2] * k[2] * k[2]) / c.voronoi();
  }
  if (!c.layout.multipliers)
    for (std::size_t j = 0; j < model.elements; ++j) {
      const double strain = (state.position[j + 1] - state.position[j]).norm() / c.ell - 1.0;
      parts.stretching += 0.5 * model.extensional_stiffness * strain * strain * c.ell;
    }
  for (std::size_t i = 0; i <= model.elements; ++i) parts.gravity -= c.vertex_mass(i) * model.gravity.dot(state.position[i]);
  parts.tip_force = -model.end_force.dot(state.position[model.elements]);
  return parts;
}

VecX chart_residual(const RodModel& model, const RodState& base, const VecX& dz, double load_factor) {
  validate(model);
  const Context c(model, base, &dz);
  VecX r;
  assemble(c, load_factor, r, nullptr);
  return r;
}

VecX static_residual(const RodModel& model, const RodState& state, double load_factor) {
  validate(model);
  const Context c(model, state);
  VecX r;
  assemble(c, load_factor, r, nullptr);
  return r;
}

void static_system(const RodModel& model, const RodState& state, double load_factor, VecX& residual,
                   Eigen::SparseMatrix<double>& jacobian) {
  chart_system(model, state, VecX(), load_factor, residual, jacobian);
}

void chart_system(const RodModel& model, const RodState& base, const VecX& dz, double load_factor, VecX& residual,
                  Eigen::SparseMatrix<double>& jacobian) {
  validate(model);
  const Context c(model, base, dz.size() ? &dz : nullptr);
  Triplets triplets;
  triplets.reserve(model.elements * (kStencil * kStencil + 40));
  assemble(c, load_factor, residual, &triplets);
  const auto n = Eigen::Index(c.layout.size());
  jacobian.resize(n, n);
  jacobian.setFromTriplets(triplets.begin(), triplets.end());
}

RodState displaced(const RodModel& model, const RodState& state, const VecX& dz, double* largest_twist_change) {
  const DofLayout layout(model);
  RodState next = state;
  const auto previous = edge_tangents(state);
  for (std::size_t i = 0; i <= model.elements; ++i) next.position[i] += dz.segment<3>(Eigen::Index(layout.vertex(i)));
  for (std::size_t j = 0; j < model.elements; ++j) {
    next.angle[j] += dz[Eigen::Index(layout.angle(j))];
    if (layout.multipliers) next.multiplier[j] += dz[Eigen::Index(layout.multiplier(j))];
  }
  const double change = transport_reference_frames(next, previous);
  if (largest_twist_change) *largest_twist_change = change;
  return next;
}

std::vector<Vec3> elastic_vertex_forces(const RodModel& model, const RodState& state) {
  validate(model);
  const Context c(model, state);
  VecX r = VecX::Zero(Eigen::Index(c.layout.size()));
  StencilVector g;
  for (std::size_t i = 1; i < model.elements; ++i) {
    stencil_gradient_hessian(c, i, g, nullptr);
    const auto index = c.stencil_index(i);
    for (int a = 0; a < kStencil; ++a) r[Eigen::Index(index[a])] += g[a];
  }
  add_edges(c, r, nullptr);
  std::vector<Vec3> forces(model.elements + 1);
  for (std::size_t i = 0; i <= model.elements; ++i) forces[i] = r.segment<3>(Eigen::Index(c.layout.vertex(i)));
  return forces;
}

}  // namespace rodvv::solvers::rod3d
