// Super-Helix stability eigenvalue (solvers/superhelix/stability.hpp): its sign against Euler's
// column (a clamped-free column under a dead compressive end force buckles at pi^2 EI / (4 L^2)),
// and the inputs it refuses.
#include <gtest/gtest.h>

#include <numbers>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/solvers/superhelix/stability.hpp"
#include "rodvv/solvers/superhelix/statics.hpp"

namespace {

using rodvv::Vec3;
namespace sh = rodvv::solvers::superhelix;

sh::RodModel column(double load_fraction) {
  sh::RodModel model;
  model.elements = 16;
  model.length = 1.7;
  model.stiffness = Vec3(0.6, 1.1, 2.3);  // buckles about n1 (the weaker bending axis)
  const double euler = std::numbers::pi * std::numbers::pi * 1.1 / (4 * 1.7 * 1.7);
  model.end_force = -load_fraction * euler * model.root_frame.col(0);  // compression along the axis
  return model;
}

TEST(SuperHelixStability, SignChangesAtEulersLoad) {
  // The straight column is an equilibrium at any axial load; piecewise-constant strains give the
  // Euler load to O(h^2) (~1e-3 at N = 16), so +-5 % is unambiguous.
  for (double fraction : {0.0, 0.5, 0.95}) {
    const auto model = column(fraction);
    EXPECT_GT(sh::stability_eigenvalue(model, sh::natural_strain_vector(model)), 0.0) << fraction;
  }
  const auto beyond = column(1.05);
  EXPECT_LT(sh::stability_eigenvalue(beyond, sh::natural_strain_vector(beyond)), 0.0);
}

TEST(SuperHelixStability, RefusesWhatItCannotJudge) {
  auto model = column(0.5);
  const auto q = sh::natural_strain_vector(model);
  const auto parameter_of = [](const sh::RodModel& m, const rodvv::VecX& x) {
    try {
      sh::stability_eigenvalue(m, x);
    } catch (const rodvv::InputError& e) {
      return e.parameter();
    }
    return std::string("none");
  };
  EXPECT_EQ(parameter_of(model, q), "none");
  rodvv::VecX off = q;
  off[4] += 0.1;  // not an equilibrium
  EXPECT_EQ(parameter_of(model, off), "q");
  EXPECT_EQ(parameter_of(model, rodvv::VecX::Zero(5)), "q");
  // A dead end moment about a bending axis: not conservative, its load stiffness is unsymmetric.
  sh::RodModel moment = column(0.0);
  moment.end_moment = Vec3(0.3, 0.5, -0.2);
  const auto bent = sh::solve_static(moment).q;
  EXPECT_EQ(parameter_of(moment, bent), "end_moment");
}

}  // namespace
