#pragma once
// What a planar solution file may leave out and rodvv can derive: the tangent angle from the
// positions, the curvature from the angle, both by second-order finite differences on the file's
// own (possibly non-uniform) arclength grid.
#include <vector>

namespace rodvv::solution_files {

// df/ds at every node: the three-point stencil of the quadratic through (s_{i-1}, s_i, s_{i+1})
// inside, the one-sided three-point stencil at the ends (both O(h^2)); the chord slope for two
// nodes. s strictly increasing, at least two nodes.
std::vector<double> derivative(const std::vector<double>& s, const std::vector<double>& f);

// theta = atan2(y', x'), unwrapped so that consecutive nodes differ by less than pi.
std::vector<double> tangent_angle(const std::vector<double>& s, const std::vector<double>& x,
                                  const std::vector<double>& y);

}  // namespace rodvv::solution_files
