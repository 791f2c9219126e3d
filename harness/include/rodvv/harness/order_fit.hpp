#pragma once
// Observed order of convergence from errors e_i at mesh sizes h_i (coarse -> fine), assuming
// e ~ C h^p: pairwise orders between consecutive levels and the least-squares slope of log e
// against log h over the last `fit_levels` levels, with its coefficient of determination R^2
// (deal.II ConvergenceTable; Roache 1998, "Verification and Validation in Computational Science").
#include <cstddef>
#include <span>

#include "rodvv/harness/sweep_result.hpp"

namespace rodvv::harness {

// Levels whose error is missing, zero or non-finite cannot enter a logarithm: a pairwise order
// touching one is left out, and the least-squares fit is absent when any of the last fit_levels
// levels is such a level (the fit must not silently skip the finest data).
// Throws InputError when h and errors differ in length, fit_levels < 2, or an h is not positive.
OrderFit fit_order(std::span<const double> h, std::span<const std::optional<double>> errors,
                   std::size_t fit_levels = 3);

}  // namespace rodvv::harness
