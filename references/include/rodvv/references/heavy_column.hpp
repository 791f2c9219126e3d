#pragma once
// Greenhill's heavy column (Greenhill 1881, Proc. Cambridge Phil. Soc. 4:65, "Determination of the
// greatest height consistent with stability that a vertical pole or mast can be made"; Timoshenko &
// Gere, Theory of Elastic Stability, 1961, §2.10): a uniform column clamped upright at its foot and
// free at its top buckles under its own weight w = rho S g per unit length when
//
//   w L^3 / EI = 7.83734744...  = (9/4) j^2,  j the first positive zero of J_{-1/3}
//
// (EI the smaller bending stiffness; the straight column is stable below, unstable above).
// Computed here from the power series of the linearised slope theta (s from the free top):
//   EI theta'' + w s theta = 0, theta'(0) = 0 (no moment at the top), theta(L) = 0 (clamped foot);
//   theta = sum_n a_n s^{3n}, a_n = -c a_{n-1} / (3n (3n - 1)), c = w / EI, so that
//   f(x) = sum_n prod_{m<=n} (-x / (3m (3m - 1))) = 0 at x = w L^3 / EI,
// its first root by TOMS 748 (bracketed_root.hpp) on [7, 8.5]. tests/data/make_heavy_column_table.py
// computes it from mpmath's besselj zero and from an odefun shooting.
// InputError for EI or w not finite and > 0.
namespace rodvv::references {

// (w L^3 / EI) at the onset.
double heavy_column_critical_weight();

struct HeavyColumn {
  double EI = 1.0;  // smaller bending stiffness, > 0
  double w = 1.0;   // weight per unit length rho S |g|, > 0
};
// The tallest stable column: L_cr = (7.837 EI / w)^(1/3).
double heavy_column_critical_length(const HeavyColumn& column);

}  // namespace rodvv::references
