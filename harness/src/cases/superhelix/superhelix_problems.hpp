#pragma once
// The Super-Helix cases kept one problem per file (this folder); the older ones live in
// ../superhelix_cases.cpp, which registers these too.
#include <cstddef>
#include <vector>

#include "rodvv/harness/case.hpp"
#include "rodvv/harness/registry.hpp"
#include "rodvv/solvers/superhelix/model.hpp"

namespace rodvv::harness::superhelix_cases {

// The method description every Super-Helix case carries.
extern const char* const kMethod;

// The release of superhelix/energy-decay and superhelix/clothoid-energy-decay: a twisted, curved cantilever
// (L = 0.7, rho S = 0.3, (GJ, EI1, EI2) = (0.03, 0.05, 0.08), natural strains (0.5, 0, 1.2)/L, a solid elliptic
// section of semi-axes 0.1 and 0.06 whose rotational inertia is scaled by J_scale), clamped in a tilted frame,
// under gravity g along a direction in none of its planes.
inline constexpr double kEnergyReleaseLength = 0.7;
solvers::superhelix::RodModel energy_release_model(std::size_t elements, double g, double J_scale);

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
