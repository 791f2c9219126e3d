#pragma once
// A JSON value with its path from the document root ("$.planar_rod.nodes.x[3]"), so that every
// complaint about a solution file says where in the file it is and what was expected.
#include <cstddef>
#include <initializer_list>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace rodvv::solution_files {

class JsonCursor {
 public:
  JsonCursor(const nlohmann::ordered_json& value, std::string path, const std::string& source)
      : value_(&value), path_(std::move(path)), source_(&source) {}

  const nlohmann::ordered_json& value() const { return *value_; }
  const std::string& path() const { return path_; }
  const std::string& source() const { return *source_; }

  // InputError "<source>: <path>: <what>".
  [[noreturn]] void fail(const std::string& what) const;

  // This value must be an object whose keys are all among `known`.
  void expect_object(std::initializer_list<const char*> known) const;
  void expect_fields(const std::vector<std::string>& known) const;
  bool has(const char* key) const;
  JsonCursor field(const char* key) const;  // required

  double number() const;                    // finite
  double positive_number() const;           // finite, > 0
  std::size_t count() const;                // a whole number >= 0
  std::string string() const;
  std::vector<double> numbers() const;      // an array of finite numbers

 private:
  std::string type_name() const;
  const nlohmann::ordered_json* value_;
  std::string path_;
  const std::string* source_;
};

}  // namespace rodvv::solution_files
