#include "json_cursor.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "rodvv/common/errors.hpp"

namespace rodvv::solution_files {

void JsonCursor::fail(const std::string& what) const {
  throw InputError("solution", fmt::format("{}: {}: {}", *source_, path_, what));
}

std::string JsonCursor::type_name() const {
  if (value_->is_number()) return fmt::format("the number {}", value_->dump());
  if (value_->is_string()) {
    const auto text = value_->get<std::string>();
    return text.size() <= 40 ? fmt::format("the string \"{}\"", text) : "a string";
  }
  return value_->type_name();  // "null", "boolean", "array", "object"
}

void JsonCursor::expect_object(std::initializer_list<const char*> known) const {
  expect_fields(std::vector<std::string>(known.begin(), known.end()));
}

void JsonCursor::expect_fields(const std::vector<std::string>& known) const {
  if (!value_->is_object()) fail("expected an object, got " + type_name());
  for (const auto& [key, ignored] : value_->items()) {
    if (std::find(known.begin(), known.end(), key) != known.end()) continue;
    std::string names;
    for (const auto& name : known) names += (names.empty() ? "" : ", ") + name;
    fail(fmt::format("unknown field \"{}\" (allowed: {})", key, names));
  }
}

bool JsonCursor::has(const char* key) const { return value_->is_object() && value_->contains(key); }

JsonCursor JsonCursor::field(const char* key) const {
  if (!has(key)) fail(fmt::format("missing required field \"{}\"", key));
  return {value_->at(key), path_ + "." + key, *source_};
}

double JsonCursor::number() const {
  if (!value_->is_number()) fail("expected a finite number, got " + type_name());
  const double x = value_->get<double>();
  if (!std::isfinite(x)) fail("expected a finite number, got " + value_->dump());
  return x;
}

double JsonCursor::positive_number() const {
  const double x = number();
  if (!(x > 0.0)) fail(fmt::format("expected a number > 0, got {}", value_->dump()));
  return x;
}

std::size_t JsonCursor::count() const {
  const double x = number();
  if (x < 0.0 || x != std::floor(x) || x > 1e15) fail("expected a whole number >= 0, got " + value_->dump());
  return static_cast<std::size_t>(x);
}

std::string JsonCursor::string() const {
  if (!value_->is_string()) fail("expected a string, got " + type_name());
  return value_->get<std::string>();
}

std::vector<double> JsonCursor::numbers() const {
  if (!value_->is_array()) fail("expected an array of numbers, got " + type_name());
  std::vector<double> values;
  values.reserve(value_->size());
  for (std::size_t i = 0; i < value_->size(); ++i)
    values.push_back(JsonCursor(value_->at(i), fmt::format("{}[{}]", path_, i), *source_).number());
  return values;
}

}  // namespace rodvv::solution_files
