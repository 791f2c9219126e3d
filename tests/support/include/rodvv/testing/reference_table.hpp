#pragma once
// Reader for the high-precision reference tables in tests/data (CSV written by the mpmath scripts):
// '#' lines are comments, the first other line is the header, every row has the same number of
// comma-separated fields (an empty field is allowed and reads as NaN through parse_table_number).
// Problems are reported as GoogleTest failures naming the file and the line, so a damaged table
// turns the suite red instead of silently shrinking it.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

namespace rodvv::testing {

// An empty field is NaN; anything not a complete number is a test failure.
inline double parse_table_number(const std::string& field) {
  if (field.empty()) return std::numeric_limits<double>::quiet_NaN();
  char* end = nullptr;
  const double value = std::strtod(field.c_str(), &end);  // correctly rounded to nearest
  EXPECT_EQ(*end, '\0') << "bad number '" << field << "'";
  return value;
}

// The data rows of tests/data/<file_name>, split into fields; rows with the wrong field count are
// reported and skipped.
inline std::vector<std::vector<std::string>> read_reference_table(const std::string& file_name,
                                                                  const std::string& header) {
  const std::string path = std::string(RODVV_TEST_DATA_DIR) + "/" + file_name;
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << "cannot open " << path;
  std::size_t columns = 1;
  for (char ch : header) columns += ch == ',' ? 1 : 0;
  std::vector<std::vector<std::string>> rows;
  std::string line;
  bool header_seen = false;
  while (std::getline(in, line)) {
    if (line.empty() || line.front() == '#') continue;
    if (!header_seen) {
      EXPECT_EQ(line, header) << path;
      header_seen = true;
      continue;
    }
    std::vector<std::string> fields(1);
    for (char ch : line) {
      if (ch == ',') fields.emplace_back();
      else fields.back() += ch;
    }
    EXPECT_EQ(fields.size(), columns) << path << ": malformed line: " << line;
    if (fields.size() == columns) rows.push_back(std::move(fields));
  }
  return rows;
}

}  // namespace rodvv::testing
