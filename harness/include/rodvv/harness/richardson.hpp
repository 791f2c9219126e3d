#pragma once
// Richardson extrapolation and the Grid Convergence Index (GCI) from three levels of a smooth
// solution functional f (not an error), following Celik et al. 2008 (J. Fluids Eng. 130:078001,
// "Procedure for estimation and reporting of uncertainty due to discretization in CFD
// applications"), which generalises Roache 1994 (J. Fluids Eng. 116:405) to non-constant ratios:
//   r21 = h2/h1, r32 = h3/h2, e21 = f2 - f1, e32 = f3 - f2, s = sign(e32/e21)
//   p solves e32/e21 = r21^p (r32^p - 1)/(r21^p - 1)   (Celik's eqs. 3-5 for s = 1, solved by
//   bracketing rather than fixed-point iteration, which can stall for unequal ratios)
//   f_ext = (r21^p f1 - f2) / (r21^p - 1)
//   GCI_fine = Fs |(f1 - f2)/f1| / (r21^p - 1),  GCI_coarse = Fs |(f2 - f3)/f2| / (r32^p - 1),
//   Fs = 1.25 (three-level study); asymptotic range when GCI_coarse / (r21^p GCI_fine) ~ 1.
// Index 1 is the finest level.
#include <optional>
#include <string>

#include "rodvv/harness/sweep_result.hpp"

namespace rodvv::harness {

inline constexpr double kGciSafetyFactor = 1.25;

struct RichardsonInput {
  double h1, h2, h3;  // fine, medium, coarse mesh sizes: h1 < h2 < h3
  double f1, f2, f3;  // the functional at those levels
};

// Empty (with *why_not set) when the differences vanish, convergence oscillates (s < 0), the
// order is not in [0.001, 30], or an input is not finite. Throws InputError when the mesh sizes
// are not strictly increasing and positive.
std::optional<RichardsonResult> richardson_gci(const RichardsonInput& input, std::string* why_not);

}  // namespace rodvv::harness
