// superhelix/clothoid-energy-decay: the super-clothoid's dynamics (solvers/superhelix/clothoid_dynamics.hpp),
// which no case ran before (issue 13, class 5): the release of superhelix/energy-decay on the super-clothoid
// rod - a twisted, curved cantilever (natural strains (0.5, 0, 1.2)/L, GJ != EI1 != EI2, a solid elliptic
// section's rotational inertia), clamped in a tilted frame, under gravity along a direction in none of its
// planes, released from its natural shape with nodal strain rates (1.5, 1.0, -0.7): it swings and twists out
// of plane. No damping: the exact flow conserves E = T + U + V (clothoid_total_energy), and semi-implicit
// Euler loses it at first order in h. The production step is the recursive (linear-time) path; at every step
// the dense path's dv is compared with it in the dense system (M + D) dv = b (D = h^2 K, K the clothoid's
// block-tridiagonal stiffness): a relative residual, free of cond(M + D).
#include <algorithm>
#include <cmath>
#include <vector>

#include "../case_builder.hpp"
#include "rodvv/harness/gate.hpp"
#include "rodvv/harness/trajectory_metrics.hpp"
#include "rodvv/solvers/superhelix/clothoid_dynamics.hpp"
#include "rodvv/solvers/superhelix/clothoid_kinematics.hpp"
#include "rodvv/solvers/superhelix/clothoid_statics.hpp"
#include "superhelix_problems.hpp"

namespace rodvv::harness::superhelix_cases {

namespace {

namespace sh = solvers::superhelix;
using namespace cases;

// The level is dt / tau; the step is t_end / round(t_end / dt), so that every level ends at t_end.
LevelOutput run(const Parameters& p, double dt_over_tau) {
  const double t_end = parameter_value(p, "t_end");
  const sh::RodModel model = energy_release_model(4, p, 1.0);
  const auto steps =
      static_cast<std::size_t>(std::max(1.0, std::round(t_end / (dt_over_tau * bending_time(p, "EI1")))));
  const double dt = t_end / double(steps);
  const auto dofs = static_cast<Eigen::Index>(sh::clothoid_dof_count(model));
  sh::DynamicState state{sh::clothoid_natural_strain_vector(model), VecX::Zero(dofs), 0.0};
  const Vec3 rates = energy_release_rates(p);
  for (Eigen::Index node = 0; node < dofs / 3; ++node) state.qdot.segment<3>(3 * node) = rates;
  const MatX stiffness = sh::clothoid_stiffness(model);
  const double e0 = sh::clothoid_total_energy(model, state);
  EnergyLedger ledger(e0);
  double worst_residual = 0.0;
  for (std::size_t i = 0; i < steps; ++i) {
    const VecX dense = sh::clothoid_velocity_change(model, state, dt, sh::DynamicsPath::Dense);
    const VecX fast = sh::clothoid_velocity_change(model, state, dt, sh::DynamicsPath::Recursive);
    const sh::ClothoidKinematics kinematics(model, state.q);
    const MatX system = sh::clothoid_mass_matrix(model, kinematics) + (dt * dt) * stiffness;
    worst_residual = std::max(worst_residual, (system * (dense - fast)).norm() / (system * dense).norm());
    state = sh::clothoid_step(model, state, dt, sh::DynamicsPath::Recursive);  // the production step
    ledger.record(state.time, sh::clothoid_total_energy(model, state));
  }
  LevelOutput output;
  ledger.add_to(output);  // the loss is O(h) for this scheme
  output.metrics["dense_vs_recursive"] = value_sample(worst_residual);
  return output;
}

}  // namespace

void add_clothoid_energy_decay(Registry& registry) {
  const std::vector<double> levels{2e-3, 1e-3, 5e-4};
  // Measured 2026-11-28 (dt / tau = 4e-3 .. 5e-4, tau = 1.2003 at the defaults): energy_loss 5.22e-3, 2.77e-3,
  // 1.44e-3, 7.42e-4 (pairwise orders 0.917, 0.939, 0.960: an O(h^2) part decays, as on the Super-Helix); every
  // step loses energy (max_energy_increase = 0); dense vs recursive: relative residual <= 3.2e-15. 0.4, 0.8,
  // 1.7 s CPU per level.
  constexpr double kEnergyLossAtFinest = 7.4193e-4;  // at dt / tau = 5e-4
  std::vector<GateSpec> gates{
      order_gate("energy_loss", 1.0, "semi-implicit Euler dissipates at first order in h (ALGORITHMS.md §1.5, §2)"),
      measured_bound("energy_loss", kEnergyLossAtFinest, levels.back(), 1.0),
      upper_bound_gate("dense_vs_recursive", 1e-12, GateScope::AllLevels,
                       "the O(N) recursion solves the same system as the dense LDL^T (relative residual, as the "
                       "Super-Helix's)")};
  // Monotone decay is what this release shows, not a property of the scheme (explicit velocity terms): held at
  // the defaults, as a measured bound.
  GateSpec monotone = upper_bound_gate("max_energy_increase", 1e-13, GateScope::AllLevels,
                                       "monotone decay at the default release: any increase is round-off of E");
  monotone.measured = true;
  gates.push_back(monotone);
  Case c = make_case(
      "superhelix",
      {"superhelix/clothoid-energy-decay",
       "undamped 3-D swing and twist of a super-clothoid: energy decay and dense vs O(N) step",
       "Super-clothoid cantilever (4 elements, length L, line density rho S, stiffnesses GJ != EI1 != EI2; defaults "
       "0.7, 0.3, (0.03, 0.05, 0.08); solid elliptic section with semi-axes L/7 and 0.6 L/7, natural strains (0.5, "
       "0, 1.2)/L, tilted clamp) released from its natural shape with nodal strain rates (1.25, 0.85, -0.6) / "
       "(L tau), tau = L^2 sqrt(rho S / EI1), under gravity g along a direction in none of its planes, no "
       "damping. Semi-implicit Euler, the recursive (linear-time) path; the level is dt / tau.",
       "E = T + U + V is conserved by the exact flow; the loss E(0) - E(t_end) is the error, O(h)",
       "ALGORITHMS.md §2 (the super-clothoid: the Super-Helix Lagrangian on nodal strains); Casati & Bertails "
       "2013", kMethod},
      energy_release_parameters(),
      {"dt/tau", "time step over tau = L^2 sqrt(rho S / EI1)", ResolutionScale::StepSize, levels,
       {4e-3, 2e-3, 1e-3, 5e-4, 2.5e-4}},
      {{"energy_loss", MetricKind::Error, "", "(E(0) - E(t_end)) / |E|", false, 1.0},
       {"max_energy_increase", MetricKind::Invariant, "", "max (E_{n+1} - E_n) / |E| (<= round-off: monotone)", false,
        std::nullopt},
       {"dense_vs_recursive", MetricKind::Error, "",
        "max over steps of |(M + D)(dv_dense - dv_recursive)| / |(M + D) dv_dense| (relative residual)", false,
        std::nullopt}},
      std::move(gates), run);
  // t_end / tau <= 0.584 (t_end = 0.7 at the defaults) and the swing t_end sqrt(g / L) <= 1.5 (measured 2026-11-27
  // with the default levels: t_end 0.5, 0.7 and (g, t_end) = (100, 0.12), (40, 0.19), (20, 0.28), (10, 0.4) pass,
  // orders 0.92 .. 1.19; t_end = 1 gives 0.900 and (100, 0.2), a swing of 2.4, 0.71: an O(h^2) part not yet
  // decayed over the longer swing).
  require_energy_release_windows(c, 1.5, 0.584);
  registry.add(std::move(c));
}

}  // namespace rodvv::harness::superhelix_cases
