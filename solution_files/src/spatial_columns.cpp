#include "spatial_columns.hpp"

#include <fmt/format.h>

namespace rodvv::solution_files {

std::array<std::string, 3> vector_columns(const std::string& field, const std::array<const char*, 3>& axes) {
  return {fmt::format("{}_{}", field, axes[0]), fmt::format("{}_{}", field, axes[1]),
          fmt::format("{}_{}", field, axes[2])};
}

std::array<std::string, 9> frame_columns() {
  std::array<std::string, 9> names;
  for (std::size_t d = 0; d < 3; ++d)
    for (std::size_t a = 0; a < 3; ++a) names[3 * d + a] = fmt::format("{}_{}", kDirectors[d], kWorldAxes[a]);
  return names;
}

}  // namespace rodvv::solution_files
