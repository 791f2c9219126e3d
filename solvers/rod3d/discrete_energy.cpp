#include "rodvv/solvers/rod3d/discrete_energy.hpp"

#include <array>
#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "rodvv/common/errors.hpp"
#include "taylor2.hpp"
#include "vertex_chart.hpp"

// The bending-twisting energy of the discrete elastic rod (Bergou, Wardetzky, Robinson, Audoly &
// Grinspun, "Discrete Elastic Rods", ACM TOG 27(3) 63, 2008; with the reference frame carried by
// time-parallel transport and the reference twist bookkeeping of Bergou, Audoly, Vouga, Wardetzky &
// Grinspun, "Discrete Viscous Threads", ACM TOG 29(4) 116, 2010) is a sum over interior vertices i
// of stencil energies
//     E_i = 1/2 (k - k0)^T K (k - k0) / lbar,   K = diag(GJ, EI1, EI2),   k0 = lbar (natural strains),
// with k = (twist angle, kb.m1avg, kb.m2avg) the integrated strains of the 11 stencil dofs
// z = (x_{i-1}, theta^{i-1}, x_i, theta^i, x_{i+1}). Newton needs dE_i/dz and d2E_i/dz2 exactly.
//
// How they are computed (the hot loop of every rod3d solve: it was nested Eigen AutoDiffScalar over
// the 11 dofs, ~70 us per stencil Hessian and ~2 us per gradient; now ~3 us and ~0.4 us - see
// bench/bench_rod3d.cpp, BM_NewtonIteration and BM_Residual):
//  1. k depends on the positions only through the edge vectors e = x_i - x_{i-1}, f = x_{i+1} - x_i,
//     so k is differentiated in the 8 reduced variables w = (e, f, theta^{i-1}, theta^i) and the
//     result mapped back with the constant matrix A = dw/dz (entries 0, +-1): g_z = A^T g_w,
//     H_z = A^T H_w A - exact, w being linear in z.
//  2. Each quantity is differentiated only in the variables it depends on: an edge's frame (unit
//     tangent, transported reference director, binormal) in its own edge vector (3 variables); the
//     curvature binormal, its components on the frames and the reference twist in (e, f) (6); only
//     the last step, which brings in the material angles, in all 8 (see "exact derivatives" below).
//  3. Second-order forward jets (taylor2.hpp: value, gradient, symmetric Hessian in one pass per
//     operation) give k_a, its gradient J_a and Hessian Hk_a; then, with s = K (k - k0) / lbar,
//         g_w = J^T s,   H_w = J^T (K / lbar) J + sum_a s_a Hk_a
//     (the Gauss-Newton part plus the curvature of the strain map - both exact).
// The gradient-only paths (residuals) run the same code with first-order jets, the energy with
// doubles: the strain formulas are written once, generic in the scalar type.
// Checks (tests/solvers/test_rod3d.cpp): the jets against finite differences, the stencil gradient
// and Hessian against the previous nested-AutoDiff implementation (to 1e-12 relative), the global
// residual and Jacobian against finite differences of the energy and the residual.

namespace rodvv::solvers::rod3d {

namespace {

constexpr int kStencil = 11;  // x_{i-1}, theta^{i-1}, x_i, theta^i, x_{i+1}
constexpr int kReduced = 8;   // w = (e = x_i - x_{i-1}, f = x_{i+1} - x_i, theta^{i-1}, theta^i)
using StencilVector = Eigen::Matrix<double, kStencil, 1>;
using StencilMatrix = Eigen::Matrix<double, kStencil, kStencil>;

// What a vertex stencil needs from the state it is linearised about.
struct VertexStencil {
  Vec3 t_prev, a_prev, t_next, a_next;  // tangents and reference directors of edges i-1, i
  double reference_twist = 0.0;
};

// ---- generic 3-vector algebra ----------------------------------------------------------------------
// std::array rather than Eigen vectors so that any scalar works without Eigen NumTraits, and so that
// constant vectors (V3<double>) enter products as constants: a double times a jet is a scaling, a jet
// times a jet a full second-order product. Every result is converted to the named scalar T at once,
// so the helpers also accept scalars whose arithmetic returns expression templates.
template <typename T>
using V3 = std::array<T, 3>;

V3<double> v3(const Vec3& v) { return {v[0], v[1], v[2]}; }

template <typename T, typename A, typename B>
T vdot(const V3<A>& a, const V3<B>& b) {
  return T(a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
}
template <typename T, typename A, typename B>
V3<T> vcross(const V3<A>& a, const V3<B>& b) {
  return {T(a[1] * b[2] - a[2] * b[1]), T(a[2] * b[0] - a[0] * b[2]), T(a[0] * b[1] - a[1] * b[0])};
}
template <typename T, typename S, typename A>
V3<T> vscale(const S& s, const V3<A>& a) {
  return {T(s * a[0]), T(s * a[1]), T(s * a[2])};
}
template <typename T>
V3<T> vadd(const V3<T>& a, const V3<T>& b) {
  return {T(a[0] + b[0]), T(a[1] + b[1]), T(a[2] + b[2])};
}

// The parallel transport (the rotation about from x to taking the unit vector `from` to the unit
// vector `to`) applied to v, given b = from x to and c = from . to:  c v + b x v + (b.v / (1 + c)) b.
template <typename T, typename V>
V3<T> rotate(const V3<T>& b, const T& c, const V3<V>& v) {
  const T s = T(vdot<T>(b, v) / (1.0 + c));
  return vadd(vadd(vscale<T>(c, v), vcross<T>(b, v)), vscale<T>(s, b));
}

// ---- the strains of a stencil (written once for every scalar) -------------------------------------

// One edge's unit tangent t, reference director a and a's partner t x a, as functions of the edge
// vector alone: a is the state's reference director carried from the state's tangent to t by
// parallel transport (time-parallel transport, Bergou et al. 2010).
template <typename T>
struct EdgeFrame {
  V3<T> t, a, b;
};

template <typename T>
EdgeFrame<T> edge_frame(const V3<T>& edge, const Vec3& t_state, const Vec3& a_state) {
  using std::sqrt;
  const T length = sqrt(vdot<T>(edge, edge));
  EdgeFrame<T> frame;
  frame.t = {T(edge[0] / length), T(edge[1] / length), T(edge[2] / length)};
  const V3<double> from = v3(t_state);
  frame.a = rotate<T>(vcross<T>(from, frame.t), vdot<T>(from, frame.t), v3(a_state));
  frame.b = vcross<T>(frame.t, frame.a);
  return frame;
}

// The integrated strains k = (twist angle, kb.m1avg, kb.m2avg) of a vertex (Bergou et al. 2008:
// curvature binormal kb = 2 te x tf / (1 + te.tf); material directors m1 = cos(theta) a + sin(theta) b,
// m2 = cos(theta) b - sin(theta) a on each edge, here averaged over the two edges; twist =
// theta^i - theta^{i-1} + reference twist), in two stages so that the jets can be staged by what
// each quantity depends on (see the top of the file):
//   bend_twist       - the terms that depend on the two edge frames but not on the material angles:
//                      kb.a and kb.b of both edges, and the reference twist;
//   material_strains - k from those and the material angles, kb distributed over the sum:
//                        kb.m1avg = 1/2 kb.(m1^{i-1} + m1^i)
//                                 = 1/2 (cos th0 kb.ae + sin th0 kb.be + cos th1 kb.af + sin th1 kb.bf),
//                      and likewise for m2.
// These are the formulas of the previous single-function stencil_strain (now in the test file as the
// reference) with kb distributed over the sum and te x tf, te.tf shared between kb and the transport
// te -> tf: the same math and the same chart conventions (transported reference directors, asin of
// the reference-twist increment), the values differing only by round-off.
template <typename T>
struct BendTwist {
  T kb_ae, kb_be, kb_af, kb_bf;  // kb . (a, b) of edges i-1 (e) and i (f)
  T reference_twist;             // continued from the state's
};

template <typename T>
BendTwist<T> bend_twist(const EdgeFrame<T>& e, const EdgeFrame<T>& f, double state_reference_twist) {
  using std::asin;
  const V3<T> b = vcross<T>(e.t, f.t);  // te x tf, shared by kb and the transport te -> tf
  const T c = vdot<T>(e.t, f.t);
  const V3<T> kb = vscale<T>(T(2.0 / (1.0 + c)), b);
  // Reference twist = the state's value + the signed angle, about tf, from the space-parallel
  // transport of ae (turned back by the state's reference twist) to af. Near the state this angle
  // is small, so asin of its sine is exact and smooth (|angle| < pi/2 is checked on every update).
  const double c0 = std::cos(state_reference_twist), s0 = std::sin(state_reference_twist);
  const V3<T> p = rotate<T>(b, c, e.a);
  const V3<T> p_turned = vadd(vscale<T>(c0, p), vscale<T>(s0, vcross<T>(f.t, p)));
  return {vdot<T>(kb, e.a), vdot<T>(kb, e.b), vdot<T>(kb, f.a), vdot<T>(kb, f.b),
          T(state_reference_twist + asin(vdot<T>(vcross<T>(p_turned, f.a), f.t)))};
}

template <typename T>
V3<T> material_strains(const BendTwist<T>& bt, const T& th0, const T& th1) {
  using std::cos;
  using std::sin;
  const T ce = cos(th0), se = sin(th0), cf = cos(th1), sf = sin(th1);
  return {T(th1 - th0 + bt.reference_twist),
          T(0.5 * (ce * bt.kb_ae + se * bt.kb_be + cf * bt.kb_af + sf * bt.kb_bf)),
          T(0.5 * (ce * bt.kb_be - se * bt.kb_ae + cf * bt.kb_bf - sf * bt.kb_af))};
}

// The strains at plain values (energy, integrated_strains).
Vec3 stencil_strain_value(const StencilVector& z, const VertexStencil& st) {
  const V3<double> e{z[4] - z[0], z[5] - z[1], z[6] - z[2]}, f{z[8] - z[4], z[9] - z[5], z[10] - z[6]};
  const V3<double> k = material_strains<double>(
      bend_twist<double>(edge_frame<double>(e, st.t_prev, st.a_prev), edge_frame<double>(f, st.t_next, st.a_next),
                         st.reference_twist),
      z[3], z[7]);
  return Vec3(k[0], k[1], k[2]);
}

// ---- exact derivatives with jets -------------------------------------------------------------------
//
// Reduced variables w = (e, f, theta^{i-1}, theta^i) (8), edge variables (e) and (f) (3 each):
//   edge_frame       Jet<3>  per edge, lifted to Jet<6> at offset 0 (e) or 3 (f);
//   bend_twist       Jet<6>  (e, f), lifted to Jet<8> at offset 0;
//   material_strains Jet<8>  with theta^{i-1}, theta^i the variables 6 and 7.
// The bulk of the work (bend_twist) thus runs on 6 variables (21 Hessian entries) and the frames on 3.

constexpr int kPair = 6;  // (e, f)

// w = A z: reduced variable w_slot enters stencil dof p with the given sign (x_i enters e and f).
struct ReducedTerm {
  int slot;
  double sign;
};
struct ReducedTerms {
  int count;
  std::array<ReducedTerm, 2> term;
};
constexpr std::array<ReducedTerms, kStencil> kReducedOf{{
    {1, {{{0, -1.0}, {}}}}, {1, {{{1, -1.0}, {}}}}, {1, {{{2, -1.0}, {}}}},                     // x_{i-1}: -e
    {1, {{{6, 1.0}, {}}}},                                                                      // theta^{i-1}
    {2, {{{0, 1.0}, {3, -1.0}}}}, {2, {{{1, 1.0}, {4, -1.0}}}}, {2, {{{2, 1.0}, {5, -1.0}}}},  // x_i: e - f
    {1, {{{7, 1.0}, {}}}},                                                                      // theta^i
    {1, {{{3, 1.0}, {}}}}, {1, {{{4, 1.0}, {}}}}, {1, {{{5, 1.0}, {}}}},                        // x_{i+1}: f
}};

template <int M, int N, int O>
EdgeFrame<taylor2::Jet<M, O>> lift_frame(const EdgeFrame<taylor2::Jet<N, O>>& frame, int offset) {
  EdgeFrame<taylor2::Jet<M, O>> r;
  for (std::size_t q = 0; q < 3; ++q) {
    r.t[q] = taylor2::lift<M>(frame.t[q], offset);
    r.a[q] = taylor2::lift<M>(frame.a[q], offset);
    r.b[q] = taylor2::lift<M>(frame.b[q], offset);
  }
  return r;
}

// Gradient (and, for Order 2, Hessian) of the stencil energy with respect to its 11 dofs z.
template <int Order>
void stencil_derivatives(const StencilVector& z, const VertexStencil& st, const Vec3& stiffness,
                         const Vec3& natural_integrated, double voronoi, StencilVector& gradient,
                         StencilMatrix* hessian) {
  using EdgeJet = taylor2::Jet<3, Order>;
  using PairJet = taylor2::Jet<kPair, Order>;
  using Jet = taylor2::Jet<kReduced, Order>;
  V3<EdgeJet> e, f;
  for (int q = 0; q < 3; ++q) {
    e[std::size_t(q)] = EdgeJet::variable(z[4 + q] - z[q], q);
    f[std::size_t(q)] = EdgeJet::variable(z[8 + q] - z[4 + q], q);
  }
  const BendTwist<PairJet> bt = bend_twist<PairJet>(lift_frame<kPair>(edge_frame<EdgeJet>(e, st.t_prev, st.a_prev), 0),
                                                    lift_frame<kPair>(edge_frame<EdgeJet>(f, st.t_next, st.a_next), 3),
                                                    st.reference_twist);
  const BendTwist<Jet> lifted{taylor2::lift<kReduced>(bt.kb_ae, 0), taylor2::lift<kReduced>(bt.kb_be, 0),
                              taylor2::lift<kReduced>(bt.kb_af, 0), taylor2::lift<kReduced>(bt.kb_bf, 0),
                              taylor2::lift<kReduced>(bt.reference_twist, 0)};
  const V3<Jet> k = material_strains<Jet>(lifted, Jet::variable(z[3], 6), Jet::variable(z[7], 7));

  // E = sum_a 1/2 w_a (k_a - k0_a)^2 with w_a = K_a / lbar (the vertex-based bending and twisting
  // energies of Bergou et al. 2008):  g_w = sum_a w_a d_a J_a,  H_w = sum_a w_a (J_a J_a^T + d_a Hk_a).
  std::array<double, kReduced> gw{};
  std::array<double, Jet::kHessianSize> hw{};  // packed like a Jet's Hessian
  for (std::size_t a = 0; a < 3; ++a) {
    const double w = stiffness[Eigen::Index(a)] / voronoi, d = k[a].v - natural_integrated[Eigen::Index(a)];
    for (int m = 0; m < kReduced; ++m) gw[m] += w * d * k[a].g[m];
    if constexpr (Order == 2) {
      int slot = 0;
      for (int n = 0; n < kReduced; ++n)
        for (int m = n; m < kReduced; ++m, ++slot) hw[slot] += w * (k[a].g[m] * k[a].g[n] + d * k[a].h[slot]);
    }
  }
  // Back to z: g_z = A^T g_w, H_z = A^T H_w A (A has at most two nonzeros, +-1, per column).
  for (int p = 0; p < kStencil; ++p) {
    const auto& rp = kReducedOf[std::size_t(p)];
    double sum = 0.0;
    for (int s = 0; s < rp.count; ++s) sum += rp.term[s].sign * gw[rp.term[s].slot];
    gradient[p] = sum;
  }
  if constexpr (Order == 2) {
    const auto hw_at = [&](int m, int n) { return m >= n ? hw[Jet::packed(m, n)] : hw[Jet::packed(n, m)]; };
    for (int q = 0; q < kStencil; ++q) {
      const auto& rq = kReducedOf[std::size_t(q)];
      for (int p = q; p < kStencil; ++p) {
        const auto& rp = kReducedOf[std::size_t(p)];
        double sum = 0.0;
        for (int t = 0; t < rq.count; ++t)
          for (int s = 0; s < rp.count; ++s)
            sum += rp.term[s].sign * rq.term[t].sign * hw_at(rp.term[s].slot, rq.term[t].slot);
        (*hessian)(p, q) = sum;
        (*hessian)(q, p) = sum;
      }
    }
  }
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
  if (hessian)
    stencil_derivatives<2>(c.stencil_dofs(i), c.stencil(i), c.model.stiffness, c.natural_integrated(), c.voronoi(),
                           gradient, hessian);
  else
    stencil_derivatives<1>(c.stencil_dofs(i), c.stencil(i), c.model.stiffness, c.natural_integrated(), c.voronoi(),
                           gradient, nullptr);
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

// The self-contact barrier (self_contact.hpp) on the evaluated positions: residual += dE/dx, Jacobian +=
// its Hessian, mapped from vertex coordinates to the DofLayout.
void add_self_contact(const Context& c, VecX& r, Triplets* jac) {
  if (!has_self_contact(c.model) || is_hard(c.model.self_contact)) return;  // hard: forces are unknowns (statics)
  std::vector<Vec3> gradient;
  Triplets hessian;
  self_contact_derivatives(c.model.self_contact, c.state.position, c.ell, gradient, jac ? &hessian : nullptr);
  for (std::size_t i = 0; i < gradient.size(); ++i) r.segment<3>(Eigen::Index(c.layout.vertex(i))) += gradient[i];
  if (!jac) return;
  const auto dof = [&](int coordinate) { return int(c.layout.vertex(std::size_t(coordinate) / 3)) + coordinate % 3; };
  for (const auto& entry : hessian) jac->emplace_back(dof(entry.row()), dof(entry.col()), entry.value());
}

// A dead moment M on edge j (e = x_{j+1} - x_j): the couple (M x e)/|e|^2 on (x_{j+1}, -x_j) and M.t on
// theta^j, the generalised force of its virtual work; residual -= Q, Jacobian -= dQ/dz.
void add_edge_moment(const Context& c, std::size_t j, const Vec3& M, VecX& r, Triplets* jac) {
  const Vec3 e = c.state.position[j + 1] - c.state.position[j];
  const double len2 = e.squaredNorm(), len = std::sqrt(len2);
  const Vec3 couple = M.cross(e) / len2;
  const std::size_t a = c.layout.vertex(j), b = c.layout.vertex(j + 1), th = c.layout.angle(j);
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

// Generalised loads times the load factor: residual -= Q, Jacobian -= dQ/dz.
void add_loads(const Context& c, double load_factor, VecX& r, Triplets* jac) {
  const auto& m = c.model;
  for (std::size_t i = 0; i <= m.elements; ++i) r.segment<3>(c.layout.vertex(i)) -= load_factor * c.vertex_mass(i) * m.gravity;
  r.segment<3>(c.layout.vertex(m.elements)) -= load_factor * m.end_force;
  for (std::size_t i = 0; i < m.vertex_forces.size(); ++i)
    r.segment<3>(c.layout.vertex(i)) -= load_factor * m.vertex_forces[i];
  for (std::size_t j = 0; j < m.edge_moments.size(); ++j)
    if (!m.edge_moments[j].isZero(0.0)) add_edge_moment(c, j, load_factor * m.edge_moments[j], r, jac);
  if (!m.end_moment.isZero(0.0)) add_edge_moment(c, m.elements - 1, load_factor * m.end_moment, r, jac);
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
  add_self_contact(c, r, jac);
  add_loads(c, load_factor, r, jac);
}

}  // namespace

std::vector<Vec3> integrated_strains(const RodModel& model, const RodState& state) {
  validate(model);
  const Context c(model, state);
  std::vector<Vec3> k(model.elements + 1, Vec3::Zero());
  for (std::size_t i = 1; i < model.elements; ++i) k[i] = stencil_strain_value(c.stencil_dofs(i), c.stencil(i));
  return k;
}

EnergyParts energy(const RodModel& model, const RodState& state) {
  validate(model);
  const Context c(model, state);
  EnergyParts parts;
  const Vec3 natural = c.natural_integrated();
  for (std::size_t i = 1; i < model.elements; ++i) {
    const Vec3 k = stencil_strain_value(c.stencil_dofs(i), c.stencil(i)) - natural;
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
  for (std::size_t i = 0; i < model.vertex_forces.size(); ++i)
    parts.vertex_forces -= model.vertex_forces[i].dot(state.position[i]);
  if (has_self_contact(model)) parts.contact = self_contact_energy(model.self_contact, state.position, c.ell);
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

// ---- test hook -------------------------------------------------------------------------------------

namespace detail {

// Not part of the public API: tests/solvers/test_rod3d.cpp declares it and compares it with the
// previous implementation (nested Eigen AutoDiffScalar over the 11 stencil dofs, kept there) and
// with finite differences. The gradient and, for order 2, the Hessian of the bending-twisting energy
// of interior vertex `vertex`'s stencil (dofs x_{i-1}, theta^{i-1}, x_i, theta^i, x_{i+1}) at
// base + dz in the chart of base (dz empty: at base), by the production jets of that order (order 1:
// the residual's path, hessian returned empty).
void stencil_derivatives_for_testing(const RodModel& model, const RodState& base, const VecX& dz, std::size_t vertex,
                                     int order, VecX& gradient, Eigen::MatrixXd& hessian) {
  validate(model);
  const Context c(model, base, dz.size() ? &dz : nullptr);
  if (vertex < 1 || vertex >= model.elements)
    throw InputError("vertex", "invalid parameter 'vertex': must be an interior vertex 1 .. N-1");
  if (order != 1 && order != 2) throw InputError("order", "invalid parameter 'order': must be 1 or 2");
  StencilVector g;
  StencilMatrix h;
  const StencilVector z = c.stencil_dofs(vertex);
  const VertexStencil st = c.stencil(vertex);
  if (order == 2)
    stencil_derivatives<2>(z, st, model.stiffness, c.natural_integrated(), c.voronoi(), g, &h);
  else
    stencil_derivatives<1>(z, st, model.stiffness, c.natural_integrated(), c.voronoi(), g, nullptr);
  gradient = g;
  if (order == 2)
    hessian = h;
  else
    hessian.resize(0, 0);
}

void vertex_stencil_derivatives(const VertexChart& chart, const Eigen::Matrix<double, 11, 1>& dofs, const Vec3& stiffness,
                                const Vec3& natural_integrated, double voronoi, Eigen::Matrix<double, 11, 1>& gradient,
                                Eigen::Matrix<double, 11, 11>& hessian) {
  const VertexStencil st{chart.t_prev, chart.a_prev, chart.t_next, chart.a_next, chart.reference_twist};
  stencil_derivatives<2>(dofs, st, stiffness, natural_integrated, voronoi, gradient, &hessian);
}

Vec3 vertex_stencil_strains(const VertexChart& chart, const Eigen::Matrix<double, 11, 1>& dofs) {
  const VertexStencil st{chart.t_prev, chart.a_prev, chart.t_next, chart.a_next, chart.reference_twist};
  return stencil_strain_value(dofs, st);
}

}  // namespace detail

}  // namespace rodvv::solvers::rod3d
