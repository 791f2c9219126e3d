#include "column_table.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "rodvv/common/errors.hpp"

namespace rodvv::solution_files {

namespace {

std::string allowed(const std::vector<std::string>& known) {
  std::string names;
  for (const auto& name : known) names += (names.empty() ? "" : ", ") + name;
  return names;
}

bool is_known(std::string_view name, const std::vector<std::string>& known) {
  for (const auto& k : known)
    if (name == k) return true;
  return false;
}

std::string_view trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  while (true) {
    const auto comma = line.find(',', start);
    fields.push_back(trim(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

void check_lengths(const ColumnTable& table) {
  for (const auto& [name, values] : table.columns)
    if (values.size() != table.rows())
      throw InputError("solution", fmt::format("{}: column \"{}\" has {} values but \"{}\" has {}: every array must "
                                               "have one value per node",
                                               table.where, name, values.size(), table.columns.front().first,
                                               table.rows()));
}

}  // namespace

const std::vector<double>* ColumnTable::find(std::string_view name) const {
  for (const auto& [column, values] : columns)
    if (column == name) return &values;
  return nullptr;
}

ColumnTable columns_from_json(const JsonCursor& object, const std::vector<std::string>& known) {
  object.expect_fields(known);
  ColumnTable table;
  table.where = object.source() + ": " + object.path();
  for (const auto& [key, value] : object.value().items())
    table.columns.emplace_back(key, object.field(key.c_str()).numbers());
  check_lengths(table);
  return table;
}

ColumnTable columns_from_csv(const std::filesystem::path& path, const std::string& display,
                             const std::vector<std::string>& known) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("solution", fmt::format("{}: cannot open the CSV file '{}'", display, path.string()));
  ColumnTable table;
  table.where = path.filename().string();
  const auto fail = [&](std::size_t line, const std::string& what) {
    throw InputError("solution", fmt::format("{}:{}: {}", path.string(), line, what));
  };
  std::string line;
  std::size_t line_number = 0;
  bool have_header = false;
  while (std::getline(in, line)) {
    ++line_number;
    const std::string_view text = trim(line);
    if (text.empty() || text.front() == '#') continue;  // blank lines and comments
    const auto fields = split(text);
    if (!have_header) {
      for (const auto field : fields) {
        if (!is_known(field, known))
          fail(line_number, fmt::format("unknown column \"{}\" in the header (allowed: {})", field, allowed(known)));
        for (const auto& [name, ignored] : table.columns)
          if (name == field) fail(line_number, fmt::format("column \"{}\" appears twice in the header", field));
        table.columns.emplace_back(std::string(field), std::vector<double>{});
      }
      have_header = true;
      continue;
    }
    if (fields.size() != table.columns.size())
      fail(line_number, fmt::format("{} fields, but the header names {} columns", fields.size(), table.columns.size()));
    for (std::size_t j = 0; j < fields.size(); ++j) {
      double value = 0.0;
      auto field = fields[j];
      if (field.starts_with('+')) field.remove_prefix(1);  // from_chars takes no explicit plus sign
      const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
      if (error != std::errc() || end != field.data() + field.size() || !std::isfinite(value))
        fail(line_number, fmt::format("column \"{}\": expected a finite number, got \"{}\"", table.columns[j].first,
                                      std::string(field.substr(0, 40))));
      table.columns[j].second.push_back(value);
    }
  }
  if (!have_header) fail(line_number, "no header row (a first line naming the columns, comma separated)");
  return table;
}

}  // namespace rodvv::solution_files
