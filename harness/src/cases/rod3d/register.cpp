// rod3d/*: the nodal 3-D rod. One file per problem in this folder; this one lists them.
#include "rod3d_cases.hpp"

namespace rodvv::harness {

namespace rod3d_cases {
const char* const kMethod =
    "discrete elastic rod (Bergou et al. 2008, 2010): vertices and one material angle per edge, "
    "parallel-transported reference frames, inextensible edges by Lagrange multipliers; statics by "
    "Newton with exact derivatives (forward-mode jets), banded LU, continuation; second order in h = L/N";
}  // namespace rod3d_cases

void register_rod3d_cases(Registry& registry) {
  rod3d_cases::add_helix_axial_wrench(registry);
  rod3d_cases::add_mattiasson(registry);
  rod3d_cases::add_heavy_cantilever(registry);
  rod3d_cases::add_roll_up(registry);
  rod3d_cases::add_modes(registry);
  rod3d_cases::add_energy_in_time(registry);
  rod3d_cases::add_skew_vibration(registry);
  rod3d_cases::add_helical_buckling(registry);
  rod3d_cases::add_bathe_bolourchi(registry);
  rod3d_cases::add_lateral_torsional(registry);
  rod3d_cases::add_greenhill(registry);
  rod3d_cases::add_michell_ring(registry);
  rod3d_cases::add_manufactured(registry);
}

}  // namespace rodvv::harness
