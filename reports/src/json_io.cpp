#include "rodvv/reports/json_io.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <system_error>

#include "rodvv/common/errors.hpp"

namespace rodvv::reports {

using nlohmann::json;

namespace {

constexpr const char* kParameter = "results file";

// ---------------------------------------------------------------------------------------------
// Writing

json number(double value) { return std::isfinite(value) ? json(value) : json(nullptr); }

json number(const std::optional<double>& value) {
  return value ? number(*value) : json(nullptr);
}

json string_or_null(const std::optional<std::string>& value) {
  return value ? json(*value) : json(nullptr);
}

json numbers(const std::vector<double>& values) {
  json out = json::array();
  for (const double v : values) out.push_back(number(v));
  return out;
}

json to_json(const Provenance& p) {
  return json{{"rodvv_version", p.rodvv_version},   {"git_commit", p.git_commit},
              {"compiler_id", p.compiler_id},       {"compiler_version", p.compiler_version},
              {"build_type", p.build_type},         {"compile_flags", p.compile_flags},
              {"cpu_model", p.cpu_model},           {"host_cores", p.host_cores},
              {"date_utc", p.date_utc}};
}

json to_json(const harness::Parameter& p) {
  return json{{"name", p.name},         {"value", number(p.value)},  {"min", number(p.min)},
              {"max", number(p.max)},   {"min_open", p.min_open},     {"max_open", p.max_open},
              {"unit", p.unit},         {"description", p.description}};
}

json to_json(const harness::Resolution& r) {
  return json{{"name", r.name},
              {"description", r.description},
              {"scale", harness::to_string(r.scale)},
              {"default_levels", numbers(r.default_levels)},
              {"extended_levels", numbers(r.extended_levels)}};
}

json to_json(const harness::MetricSpec& m) {
  return json{{"name", m.name},
              {"kind", harness::to_string(m.kind)},
              {"unit", m.unit},
              {"description", m.description},
              {"extrapolate", m.extrapolate},
              {"theoretical_order", number(m.theoretical_order)}};
}

json to_json(const harness::CaseInfo& info) {
  json parameters = json::array();
  for (const auto& p : info.parameters) parameters.push_back(to_json(p));
  json metrics = json::array();
  for (const auto& m : info.metrics) metrics.push_back(to_json(m));
  return json{{"name", info.name},           {"family", info.family},
              {"group", info.group},         {"title", info.title},
              {"physics", info.physics},     {"reference", info.reference},
              {"citation", info.citation},   {"method", info.method},
              {"parameters", parameters},    {"resolution", to_json(info.resolution)},
              {"metrics", metrics}};
}

json to_json(const harness::LevelResult& level) {
  json metrics = json::object();
  for (const auto& [name, sample] : level.metrics)
    metrics[name] = json{{"computed", number(sample.computed)},
                         {"reference", number(sample.reference)},
                         {"error", number(sample.error)},
                         {"scale", number(sample.scale)}};
  json series = json::array();
  for (const auto& s : level.series)
    series.push_back(json{{"name", s.name},
                          {"x_label", s.x_label},
                          {"y_label", s.y_label},
                          {"x", numbers(s.x)},
                          {"y", numbers(s.y)}});
  return json{{"level", number(level.level)},
              {"h", number(level.h)},
              {"wall_seconds", number(level.wall_seconds)},
              {"cpu_seconds", number(level.cpu_seconds)},
              {"metrics", metrics},
              {"series", series},
              {"failure", string_or_null(level.failure)}};
}

json to_json(const harness::MetricAnalysis& a) {
  json richardson = nullptr;
  if (a.richardson) {
    const auto& r = *a.richardson;
    richardson = json{{"refinement_ratio", number(r.refinement_ratio)},
                      {"observed_order", number(r.observed_order)},
                      {"extrapolated", number(r.extrapolated)},
                      {"gci_fine", number(r.gci_fine)},
                      {"gci_coarse", number(r.gci_coarse)},
                      {"asymptotic_ratio", number(r.asymptotic_ratio)}};
  }
  return json{{"metric", a.metric},
              {"order", json{{"pairwise", numbers(a.order.pairwise)},
                             {"least_squares", number(a.order.least_squares)},
                             {"r_squared", number(a.order.r_squared)},
                             {"levels_used", a.order.levels_used}}},
              {"richardson", richardson},
              {"richardson_note", string_or_null(a.richardson_note)}};
}

json to_json(const harness::GateResult& g) {
  return json{{"name", g.name},
              {"kind", harness::to_string(g.kind)},
              {"metric", g.metric},
              {"passed", g.passed},
              {"measured", number(g.measured)},
              {"lower", number(g.lower)},
              {"upper", number(g.upper)},
              {"reason", g.reason},
              {"rationale", g.rationale}};
}

// ---------------------------------------------------------------------------------------------
// Reading: every accessor knows the path of the value it reads, so an error names the field.

const char* type_phrase(const json& value) {
  switch (value.type()) {
    case json::value_t::null: return "null";
    case json::value_t::object: return "an object";
    case json::value_t::array: return "an array";
    case json::value_t::string: return "a string";
    case json::value_t::boolean: return "a boolean";
    case json::value_t::number_integer:
    case json::value_t::number_unsigned: return "an integer";
    case json::value_t::number_float: return "a number";
    case json::value_t::binary: return "binary data";
    case json::value_t::discarded: return "nothing";
  }
  return "an unknown value";
}

class Reader {
 public:
  explicit Reader(std::string_view source) : source_(source) {}

  [[noreturn]] void fail(const std::string& path, const std::string& problem) const {
    throw InputError(kParameter, std::string(source_) + ": field '" + path + "': " + problem);
  }

  [[noreturn]] void wrong_type(const std::string& path, const char* expected,
                               const json& got) const {
    fail(path, std::string("expected ") + expected + ", got " + type_phrase(got));
  }

  static std::string child(const std::string& path, std::string_view key) {
    return path.empty() ? std::string(key) : path + "." + std::string(key);
  }
  static std::string index(const std::string& path, std::size_t i) {
    return path + "[" + std::to_string(i) + "]";
  }

  // The member `key` of the object at `path`; missing -> error.
  const json& member(const json& object, const std::string& path, std::string_view key,
                     const char* expected) const {
    const auto it = object.find(std::string(key));
    if (it == object.end()) fail(child(path, key), std::string("missing: expected ") + expected);
    return *it;
  }

  const json& object(const json& parent, const std::string& path, std::string_view key) const {
    const json& v = member(parent, path, key, "an object");
    if (!v.is_object()) wrong_type(child(path, key), "an object", v);
    return v;
  }

  const json& array(const json& parent, const std::string& path, std::string_view key) const {
    const json& v = member(parent, path, key, "an array");
    if (!v.is_array()) wrong_type(child(path, key), "an array", v);
    return v;
  }

  void require_object(const json& v, const std::string& path) const {
    if (!v.is_object()) wrong_type(path, "an object", v);
  }

  std::string string(const json& parent, const std::string& path, std::string_view key) const {
    const json& v = member(parent, path, key, "a string");
    if (!v.is_string()) wrong_type(child(path, key), "a string", v);
    return v.get<std::string>();
  }

  std::optional<std::string> optional_string(const json& parent, const std::string& path,
                                             std::string_view key) const {
    const json& v = member(parent, path, key, "a string or null");
    if (v.is_null()) return std::nullopt;
    if (!v.is_string()) wrong_type(child(path, key), "a string or null", v);
    return v.get<std::string>();
  }

  bool boolean(const json& parent, const std::string& path, std::string_view key) const {
    const json& v = member(parent, path, key, "a boolean");
    if (!v.is_boolean()) wrong_type(child(path, key), "a boolean", v);
    return v.get<bool>();
  }

  // A number; null (how non-finite values are written) reads as `if_null`.
  double value_number(const json& v, const std::string& path,
                      double if_null = std::numeric_limits<double>::quiet_NaN()) const {
    if (v.is_null()) return if_null;
    if (!v.is_number()) wrong_type(path, "a number or null", v);
    return v.get<double>();
  }

  double number(const json& parent, const std::string& path, std::string_view key,
                double if_null = std::numeric_limits<double>::quiet_NaN()) const {
    return value_number(member(parent, path, key, "a number or null"), child(path, key), if_null);
  }

  std::optional<double> optional_number(const json& parent, const std::string& path,
                                        std::string_view key) const {
    const json& v = member(parent, path, key, "a number or null");
    if (v.is_null()) return std::nullopt;
    if (!v.is_number()) wrong_type(child(path, key), "a number or null", v);
    return v.get<double>();
  }

  std::vector<double> numbers(const json& parent, const std::string& path,
                              std::string_view key) const {
    const json& v = array(parent, path, key);
    std::vector<double> out;
    out.reserve(v.size());
    const std::string p = child(path, key);
    for (std::size_t i = 0; i < v.size(); ++i) out.push_back(value_number(v[i], index(p, i)));
    return out;
  }

  std::uint64_t count(const json& parent, const std::string& path, std::string_view key) const {
    const json& v = member(parent, path, key, "a non-negative integer");
    if (v.is_number_unsigned()) return v.get<std::uint64_t>();
    if (v.is_number_integer() && v.get<std::int64_t>() >= 0)
      return static_cast<std::uint64_t>(v.get<std::int64_t>());
    wrong_type(child(path, key), "a non-negative integer", v);
  }

  // An enumeration written with harness::to_string; parsed back by trying every enumerator.
  template <typename Enum, std::size_t N>
  Enum enumeration(const json& parent, const std::string& path, std::string_view key,
                   const Enum (&values)[N]) const {
    const std::string text = string(parent, path, key);
    std::string allowed;
    for (const Enum e : values) {
      if (text == harness::to_string(e)) return e;
      allowed += (allowed.empty() ? "'" : ", '") + std::string(harness::to_string(e)) + "'";
    }
    fail(child(path, key), "unknown value '" + text + "': expected one of " + allowed);
  }

 private:
  std::string_view source_;
};

constexpr harness::MetricKind kMetricKinds[] = {
    harness::MetricKind::Error, harness::MetricKind::Invariant, harness::MetricKind::Diagnostic};
constexpr harness::GateKind kGateKinds[] = {
    harness::GateKind::Order, harness::GateKind::UpperBound, harness::GateKind::LowerBound,
    harness::GateKind::Regression};
constexpr harness::ResolutionScale kScales[] = {harness::ResolutionScale::StepSize,
                                                harness::ResolutionScale::Count,
                                                harness::ResolutionScale::Parameter};

Provenance read_provenance(const Reader& r, const json& j, const std::string& path) {
  Provenance p;
  p.rodvv_version = r.string(j, path, "rodvv_version");
  p.git_commit = r.string(j, path, "git_commit");
  p.compiler_id = r.string(j, path, "compiler_id");
  p.compiler_version = r.string(j, path, "compiler_version");
  p.build_type = r.string(j, path, "build_type");
  p.compile_flags = r.string(j, path, "compile_flags");
  p.cpu_model = r.string(j, path, "cpu_model");
  const std::uint64_t cores = r.count(j, path, "host_cores");
  if (cores > std::numeric_limits<unsigned>::max())
    r.fail(Reader::child(path, "host_cores"), "value out of range");
  p.host_cores = static_cast<unsigned>(cores);
  p.date_utc = r.string(j, path, "date_utc");
  return p;
}

harness::Parameter read_parameter(const Reader& r, const json& j, const std::string& path) {
  r.require_object(j, path);
  harness::Parameter p;
  p.name = r.string(j, path, "name");
  p.value = r.number(j, path, "value");
  // A null bound is an unbounded side (an infinite bound is written as null).
  p.min = r.number(j, path, "min", -std::numeric_limits<double>::infinity());
  p.max = r.number(j, path, "max", std::numeric_limits<double>::infinity());
  p.min_open = r.boolean(j, path, "min_open");
  p.max_open = r.boolean(j, path, "max_open");
  p.unit = r.string(j, path, "unit");
  p.description = r.string(j, path, "description");
  return p;
}

harness::Resolution read_resolution(const Reader& r, const json& j, const std::string& path) {
  harness::Resolution res;
  res.name = r.string(j, path, "name");
  res.description = r.string(j, path, "description");
  res.scale = r.enumeration(j, path, "scale", kScales);
  res.default_levels = r.numbers(j, path, "default_levels");
  res.extended_levels = r.numbers(j, path, "extended_levels");
  return res;
}

harness::MetricSpec read_metric_spec(const Reader& r, const json& j, const std::string& path) {
  r.require_object(j, path);
  harness::MetricSpec m;
  m.name = r.string(j, path, "name");
  m.kind = r.enumeration(j, path, "kind", kMetricKinds);
  m.unit = r.string(j, path, "unit");
  m.description = r.string(j, path, "description");
  m.extrapolate = r.boolean(j, path, "extrapolate");
  m.theoretical_order = r.optional_number(j, path, "theoretical_order");
  return m;
}

harness::CaseInfo read_case_info(const Reader& r, const json& j, const std::string& path) {
  harness::CaseInfo info;
  info.name = r.string(j, path, "name");
  info.family = r.string(j, path, "family");
  info.group = r.string(j, path, "group");
  info.title = r.string(j, path, "title");
  info.physics = r.string(j, path, "physics");
  info.reference = r.string(j, path, "reference");
  info.citation = r.string(j, path, "citation");
  info.method = r.string(j, path, "method");
  const json& parameters = r.array(j, path, "parameters");
  for (std::size_t i = 0; i < parameters.size(); ++i)
    info.parameters.push_back(
        read_parameter(r, parameters[i], Reader::index(Reader::child(path, "parameters"), i)));
  info.resolution =
      read_resolution(r, r.object(j, path, "resolution"), Reader::child(path, "resolution"));
  const json& metrics = r.array(j, path, "metrics");
  for (std::size_t i = 0; i < metrics.size(); ++i)
    info.metrics.push_back(
        read_metric_spec(r, metrics[i], Reader::index(Reader::child(path, "metrics"), i)));
  return info;
}

harness::Series read_series(const Reader& r, const json& j, const std::string& path) {
  r.require_object(j, path);
  harness::Series s;
  s.name = r.string(j, path, "name");
  s.x_label = r.string(j, path, "x_label");
  s.y_label = r.string(j, path, "y_label");
  s.x = r.numbers(j, path, "x");
  s.y = r.numbers(j, path, "y");
  if (s.x.size() != s.y.size())
    r.fail(Reader::child(path, "y"), "has " + std::to_string(s.y.size()) + " values but 'x' has " +
                                         std::to_string(s.x.size()));
  return s;
}

harness::LevelResult read_level(const Reader& r, const json& j, const std::string& path) {
  r.require_object(j, path);
  harness::LevelResult level;
  level.level = r.number(j, path, "level");
  level.h = r.number(j, path, "h");
  level.wall_seconds = r.number(j, path, "wall_seconds");
  // Absent from files written before it was recorded: 0, "not measured" (the plots then use wall time).
  level.cpu_seconds = j.contains("cpu_seconds") ? r.number(j, path, "cpu_seconds") : 0.0;
  const json& metrics = r.object(j, path, "metrics");
  const std::string metrics_path = Reader::child(path, "metrics");
  for (const auto& [name, value] : metrics.items()) {
    const std::string p = metrics_path + "['" + name + "']";
    r.require_object(value, p);
    harness::MetricSample sample;
    sample.computed = r.number(value, p, "computed");
    sample.reference = r.optional_number(value, p, "reference");
    sample.error = r.optional_number(value, p, "error");
    // Absent from files written before sizes were recorded.
    if (value.contains("scale")) sample.scale = r.optional_number(value, p, "scale");
    level.metrics.emplace(name, sample);
  }
  const json& series = r.array(j, path, "series");
  for (std::size_t i = 0; i < series.size(); ++i)
    level.series.push_back(
        read_series(r, series[i], Reader::index(Reader::child(path, "series"), i)));
  level.failure = r.optional_string(j, path, "failure");
  return level;
}

harness::MetricAnalysis read_analysis(const Reader& r, const json& j, const std::string& path) {
  r.require_object(j, path);
  harness::MetricAnalysis a;
  a.metric = r.string(j, path, "metric");
  const std::string order_path = Reader::child(path, "order");
  const json& order = r.object(j, path, "order");
  a.order.pairwise = r.numbers(order, order_path, "pairwise");
  a.order.least_squares = r.optional_number(order, order_path, "least_squares");
  a.order.r_squared = r.optional_number(order, order_path, "r_squared");
  a.order.levels_used = static_cast<std::size_t>(r.count(order, order_path, "levels_used"));
  const json& richardson = r.member(j, path, "richardson", "an object or null");
  if (!richardson.is_null()) {
    const std::string p = Reader::child(path, "richardson");
    if (!richardson.is_object()) r.wrong_type(p, "an object or null", richardson);
    harness::RichardsonResult rr;
    rr.refinement_ratio = r.number(richardson, p, "refinement_ratio");
    rr.observed_order = r.number(richardson, p, "observed_order");
    rr.extrapolated = r.number(richardson, p, "extrapolated");
    rr.gci_fine = r.number(richardson, p, "gci_fine");
    rr.gci_coarse = r.number(richardson, p, "gci_coarse");
    rr.asymptotic_ratio = r.number(richardson, p, "asymptotic_ratio");
    a.richardson = rr;
  }
  a.richardson_note = r.optional_string(j, path, "richardson_note");
  return a;
}

harness::GateResult read_gate(const Reader& r, const json& j, const std::string& path) {
  r.require_object(j, path);
  harness::GateResult g;
  g.name = r.string(j, path, "name");
  g.kind = r.enumeration(j, path, "kind", kGateKinds);
  g.metric = r.string(j, path, "metric");
  g.passed = r.boolean(j, path, "passed");
  g.measured = r.optional_number(j, path, "measured");
  g.lower = r.optional_number(j, path, "lower");
  g.upper = r.optional_number(j, path, "upper");
  g.reason = r.string(j, path, "reason");
  g.rationale = r.string(j, path, "rationale");
  return g;
}

harness::SweepResult read_case(const Reader& r, const json& j, const std::string& path) {
  r.require_object(j, path);
  harness::SweepResult result;
  result.info = read_case_info(r, r.object(j, path, "info"), Reader::child(path, "info"));
  const json& levels = r.array(j, path, "levels");
  for (std::size_t i = 0; i < levels.size(); ++i)
    result.levels.push_back(read_level(r, levels[i], Reader::index(Reader::child(path, "levels"), i)));
  const json& analyses = r.array(j, path, "analyses");
  for (std::size_t i = 0; i < analyses.size(); ++i)
    result.analyses.push_back(
        read_analysis(r, analyses[i], Reader::index(Reader::child(path, "analyses"), i)));
  const json& gates = r.array(j, path, "gates");
  for (std::size_t i = 0; i < gates.size(); ++i)
    result.gates.push_back(read_gate(r, gates[i], Reader::index(Reader::child(path, "gates"), i)));
  // Optional: added to the data model after the first files were written.
  if (const auto it = j.find("skipped_gates"); it != j.end()) {
    const std::string p = Reader::child(path, "skipped_gates");
    if (!it->is_array()) r.wrong_type(p, "an array of strings", *it);
    for (std::size_t i = 0; i < it->size(); ++i) {
      const json& v = (*it)[i];
      if (!v.is_string()) r.wrong_type(Reader::index(p, i), "a string", v);
      result.skipped_gates.push_back(v.get<std::string>());
    }
  }
  result.wall_seconds = r.number(j, path, "wall_seconds");
  // "passed" is derived (SweepResult::passed); it is written for jq and dashboards, not read.
  return result;
}

std::string label_of(const ValidationReport& report, std::size_t index) {
  return report.source.empty() ? "input #" + std::to_string(index + 1) : report.source;
}

}  // namespace

// ---------------------------------------------------------------------------------------------

json to_json(const harness::SweepResult& result) {
  json levels = json::array();
  for (const auto& level : result.levels) levels.push_back(to_json(level));
  json analyses = json::array();
  for (const auto& a : result.analyses) analyses.push_back(to_json(a));
  json gates = json::array();
  for (const auto& g : result.gates) gates.push_back(to_json(g));
  return json{{"info", to_json(result.info)},
              {"passed", result.passed()},
              {"wall_seconds", number(result.wall_seconds)},
              {"levels", levels},
              {"analyses", analyses},
              {"gates", gates},
              {"skipped_gates", result.skipped_gates}};
}

json to_json(const ValidationReport& report) {
  json cases = json::array();
  for (const auto& c : report.cases) cases.push_back(to_json(c));
  return json{{"schema_version", report.schema_version},
              {"passed", report.passed()},
              {"provenance", to_json(report.provenance)},
              {"merged_from", report.merged_from},
              {"cases", cases}};
}

ValidationReport report_from_json(const json& document, std::string_view source_name) {
  const Reader r(source_name);
  if (!document.is_object())
    throw InputError(kParameter, std::string(source_name) + ": expected a JSON object at the top "
                                     "level, got " + type_phrase(document));
  ValidationReport report;
  report.source = std::string(source_name);
  const json& version = r.member(document, "", "schema_version", "an integer");
  if (!version.is_number_integer()) r.wrong_type("schema_version", "an integer", version);
  if (version.get<std::int64_t>() != kSchemaVersion)
    r.fail("schema_version", "unsupported version " + version.dump() + ": this rodvv reads " +
                                 std::to_string(kSchemaVersion));
  report.schema_version = kSchemaVersion;
  report.provenance = read_provenance(r, r.object(document, "", "provenance"), "provenance");
  if (const auto it = document.find("merged_from"); it != document.end()) {
    if (!it->is_array()) r.wrong_type("merged_from", "an array of strings", *it);
    for (std::size_t i = 0; i < it->size(); ++i) {
      const json& v = (*it)[i];
      if (!v.is_string()) r.wrong_type(Reader::index("merged_from", i), "a string", v);
      report.merged_from.push_back(v.get<std::string>());
    }
  }
  const json& cases = r.array(document, "", "cases");
  for (std::size_t i = 0; i < cases.size(); ++i)
    report.cases.push_back(read_case(r, cases[i], Reader::index("cases", i)));
  return report;
}

ValidationReport report_from_json_text(std::string_view text, std::string_view source_name) {
  const std::string source(source_name);
  json document;
  try {
    document = json::parse(text);
  } catch (const json::parse_error& e) {
    throw InputError(kParameter, source + ": not valid JSON: " + e.what());
  } catch (const json::exception& e) {  // e.g. out_of_range 406: a number such as 1e400 overflows a double
    throw InputError(kParameter, source + ": not readable as results: " + e.what() +
                                     " (every number must be a finite double)");
  }
  return report_from_json(document, source_name);
}

ValidationReport read_report_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError(kParameter, path.string() + ": cannot open: " + std::strerror(errno));
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) throw InputError(kParameter, path.string() + ": read failed: " + std::strerror(errno));
  return report_from_json_text(text, path.string());
}

void write_report_file(const std::filesystem::path& path, const ValidationReport& report) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw InputError("output file", path.string() + ": cannot write: " + std::strerror(errno));
  // Shortest round-trip doubles (nlohmann's to_chars); replace invalid UTF-8 rather than throw
  // halfway through a file.
  out << to_json(report).dump(2, ' ', false, json::error_handler_t::replace) << '\n';
  out.flush();
  if (!out) throw InputError("output file", path.string() + ": write failed");
}

ValidationReport merge_reports(std::vector<ValidationReport> reports) {
  if (reports.empty()) throw InputError(kParameter, "no results to merge");
  ValidationReport merged;
  merged.provenance = reports.front().provenance;
  std::map<std::string, std::string> seen;  // case name -> label of the input holding it
  for (std::size_t i = 0; i < reports.size(); ++i) {
    auto& input = reports[i];
    const std::string label = label_of(input, i);
    if (input.merged_from.empty())
      merged.merged_from.push_back(label);
    else
      merged.merged_from.insert(merged.merged_from.end(), input.merged_from.begin(),
                                input.merged_from.end());
    for (auto& c : input.cases) {
      const auto [it, inserted] = seen.emplace(c.info.name, label);
      if (!inserted)
        throw InputError(kParameter, "case '" + c.info.name + "' appears in both '" + it->second +
                                         "' and '" + label + "'");
      merged.cases.push_back(std::move(c));
    }
  }
  return merged;
}

std::vector<ValidationReport> read_reports_from_directory(const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw InputError("results directory", dir.string() + ": not a directory");
  std::vector<fs::path> files;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (it->path().extension() == ".json" && it->is_regular_file(ec)) files.push_back(it->path());
  if (ec) throw InputError("results directory", dir.string() + ": cannot list: " + ec.message());
  if (files.empty())
    throw InputError("results directory", dir.string() + ": no *.json results files");
  std::sort(files.begin(), files.end());
  std::vector<ValidationReport> reports;
  reports.reserve(files.size());
  for (const auto& file : files) reports.push_back(read_report_file(file));
  return reports;
}

}  // namespace rodvv::reports
