#pragma once
// The per-node (or per-sample) arrays of a solution as named columns of equal length, from an
// inline JSON object of arrays or from a CSV file with a header row.
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "json_cursor.hpp"

namespace rodvv::solution_files {

struct ColumnTable {
  std::string where;  // for messages: "$.planar_rod.nodes" or "run_N40.csv"
  std::vector<std::pair<std::string, std::vector<double>>> columns;

  const std::vector<double>* find(std::string_view name) const;
  std::size_t rows() const { return columns.empty() ? 0 : columns.front().second.size(); }
};

// Every column's name must be in `known`; all columns must have one length. InputError otherwise,
// naming the JSON path or the CSV line and column.
ColumnTable columns_from_json(const JsonCursor& object, const std::vector<std::string>& known);
ColumnTable columns_from_csv(const std::filesystem::path& path, const std::string& display,
                             const std::vector<std::string>& known);

}  // namespace rodvv::solution_files
