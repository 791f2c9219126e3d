#pragma once
// The Super-Helix cases kept one problem per file (this folder); the older ones live in
// ../superhelix_cases.cpp, which registers these too.
#include <cstddef>
#include <vector>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/harness/case.hpp"
#include "rodvv/harness/registry.hpp"
#include "rodvv/solvers/superhelix/model.hpp"

namespace rodvv::harness::superhelix_cases {

// The method description every Super-Helix case carries.
extern const char* const kMethod;

// The release of superhelix/energy-decay and superhelix/clothoid-energy-decay: a twisted, curved cantilever
// (L, rho S, (GJ, EI1, EI2) from the parameters, defaults 0.7, 0.3, (0.03, 0.05, 0.08); natural strains
// (0.5, 0, 1.2)/L; a solid elliptic section of semi-axes L/7 and 0.6 L/7 whose rotational inertia is scaled by
// J_scale), clamped in a tilted frame, under gravity g along a direction in none of its planes, started with
// the strain rates energy_release_rates in every element (node).
solvers::superhelix::RodModel energy_release_model(std::size_t elements, const Parameters& p, double J_scale);
// (1.25, 0.85, -0.6) / (L tau), tau = L^2 sqrt(rhoS / EI1): the same release in the units of any rod.
Vec3 energy_release_rates(const Parameters& p);
// The rod's parameters L, rhoS, GJ, EI1, EI2 (the release's defaults) and g, t_end (0.25).
Parameters energy_release_parameters();
// The windows the release was measured in: stiffness ratios, gravity g rhoS L^3 / EI1, the horizon t_end / tau
// and the swing t_end sqrt(g / L) (the last two per case).
void require_energy_release_windows(Case& c, double max_swing, double max_horizon);

// The energy bookkeeping of both energy cases: E after each step; energy_loss = (E(0) - E(t_end)) / |E|max,
// max_energy_increase (per step, same size) and the loss series E(0) - E(t).
class EnergyLedger {
 public:
  explicit EnergyLedger(double e0) : e0_(e0), energy_(e0), scale_(e0 < 0.0 ? -e0 : e0) {}
  void record(double time, double energy);
  void add_to(LevelOutput& output) const;

 private:
  double e0_, energy_, scale_, worst_increase_ = 0.0;
  std::vector<double> t_{0.0}, loss_{0.0};
};

void add_bathe_bolourchi(Registry& registry);    // 45-degree bend, out-of-plane tip load
void add_lateral_torsional(Registry& registry);  // lateral-torsional buckling of a cantilever
void add_spinning_clamp_oracle(Registry& registry);  // the step against an independent Lagrangian oracle
void add_clothoid_energy_decay(Registry& registry);  // the super-clothoid's dynamics: energy loss, dense = O(N)
void add_manufactured(Registry& registry);          // manufactured 3-D equilibrium with a distributed force
void add_touchdown(Registry& registry);             // lands on a floor and settles: velocity-level contact

}  // namespace rodvv::harness::superhelix_cases
