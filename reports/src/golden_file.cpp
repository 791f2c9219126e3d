#include "rodvv/reports/golden_file.hpp"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <string>

#include <nlohmann/json.hpp>

#include "rodvv/common/errors.hpp"

namespace rodvv::reports {

namespace {

using nlohmann::json;
constexpr const char* kParameter = "goldens";
constexpr const char* kFormat = "rodvv goldens";
constexpr int kVersion = 1;

json number(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return v;
}

class Reader {
 public:
  explicit Reader(std::string source) : source_(std::move(source)) {}
  [[noreturn]] void fail(const std::string& where, const std::string& what) const {
    throw InputError(kParameter, source_ + ": " + where + ": " + what);
  }
  double number(const json& j, const std::string& where) const {
    if (j.is_number()) return j.get<double>();
    if (j.is_string()) {
      const auto s = j.get<std::string>();
      if (s == "nan") return std::numeric_limits<double>::quiet_NaN();
      if (s == "inf") return std::numeric_limits<double>::infinity();
      if (s == "-inf") return -std::numeric_limits<double>::infinity();
    }
    fail(where, "expected a number (or \"nan\", \"inf\", \"-inf\")");
  }
  std::optional<double> optional_number(const json& j, const char* key, const std::string& where) const {
    const auto it = j.find(key);
    if (it == j.end()) return std::nullopt;
    return number(*it, where + "." + key);
  }

 private:
  std::string source_;
};

}  // namespace

harness::Goldens read_goldens(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(kParameter, path.string() + ": cannot open: " + std::strerror(errno));
  json doc;
  try {
    doc = json::parse(in);
  } catch (const json::exception& e) {
    throw InputError(kParameter, path.string() + ": not valid JSON: " + e.what());
  }
  const Reader r(path.string());
  // Types checked before reading: nlohmann's value() throws on a wrong type (an internal error).
  const auto format = doc.is_object() ? doc.find("format") : doc.end();
  if (!doc.is_object() || format == doc.end() || !format->is_string() || *format != kFormat)
    r.fail("top level", std::string("expected an object with \"format\": \"") + kFormat + "\"");
  const auto version = doc.find("version");
  if (version == doc.end() || !version->is_number_integer() || *version != kVersion)
    r.fail("version", "expected " + std::to_string(kVersion) + " (written by another rodvv: rodvv bless rewrites it)");
  const auto cases = doc.find("cases");
  if (cases == doc.end() || !cases->is_object()) r.fail("cases", "expected an object of cases");
  harness::Goldens goldens;
  for (const auto& [name, levels] : cases->items()) {
    const std::string where = "cases." + name;
    if (!levels.is_array()) r.fail(where, "expected an array of levels");
    harness::GoldenCase golden;
    for (std::size_t i = 0; i < levels.size(); ++i) {
      const json& l = levels[i];
      const std::string at = where + "[" + std::to_string(i) + "]";
      if (!l.is_object() || !l.contains("level") || !l.contains("metrics") || !l["metrics"].is_object())
        r.fail(at, "expected {\"level\", \"failed\", \"metrics\"}");
      harness::GoldenLevel level;
      level.level = r.number(l["level"], at + ".level");
      if (const auto failed = l.find("failed"); failed != l.end()) {
        if (!failed->is_boolean()) r.fail(at + ".failed", "expected true or false");
        level.failed = failed->get<bool>();
      }
      for (const auto& [metric, sample] : l["metrics"].items()) {
        const std::string m = at + ".metrics." + metric;
        if (!sample.is_object() || !sample.contains("computed")) r.fail(m, "expected {\"computed\", ...}");
        level.metrics[metric] = {r.number(sample["computed"], m + ".computed"), r.optional_number(sample, "reference", m),
                                 r.optional_number(sample, "error", m), r.optional_number(sample, "scale", m)};
      }
      golden.levels.push_back(std::move(level));
    }
    goldens[name] = std::move(golden);
  }
  return goldens;
}

void write_goldens(const std::filesystem::path& path, const harness::Goldens& goldens) {
  json cases = json::object();
  for (const auto& [name, golden] : goldens) {
    json levels = json::array();
    for (const auto& level : golden.levels) {
      json metrics = json::object();
      for (const auto& [metric, s] : level.metrics) {
        json sample = {{"computed", number(s.computed)}};
        if (s.reference) sample["reference"] = number(*s.reference);
        if (s.error) sample["error"] = number(*s.error);
        if (s.scale) sample["scale"] = number(*s.scale);
        metrics[metric] = std::move(sample);
      }
      levels.push_back({{"level", number(level.level)}, {"failed", level.failed}, {"metrics", std::move(metrics)}});
    }
    cases[name] = std::move(levels);
  }
  const json doc = {{"format", kFormat}, {"version", kVersion}, {"cases", std::move(cases)}};
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw InputError(kParameter, path.string() + ": cannot write: " + std::strerror(errno));
  out << doc.dump(1, ' ', false, json::error_handler_t::replace) << '\n';
  out.flush();
  if (!out) throw InputError(kParameter, path.string() + ": write failed");
}

}  // namespace rodvv::reports
