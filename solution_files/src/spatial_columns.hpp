#pragma once
// The 3-D rod's vector and frame fields as scalar columns, one naming for inline JSON and CSV:
// a vector field f is f_x, f_y, f_z (world components) or f_0, f_1, f_2 (material components, index 0
// the tangent); a frame R = [n0 n1 n2] is the nine columns n0_x .. n2_z (its directors in world
// components).
#include <array>
#include <string>
#include <vector>

#include "rodvv/common/eigen_types.hpp"

namespace rodvv::solution_files {

inline constexpr std::array<const char*, 3> kWorldAxes = {"x", "y", "z"};
inline constexpr std::array<const char*, 3> kMaterialAxes = {"0", "1", "2"};
inline constexpr std::array<const char*, 3> kDirectors = {"n0", "n1", "n2"};

// "position" + world -> position_x, position_y, position_z.
std::array<std::string, 3> vector_columns(const std::string& field, const std::array<const char*, 3>& axes);
std::array<std::string, 9> frame_columns();

}  // namespace rodvv::solution_files
