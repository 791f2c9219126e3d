#pragma once
// The data of a nodal 3-D rod problem: a discrete elastic rod (Bergou et al. 2008, "Discrete
// Elastic Rods"; Bergou et al. 2010, "Discrete Viscous Threads"; ALGORITHMS.md §5) of length L cut
// into N edges of equal rest length L / N, with N + 1 vertices x_0 .. x_N and one material angle
// theta^j per edge.
//
// Frame convention (common/spatial_rod.hpp): the material frame of edge j is (t^j, m1^j, m2^j)
// with t^j the unit edge tangent and m2 = t x m1; the material strains are u = (twist, kappa1,
// kappa2) with kappa1 = curvature about m1 and kappa2 about m2 (R' = R [u]x). Stiffness
// K = diag(GJ, EI1, EI2) acts on u - u_hat.
//
// Energies (ALGORITHMS.md §5, with the strains in the convention above):
//   bending and twisting at interior vertex i:  1/2 (1/lbar_i) (k_i - lbar_i u_hat)^T K (k_i - lbar_i u_hat)
//     k_i = (twist angle m_i, kb_i . m1avg, kb_i . m2avg) (integrated, dimensionless),
//     kb_i = 2 t^{i-1} x t^i / (1 + t^{i-1} . t^i), lbar_i = the rest Voronoi length (= L / N);
//   stretching of edge j: 1/2 EA (|e^j| / ebar - 1)^2 ebar, or, with EA = +inf (the default), the
//     constraint |e^j| = ebar with a Lagrange multiplier (= the axial force n.t of the edge): the
//     inextensible Kirchhoff rod, so that its closed forms apply without a stretching floor.
// Loads (dead): gravity g on the lumped vertex masses rho S lbar (half at the ends), a force and a
// moment at the tip (s = L), and any force on each vertex and moment on each edge (a distributed load
// f(s), c(s) lumped by the caller, e.g. f(s_i) lbar_i and c(s_j) ebar: a manufactured solution's loads).
// A moment on an edge enters as the generalised force of its virtual work: the couple (M x t)/|e| on
// the edge's end vertices and M.t on its material angle; it is not conservative for general 3-D
// rotations (Ziegler), so the static Jacobian is not symmetric then.
//
// Supports at each end: free; pinned (the end vertex held; the end edge's material angle held or
// not); clamped (the end edge held, with its material frame). A clamped end edge is centred on the
// support point (half of it a ghost beyond the rod), so that the Voronoi cell of the first free
// curvature vertex starts at the support: holding instead the edge that starts at the support would
// clamp the rod half an edge too far in, an O(h) error (measured: first order on the Mattiasson
// cantilever). The rest edge length is therefore L / (N - c/2), c the number of clamped ends, and
// vertex i sits at arclength (i - 1/2) ebar past a clamped root, i ebar otherwise. (An extensible
// rod's clamped half edge does not stretch: its axial compliance is that of L - ebar/2, a first-order
// error in the axial extension and the axial frequencies - measured 1/(2N) - that the inextensible
// rod, which every closed-form case uses, does not have.) An imposed
// rotation of the end cross-section about its tangent (for twisting) and the end position (for end
// displacement) are part of the end condition.
//
// Inertia (dynamics, modes): vertex masses rho S lbar; twist inertia rho I0 ebar on each material
// angle (the kinetic energy 1/2 rho I0 (theta-dot)^2 per unit length: with time-parallel
// reference frames the reference frame does not spin about the tangent, so theta-dot is the spin
// of the cross-section; ALGORITHMS.md §5). The rotary inertia of bending (Rayleigh beam) is not
// modelled: an Euler-Bernoulli beam, as the references it is compared with.
//
// validate() throws rodvv::InputError naming the parameter and its allowed range.
#include <cstddef>
#include <limits>
#include <vector>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/rod3d/self_contact.hpp"

namespace rodvv::solvers::rod3d {

enum class EndSupport { Free, Pinned, Clamped };

struct EndCondition {
  EndSupport support = EndSupport::Free;
  Vec3 position = Vec3::Zero();   // pinned: the end vertex; clamped: the support point (the clamped edge's midpoint)
  Mat3 frame = Mat3::Identity();  // clamped: the material frame (t, m1, m2) of the end edge, a rotation
                                  //   (at the tip, t points out of the rod, along +s, as everywhere)
  bool hold_twist = true;         // pinned: the end edge's material angle is held
  double rotation = 0.0;          // extra rotation of the end cross-section about its tangent (rad),
                                  //   |rotation| <= kMaxEndRotation; applied to clamped and twist-held ends
  bool slides = false;            // clamped only: the end edge keeps its tangent and material frame but
                                  //   slides freely along its tangent, which must be a coordinate axis
                                  //   (+-e_x, e_y or e_z: the two transverse coordinates of its two vertices
                                  //   are the held dofs); a dead end_force then pulls it (a rod twisted under
                                  //   constant tension, as in magnetic tweezers)
};

// The largest imposed end rotation: 1000 turns (the continuation follows any smaller value).
inline constexpr double kMaxEndRotation = 2000.0 * 3.14159265358979323846;

struct RodModel {
  std::size_t elements = 16;  // N >= 2 edges (>= 3 with both ends clamped)
  double length = 1.0;
  Vec3 stiffness = Vec3::Ones();       // (GJ, EI1, EI2), > 0
  Vec3 natural_strain = Vec3::Zero();  // u_hat, material components, constant along the rod
  double extensional_stiffness = std::numeric_limits<double>::infinity();  // EA > 0; +inf: inextensible
  double line_density = 1.0;     // rho S > 0 (mass per unit length)
  double twist_inertia = 1e-2;   // rho I0 >= 0 (polar mass moment per unit length); 0 only in statics
  Vec3 gravity = Vec3::Zero();   // acceleration of gravity
  EndCondition root;             // s = 0
  EndCondition tip;              // s = L
  Vec3 end_force = Vec3::Zero();   // dead force at the tip vertex
  Vec3 end_moment = Vec3::Zero();  // dead moment on the tip edge
  std::vector<Vec3> vertex_forces;  // dead force on each vertex x_0 .. x_N: empty (none) or N + 1 values
  std::vector<Vec3> edge_moments;   // dead moment on each edge 0 .. N-1: empty (none) or N values
  SelfContact self_contact;        // radius 0: none; else the barrier of self_contact.hpp (in the energy)
};

// The coordinate axis (0, 1, 2) of a clamp's tangent frame.col(0), or -1 if it is none.
int sliding_axis(const EndCondition& end);

inline bool has_self_contact(const RodModel& model) { return model.self_contact.radius != 0.0; }

void validate(const RodModel& model);

inline double clamped_ends(const RodModel& model) {
  return double(model.root.support == EndSupport::Clamped) + double(model.tip.support == EndSupport::Clamped);
}
inline double rest_edge_length(const RodModel& model) {
  return model.length / (static_cast<double>(model.elements) - 0.5 * clamped_ends(model));
}
// Arclength of vertex i from the root support (negative for the ghost vertex of a clamped root).
inline double vertex_arclength(const RodModel& model, std::size_t i) {
  return (static_cast<double>(i) - (model.root.support == EndSupport::Clamped ? 0.5 : 0.0)) * rest_edge_length(model);
}
// The largest dead load as a force (moments over L): the scale of a residual in force units.
double dead_load_scale(const RodModel& model, double load_factor);

inline bool is_inextensible(const RodModel& model) {
  return model.extensional_stiffness == std::numeric_limits<double>::infinity();
}

// Degrees of freedom, interleaved per edge so that the Jacobian is banded (half-bandwidth 12 with
// multipliers, 10 without): x_j (3), theta^j, [lambda_j,] ..., x_N (3).
struct DofLayout {
  std::size_t elements = 0;
  bool multipliers = true;  // inextensible: one multiplier per edge

  explicit DofLayout(const RodModel& model)
      : elements(model.elements), multipliers(is_inextensible(model)) {}
  std::size_t stride() const noexcept { return multipliers ? 5 : 4; }
  std::size_t vertex(std::size_t i) const noexcept { return stride() * i; }
  std::size_t angle(std::size_t j) const noexcept { return stride() * j + 3; }
  std::size_t multiplier(std::size_t j) const noexcept { return stride() * j + 4; }
  std::size_t size() const noexcept { return stride() * elements + 3; }
};

}  // namespace rodvv::solvers::rod3d
