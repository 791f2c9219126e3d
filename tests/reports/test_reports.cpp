// Tests of rodvv::reports on a synthetic report: two cases of one group, three levels, metrics
// with and without a reference, one failing gate, one failing level, energy series.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "rodvv/common/errors.hpp"
#include "rodvv/reports/csv.hpp"
#include "rodvv/reports/html.hpp"
#include "rodvv/reports/json_io.hpp"
#include "rodvv/reports/junit.hpp"
#include "rodvv/reports/markdown.hpp"
#include "rodvv/reports/number_format.hpp"
#include "rodvv/reports/report_tables.hpp"
#include "rodvv/reports/plot_manifest.hpp"
#include "rodvv/reports/provenance.hpp"
#include "rodvv/reports/report_writer.hpp"

namespace {

namespace fs = std::filesystem;
using namespace rodvv;
using namespace rodvv::reports;
using nlohmann::json;

constexpr const char* kSymplectic = "pendulum/libration-90/stormer-verlet";
constexpr const char* kEuler = "pendulum/libration-90/explicit-euler";
constexpr const char* kNastyTitle = "Explicit Euler <b>&\"' drifts";

// An energy curve: bounded oscillation (symplectic) or exponential growth (explicit Euler).
harness::Series energy_series(bool growing, double dt) {
  harness::Series s;
  s.name = "energy";
  s.x_label = "t";
  s.y_label = "E(t) - E(0)";
  for (int i = 0; i <= 200; ++i) {
    const double t = 0.5 * i;
    s.x.push_back(t);
    s.y.push_back(growing ? std::expm1(dt * t) : 1e-3 * dt * dt * std::sin(3.0 * t));
  }
  return s;
}

harness::SweepResult symplectic_case() {
  harness::SweepResult r;
  auto& info = r.info;
  info.name = kSymplectic;
  info.family = "pendulum";
  info.group = "pendulum/long-time-energy";
  info.title = "Libration at 90 degrees, Stormer-Verlet";
  info.physics = "theta'' = -(g/L) sin theta, theta(0) = pi/2, theta'(0) = 0";
  info.reference = "period T = 4 K(sin(theta0/2)) sqrt(L/g)";
  info.citation = "Lawden 1989, Elliptic Functions and Applications, ch. 5";
  info.method = "Stormer-Verlet (symplectic, order 2)";
  info.parameters = {
      {"theta0", 1.5707963267948966, 0.0, 3.141592653589793, true, true, "rad", "amplitude"},
      {"omega", 1.0, 0.0, std::numeric_limits<double>::infinity(), true, true, "1/s",
       "natural frequency"}};
  info.resolution = {"dt", "time step", harness::ResolutionScale::StepSize, {0.1, 0.05, 0.025},
                     {0.1, 0.05, 0.025, 0.0125}};
  info.metrics = {{"period-error", harness::MetricKind::Error, "s", "|T_h - T|", true, 2.0},
                  {"energy-drift", harness::MetricKind::Invariant, "J", "max |E - E0|", false,
                   std::nullopt},
                  {"steps", harness::MetricKind::Diagnostic, "", "time steps", false, std::nullopt}};
  const double period = 7.416298709205487;
  for (const double dt : {0.1, 0.05, 0.025}) {
    harness::LevelResult level;
    level.level = dt;
    level.h = dt;
    level.wall_seconds = 0.01 / dt * 1e-3;
    level.cpu_seconds = 0.009 / dt * 1e-3;
    const double err = 0.3 * dt * dt;
    level.metrics["period-error"] = {period + err, period, err};
    level.metrics["energy-drift"] = {1e-3 * dt * dt, 0.0, 1e-3 * dt * dt, 0.5};  // size: the energy
    level.metrics["steps"] = {100.0 / dt, std::nullopt, std::nullopt};
    level.series.push_back(energy_series(false, dt));
    r.levels.push_back(level);
  }
  harness::MetricAnalysis a;
  a.metric = "period-error";
  a.order.pairwise = {2.0000000000000004, 1.9999999999999998};
  a.order.least_squares = 2.0;
  a.order.r_squared = 0.99999999;
  a.order.levels_used = 3;
  a.richardson = harness::RichardsonResult{2.0, 2.0, period, 1.2e-4, 4.8e-4, 1.0};
  r.analyses.push_back(a);
  harness::MetricAnalysis b;
  b.metric = "energy-drift";
  b.order.pairwise = {2.0, std::numeric_limits<double>::quiet_NaN()};
  b.order.levels_used = 0;
  b.richardson_note = "not a smooth functional";
  r.analyses.push_back(b);
  r.gates = {{"period-order", harness::GateKind::Order, "period-error", true, 2.0, 1.9, 2.5,
              "order 2.00 in [1.90, 2.50]", "MOOSE mms window p-0.1 .. p+0.5"},
             {"energy-bound", harness::GateKind::UpperBound, "energy-drift", false, 6.25e-7,
              std::nullopt, 1e-7, "drift 6.25e-07 > 1e-07 at the finest level",
              "symplectic methods keep energy within O(dt^2)"}};
  r.wall_seconds = 0.75;
  return r;
}

harness::SweepResult euler_case() {
  harness::SweepResult r;
  auto& info = r.info;
  info.name = kEuler;
  info.family = "pendulum";
  info.group = "pendulum/long-time-energy";
  info.title = kNastyTitle;
  info.physics = "same as the Stormer-Verlet case";
  info.reference = "E(t) = E(0)";
  info.citation = "Hairer, Lubich, Wanner 2006";
  info.method = "explicit Euler (order 1, not symplectic)";
  info.resolution = {"N", "steps per period", harness::ResolutionScale::Count, {10, 20, 40}, {}};
  info.metrics = {{"energy-drift", harness::MetricKind::Invariant, "J", "", false, 1.0}};
  for (const double n : {10.0, 20.0, 40.0}) {
    harness::LevelResult level;
    level.level = n;
    level.h = 1.0 / n;
    level.wall_seconds = 0.002;
    if (n == 40.0) {
      level.failure = "Newton did not converge, residual 1e-3 \"bad\" <step>";
    } else {
      level.metrics["energy-drift"] = {0.5 / n, 0.0, 0.5 / n};
      level.series.push_back(energy_series(true, 1.0 / n));
    }
    r.levels.push_back(level);
  }
  harness::MetricAnalysis a;
  a.metric = "energy-drift";
  a.order.pairwise = {1.0};
  a.order.least_squares = 1.0;
  a.order.r_squared = 1.0;
  a.order.levels_used = 2;
  r.analyses.push_back(a);
  r.gates = {{"drift-order", harness::GateKind::Order, "energy-drift", true, 1.0, 0.9, 1.5,
              "order 1.00 in [0.90, 1.50]", "first-order method"}};
  r.skipped_gates = {"energy-bound: bound measured at the default parameters"};
  r.wall_seconds = 0.25;
  return r;
}

ValidationReport synthetic_report() {
  ValidationReport report;
  report.provenance = collect_provenance();
  report.cases = {symplectic_case(), euler_case()};
  return report;
}

// A fresh directory under the system temp dir, removed at the end of the test.
class TempDir {
 public:
  explicit TempDir(const std::string& name)
      : path_(fs::temp_directory_path() /
              ("rodvv-test-reports-" + std::to_string(::getpid()) + "-" + name)) {
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto pos = text.find(what); pos != std::string::npos; pos = text.find(what, pos + 1)) ++n;
  return n;
}

// Exact double equality that treats NaN == NaN (a NaN pairwise order is kept as a placeholder).
void expect_same(double a, double b, const std::string& what) {
  if (std::isnan(a) || std::isnan(b))
    EXPECT_TRUE(std::isnan(a) && std::isnan(b)) << what << ": " << a << " vs " << b;
  else
    EXPECT_EQ(a, b) << what;
}

void expect_same(const std::optional<double>& a, const std::optional<double>& b,
                 const std::string& what) {
  ASSERT_EQ(a.has_value(), b.has_value()) << what;
  if (a) expect_same(*a, *b, what);
}

void expect_same(const std::vector<double>& a, const std::vector<double>& b,
                 const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i) expect_same(a[i], b[i], what + "[" + std::to_string(i) + "]");
}

void expect_same(const harness::SweepResult& a, const harness::SweepResult& b) {
  const auto& ia = a.info;
  const auto& ib = b.info;
  EXPECT_EQ(ia.name, ib.name);
  EXPECT_EQ(ia.family, ib.family);
  EXPECT_EQ(ia.group, ib.group);
  EXPECT_EQ(ia.title, ib.title);
  EXPECT_EQ(ia.physics, ib.physics);
  EXPECT_EQ(ia.reference, ib.reference);
  EXPECT_EQ(ia.citation, ib.citation);
  EXPECT_EQ(ia.method, ib.method);
  ASSERT_EQ(ia.parameters.size(), ib.parameters.size());
  for (std::size_t i = 0; i < ia.parameters.size(); ++i) {
    const auto& pa = ia.parameters[i];
    const auto& pb = ib.parameters[i];
    EXPECT_EQ(pa.name, pb.name);
    expect_same(pa.value, pb.value, "value");
    expect_same(pa.min, pb.min, "min");
    expect_same(pa.max, pb.max, "max");
    EXPECT_EQ(pa.min_open, pb.min_open);
    EXPECT_EQ(pa.max_open, pb.max_open);
    EXPECT_EQ(pa.unit, pb.unit);
    EXPECT_EQ(pa.description, pb.description);
  }
  EXPECT_EQ(ia.resolution.name, ib.resolution.name);
  EXPECT_EQ(ia.resolution.description, ib.resolution.description);
  EXPECT_EQ(ia.resolution.scale, ib.resolution.scale);
  expect_same(ia.resolution.default_levels, ib.resolution.default_levels, "default_levels");
  expect_same(ia.resolution.extended_levels, ib.resolution.extended_levels, "extended_levels");
  ASSERT_EQ(ia.metrics.size(), ib.metrics.size());
  for (std::size_t i = 0; i < ia.metrics.size(); ++i) {
    EXPECT_EQ(ia.metrics[i].name, ib.metrics[i].name);
    EXPECT_EQ(ia.metrics[i].kind, ib.metrics[i].kind);
    EXPECT_EQ(ia.metrics[i].unit, ib.metrics[i].unit);
    EXPECT_EQ(ia.metrics[i].description, ib.metrics[i].description);
    EXPECT_EQ(ia.metrics[i].extrapolate, ib.metrics[i].extrapolate);
    expect_same(ia.metrics[i].theoretical_order, ib.metrics[i].theoretical_order, "theory");
  }
  ASSERT_EQ(a.levels.size(), b.levels.size());
  for (std::size_t i = 0; i < a.levels.size(); ++i) {
    const auto& la = a.levels[i];
    const auto& lb = b.levels[i];
    expect_same(la.level, lb.level, "level");
    expect_same(la.h, lb.h, "h");
    expect_same(la.wall_seconds, lb.wall_seconds, "wall_seconds");
    expect_same(la.cpu_seconds, lb.cpu_seconds, "cpu_seconds");
    EXPECT_EQ(la.failure, lb.failure);
    ASSERT_EQ(la.metrics.size(), lb.metrics.size());
    for (const auto& [name, sa] : la.metrics) {
      ASSERT_TRUE(lb.metrics.count(name)) << name;
      const auto& sb = lb.metrics.at(name);
      expect_same(sa.computed, sb.computed, name + ".computed");
      expect_same(sa.reference, sb.reference, name + ".reference");
      expect_same(sa.error, sb.error, name + ".error");
      expect_same(sa.scale, sb.scale, name + ".scale");
    }
    ASSERT_EQ(la.series.size(), lb.series.size());
    for (std::size_t k = 0; k < la.series.size(); ++k) {
      EXPECT_EQ(la.series[k].name, lb.series[k].name);
      EXPECT_EQ(la.series[k].x_label, lb.series[k].x_label);
      EXPECT_EQ(la.series[k].y_label, lb.series[k].y_label);
      expect_same(la.series[k].x, lb.series[k].x, "series x");
      expect_same(la.series[k].y, lb.series[k].y, "series y");
    }
  }
  ASSERT_EQ(a.analyses.size(), b.analyses.size());
  for (std::size_t i = 0; i < a.analyses.size(); ++i) {
    const auto& aa = a.analyses[i];
    const auto& ab = b.analyses[i];
    EXPECT_EQ(aa.metric, ab.metric);
    expect_same(aa.order.pairwise, ab.order.pairwise, "pairwise");
    expect_same(aa.order.least_squares, ab.order.least_squares, "least_squares");
    expect_same(aa.order.r_squared, ab.order.r_squared, "r_squared");
    EXPECT_EQ(aa.order.levels_used, ab.order.levels_used);
    ASSERT_EQ(aa.richardson.has_value(), ab.richardson.has_value());
    if (aa.richardson) {
      expect_same(aa.richardson->refinement_ratio, ab.richardson->refinement_ratio, "r");
      expect_same(aa.richardson->observed_order, ab.richardson->observed_order, "p");
      expect_same(aa.richardson->extrapolated, ab.richardson->extrapolated, "extrapolated");
      expect_same(aa.richardson->gci_fine, ab.richardson->gci_fine, "gci_fine");
      expect_same(aa.richardson->gci_coarse, ab.richardson->gci_coarse, "gci_coarse");
      expect_same(aa.richardson->asymptotic_ratio, ab.richardson->asymptotic_ratio, "ratio");
    }
    EXPECT_EQ(aa.richardson_note, ab.richardson_note);
  }
  ASSERT_EQ(a.gates.size(), b.gates.size());
  for (std::size_t i = 0; i < a.gates.size(); ++i) {
    const auto& ga = a.gates[i];
    const auto& gb = b.gates[i];
    EXPECT_EQ(ga.name, gb.name);
    EXPECT_EQ(ga.kind, gb.kind);
    EXPECT_EQ(ga.metric, gb.metric);
    EXPECT_EQ(ga.passed, gb.passed);
    expect_same(ga.measured, gb.measured, "measured");
    expect_same(ga.lower, gb.lower, "lower");
    expect_same(ga.upper, gb.upper, "upper");
    EXPECT_EQ(ga.reason, gb.reason);
    EXPECT_EQ(ga.rationale, gb.rationale);
  }
  EXPECT_EQ(a.skipped_gates, b.skipped_gates);
  expect_same(a.wall_seconds, b.wall_seconds, "case wall_seconds");
}

void expect_same(const Provenance& a, const Provenance& b) {
  EXPECT_EQ(a.rodvv_version, b.rodvv_version);
  EXPECT_EQ(a.git_commit, b.git_commit);
  EXPECT_EQ(a.compiler_id, b.compiler_id);
  EXPECT_EQ(a.compiler_version, b.compiler_version);
  EXPECT_EQ(a.build_type, b.build_type);
  EXPECT_EQ(a.compile_flags, b.compile_flags);
  EXPECT_EQ(a.cpu_model, b.cpu_model);
  EXPECT_EQ(a.host_cores, b.host_cores);
  EXPECT_EQ(a.date_utc, b.date_utc);
}

// The InputError message of parsing `document`, or "" if it parsed.
std::string load_error(const json& document) {
  try {
    report_from_json(document, "part.json");
  } catch (const InputError& e) {
    EXPECT_EQ(e.parameter(), "results file");
    return e.what();
  }
  return "";
}

// (Hand-written rather than std::regex: GCC 12 warns inside <regex> under the sanitizers.)
bool is_commit(const std::string& s) {
  if (s == "unknown") return true;
  std::string hash = s;
  if (hash.size() > 6 && hash.compare(hash.size() - 6, 6, "-dirty") == 0) hash.resize(hash.size() - 6);
  return hash.size() == 40 && hash.find_first_not_of("0123456789abcdef") == std::string::npos;
}

bool is_iso8601_utc(const std::string& s) {  // 2024-05-01T12:34:56Z
  const std::string shape = "dddd-dd-ddTdd:dd:ddZ";
  if (s.size() != shape.size()) return false;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (shape[i] == 'd' ? !std::isdigit(static_cast<unsigned char>(s[i])) : s[i] != shape[i])
      return false;
  return true;
}

// "nan", "inf" or "infinity" as a whole word, any case (not inside "info" or "Hamiltonian").
bool has_non_finite_word(const std::string& text) {
  std::string word;
  for (std::size_t i = 0; i <= text.size(); ++i) {
    const char ch = i < text.size() ? text[i] : ' ';
    if (std::isalpha(static_cast<unsigned char>(ch))) {
      word += static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
      continue;
    }
    if (word == "nan" || word == "inf" || word == "infinity") return true;
    word.clear();
  }
  return false;
}

bool python_has_matplotlib() {
  return std::system("/usr/bin/python3 -c 'import matplotlib' >/dev/null 2>&1") == 0;
}

// ---------------------------------------------------------------------------------------------

TEST(ReportsProvenance, CollectsBuildAndHostFacts) {
  const Provenance p = collect_provenance();
  EXPECT_FALSE(p.rodvv_version.empty());
  EXPECT_TRUE(is_commit(p.git_commit)) << p.git_commit;
  EXPECT_FALSE(p.compiler_id.empty());
  EXPECT_FALSE(p.compiler_version.empty());
  EXPECT_FALSE(p.cpu_model.empty());
  EXPECT_GT(p.host_cores, 0u);
  EXPECT_TRUE(is_iso8601_utc(p.date_utc)) << p.date_utc;
}

TEST(ReportsDocument, PassedIsFalseWithAFailingGateOrLevel) {
  ValidationReport report = synthetic_report();
  EXPECT_FALSE(report.passed());
  EXPECT_FALSE(report.cases[0].passed());  // failing gate
  EXPECT_FALSE(report.cases[1].passed());  // failing level
  const ReportTotals t = totals(report);
  EXPECT_EQ(t.cases, 2u);
  EXPECT_EQ(t.cases_passed, 0u);
  EXPECT_EQ(t.gates, 3u);
  EXPECT_EQ(t.gates_passed, 2u);
  EXPECT_EQ(t.levels, 6u);
  EXPECT_EQ(t.levels_failed, 1u);
  report.cases[0].gates[1].passed = true;
  report.cases[1].levels.pop_back();
  EXPECT_TRUE(report.passed());
}

TEST(ReportsJson, RoundTripKeepsEveryField) {
  ValidationReport report = synthetic_report();
  report.merged_from = {"a.json", "b.json"};
  const std::string text = to_json(report).dump(2);
  const ValidationReport back = report_from_json(json::parse(text), "memory");
  EXPECT_EQ(back.schema_version, kSchemaVersion);
  EXPECT_EQ(back.source, "memory");
  EXPECT_EQ(back.merged_from, report.merged_from);
  expect_same(report.provenance, back.provenance);
  ASSERT_EQ(back.cases.size(), report.cases.size());
  for (std::size_t i = 0; i < report.cases.size(); ++i) expect_same(report.cases[i], back.cases[i]);
  // A second trip gives the same text: nothing is lost or reinterpreted.
  EXPECT_EQ(to_json(back).dump(2), text);
}

// A parameter study's scale travels through the JSON, and its page has no order table (no order is fitted).
TEST(ReportsJson, AParameterStudyKeepsItsScaleAndHasNoOrderTable) {
  ValidationReport report = synthetic_report();
  auto& study = report.cases[1];
  study.info.resolution.scale = harness::ResolutionScale::Parameter;
  const json j = to_json(report);
  EXPECT_EQ(j["cases"][1]["info"]["resolution"]["scale"], "parameter");
  const ValidationReport back = report_from_json(j, "memory");
  EXPECT_EQ(back.cases[1].info.resolution.scale, harness::ResolutionScale::Parameter);
  EXPECT_TRUE(case_tables(study).orders.empty());
  EXPECT_FALSE(case_tables(report.cases[0]).orders.empty());
}

TEST(ReportsJson, AbsentOptionalsAreNull) {
  const json j = to_json(synthetic_report());
  const json& sym = j["cases"][0];
  EXPECT_TRUE(sym["levels"][0]["metrics"]["steps"]["reference"].is_null());
  EXPECT_TRUE(sym["levels"][0]["metrics"]["steps"]["error"].is_null());
  EXPECT_TRUE(sym["levels"][0]["metrics"]["steps"]["scale"].is_null());
  EXPECT_TRUE(sym["levels"][0]["failure"].is_null());
  EXPECT_TRUE(sym["info"]["metrics"][1]["theoretical_order"].is_null());
  EXPECT_TRUE(sym["analyses"][1]["richardson"].is_null());
  EXPECT_TRUE(sym["analyses"][1]["order"]["least_squares"].is_null());
  EXPECT_TRUE(sym["analyses"][1]["order"]["pairwise"][1].is_null());  // NaN placeholder
  EXPECT_TRUE(sym["analyses"][0]["richardson_note"].is_null());
  EXPECT_TRUE(sym["gates"][1]["lower"].is_null());
  EXPECT_EQ(sym["info"]["metrics"][0]["kind"], "error");
  EXPECT_EQ(sym["gates"][1]["kind"], "upper-bound");
  EXPECT_EQ(sym["info"]["resolution"]["scale"], "step-size");
  EXPECT_EQ(j["cases"][1]["info"]["resolution"]["scale"], "count");
  EXPECT_EQ(j["passed"], false);
}

TEST(ReportsJson, NonFiniteDoublesAreWrittenAsNull) {
  ValidationReport report = synthetic_report();
  auto& sample = report.cases[0].levels[0].metrics["period-error"];
  sample.computed = std::numeric_limits<double>::quiet_NaN();
  sample.error = std::numeric_limits<double>::infinity();
  report.cases[0].wall_seconds = -std::numeric_limits<double>::infinity();
  const std::string text = to_json(report).dump();
  EXPECT_FALSE(has_non_finite_word(text));

  const ValidationReport back = report_from_json(json::parse(text), "memory");
  const auto& read = back.cases[0].levels[0].metrics.at("period-error");
  EXPECT_TRUE(std::isnan(read.computed));
  EXPECT_FALSE(read.error.has_value());
  // An infinite parameter bound is an unbounded side and comes back as one.
  EXPECT_EQ(back.cases[0].info.parameters[1].max, std::numeric_limits<double>::infinity());
  // Renderers print n/a, never nan or inf.
  const std::string md = render_markdown(back);
  const std::string html = render_html(back, {});
  for (const auto* text_out : {&md, &html}) {
    EXPECT_FALSE(has_non_finite_word(*text_out));
    EXPECT_NE(text_out->find("n/a"), std::string::npos);
  }
}

TEST(ReportsJson, DoublesRoundTripBitExactThroughAFile) {
  TempDir dir("doubles");
  ValidationReport report = synthetic_report();
  const std::vector<double> values = {0.1,
                                      1.0 / 3.0,
                                      2.0 / 3.0 * 1e-17,
                                      std::numeric_limits<double>::denorm_min(),
                                      std::numeric_limits<double>::min(),
                                      std::numeric_limits<double>::max(),
                                      std::nextafter(1.0, 2.0),
                                      -0.0,
                                      123456789012345680.0,
                                      64.0};
  report.cases[0].levels[0].series[0].x = values;
  report.cases[0].levels[0].series[0].y = values;
  const fs::path file = dir.path() / "doubles.json";
  write_report_file(file, report);
  const std::string text = read_text(file);
  EXPECT_EQ(text.rfind("{\n  \"", 0), 0u) << "pretty-printed with a 2-space indent";
  const ValidationReport back = read_report_file(file);
  EXPECT_EQ(back.source, file.string());
  const auto& x = back.cases[0].levels[0].series[0].x;
  ASSERT_EQ(x.size(), values.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    EXPECT_EQ(x[i], values[i]) << i;
    EXPECT_EQ(std::signbit(x[i]), std::signbit(values[i])) << i;
  }
}

TEST(ReportsJson, WrongSchemaVersionIsRejected) {
  json j = to_json(synthetic_report());
  j["schema_version"] = 2;
  const std::string message = load_error(j);
  EXPECT_NE(message.find("part.json"), std::string::npos) << message;
  EXPECT_NE(message.find("'schema_version'"), std::string::npos) << message;
  EXPECT_NE(message.find("2"), std::string::npos) << message;
  j["schema_version"] = "1";
  EXPECT_NE(load_error(j).find("'schema_version': expected an integer"), std::string::npos);
}

// Files written before CPU time was recorded still read: their levels' cpu_seconds is 0 ("not
// measured"), and the work-precision plots fall back to wall time.
TEST(ReportsJson, LevelsWithoutCpuTimeReadAsZero) {
  json j = to_json(synthetic_report());
  for (auto& c : j["cases"])
    for (auto& level : c["levels"]) level.erase("cpu_seconds");
  const ValidationReport back = report_from_json(j, "memory");
  ASSERT_FALSE(back.cases.empty());
  ASSERT_FALSE(back.cases[0].levels.empty());
  EXPECT_EQ(back.cases[0].levels[0].cpu_seconds, 0.0);
}

// Files written before metric sizes were recorded still read: no scale; a wrong type is refused.
TEST(ReportsJson, MetricsWithoutScaleReadAsNone) {
  json j = to_json(synthetic_report());
  for (auto& c : j["cases"])
    for (auto& level : c["levels"])
      for (auto& [name, metric] : level["metrics"].items()) metric.erase("scale");
  const ValidationReport back = report_from_json(j, "memory");
  EXPECT_FALSE(back.cases[0].levels[0].metrics.at("energy-drift").scale.has_value());
  json wrong = to_json(synthetic_report());
  wrong["cases"][0]["levels"][0]["metrics"]["energy-drift"]["scale"] = "big";
  const std::string message = load_error(wrong);
  EXPECT_NE(message.find("scale"), std::string::npos) << message;
}

TEST(ReportsJson, MissingCasesIsRejected) {
  json j = to_json(synthetic_report());
  j.erase("cases");
  const std::string message = load_error(j);
  EXPECT_NE(message.find("field 'cases'"), std::string::npos) << message;
  EXPECT_NE(message.find("missing"), std::string::npos) << message;
}

TEST(ReportsJson, IllTypedFieldsNameTheirPath) {
  json j = to_json(synthetic_report());
  j["cases"][0]["levels"][1]["metrics"]["period-error"]["computed"] = "1.5";
  std::string message = load_error(j);
  EXPECT_NE(message.find("part.json: field "
                         "'cases[0].levels[1].metrics['period-error'].computed': expected a "
                         "number or null, got a string"),
            std::string::npos)
      << message;

  j = to_json(synthetic_report());
  j["cases"][1]["levels"][0]["metrics"] = json::array();
  message = load_error(j);
  EXPECT_NE(message.find("'cases[1].levels[0].metrics': expected an object, got an array"),
            std::string::npos)
      << message;

  j = to_json(synthetic_report());
  j["cases"][0]["gates"][1]["kind"] = "sideways";
  message = load_error(j);
  EXPECT_NE(message.find("'cases[0].gates[1].kind': unknown value 'sideways'"), std::string::npos)
      << message;
  EXPECT_NE(message.find("'upper-bound'"), std::string::npos) << message;

  j = to_json(synthetic_report());
  j["cases"][0]["analyses"][0]["order"]["levels_used"] = -1;
  message = load_error(j);
  EXPECT_NE(message.find("'cases[0].analyses[0].order.levels_used': expected a non-negative"),
            std::string::npos)
      << message;

  j = to_json(synthetic_report());
  j["cases"][0]["levels"][0]["series"][0]["y"].erase(0);
  message = load_error(j);
  EXPECT_NE(message.find("'cases[0].levels[0].series[0].y'"), std::string::npos) << message;

  EXPECT_NE(load_error(json::array()).find("top level"), std::string::npos);
}

TEST(ReportsJson, NotJsonTextIsRejected) {
  TempDir dir("notjson");
  const fs::path file = dir.path() / "broken.json";
  write_text(file, "this is { not json");
  try {
    read_report_file(file);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(file.string()), std::string::npos) << message;
    EXPECT_NE(message.find("not valid JSON"), std::string::npos) << message;
  }
  EXPECT_THROW(read_report_file(dir.path() / "absent.json"), InputError);
}

TEST(ReportsMerge, MergesTwoFilesFromADirectory) {
  TempDir dir("merge");
  ValidationReport a = synthetic_report();
  a.cases.pop_back();
  a.provenance.cpu_model = "first machine";
  ValidationReport b = synthetic_report();
  b.cases.erase(b.cases.begin());
  b.provenance.cpu_model = "second machine";
  write_report_file(dir.path() / "b-part.json", b);
  write_report_file(dir.path() / "a-part.json", a);
  write_text(dir.path() / "notes.txt", "ignored");

  const auto inputs = read_reports_from_directory(dir.path());
  ASSERT_EQ(inputs.size(), 2u);
  const ValidationReport merged = merge_reports(inputs);
  ASSERT_EQ(merged.cases.size(), 2u);
  EXPECT_EQ(merged.cases[0].info.name, kSymplectic);  // sorted by file name: a-part first
  EXPECT_EQ(merged.cases[1].info.name, kEuler);
  EXPECT_EQ(merged.provenance.cpu_model, "first machine");
  ASSERT_EQ(merged.merged_from.size(), 2u);
  EXPECT_EQ(merged.merged_from[0], (dir.path() / "a-part.json").string());
  EXPECT_EQ(merged.merged_from[1], (dir.path() / "b-part.json").string());

  // A merge of merges lists the original sources, and the list survives the file.
  write_report_file(dir.path() / "c-merged.json", merged);
  const ValidationReport again = read_report_file(dir.path() / "c-merged.json");
  EXPECT_EQ(again.merged_from, merged.merged_from);
  ValidationReport extra = synthetic_report();
  extra.cases.resize(1);
  extra.cases[0].info.name = "pendulum/other";
  extra.source = "d.json";
  const ValidationReport nested = merge_reports({again, extra});
  EXPECT_EQ(nested.merged_from.size(), 3u);
  EXPECT_EQ(nested.merged_from.back(), "d.json");
}

TEST(ReportsMerge, DuplicateCaseIsRejectedNamingBothSources) {
  ValidationReport a = synthetic_report();
  a.source = "run-1.json";
  ValidationReport b = synthetic_report();
  b.cases.erase(b.cases.begin());
  b.source = "run-2.json";
  try {
    merge_reports({a, b});
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(kEuler), std::string::npos) << message;
    EXPECT_NE(message.find("run-1.json"), std::string::npos) << message;
    EXPECT_NE(message.find("run-2.json"), std::string::npos) << message;
  }
  EXPECT_THROW(merge_reports({}), InputError);
}

TEST(ReportsMerge, DirectoryWithoutResultsIsRejected) {
  TempDir dir("empty");
  write_text(dir.path() / "readme.txt", "no json here");
  EXPECT_THROW(read_reports_from_directory(dir.path()), InputError);
  EXPECT_THROW(read_reports_from_directory(dir.path() / "missing"), InputError);
}

TEST(ReportsCsv, OneRowPerCaseLevelMetricWithQuoting) {
  ValidationReport report = synthetic_report();
  report.cases[1].info.family = "pend,ulum \"x\"";
  const std::string csv = render_csv(report);
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "case,family,level,h,metric,kind,computed,reference,error,wall_seconds");
  std::size_t rows = 0;
  while (std::getline(in, line)) ++rows;
  EXPECT_EQ(rows, 3u * 3u + 2u * 1u);  // 3 levels x 3 metrics; 2 healthy levels x 1 metric
  EXPECT_NE(csv.find("pendulum/libration-90/stormer-verlet,pendulum,0.1,0.1,period-error,error,"),
            std::string::npos);
  // Shortest round-trip doubles; absent reference/error are empty fields.
  EXPECT_NE(csv.find(",steps,diagnostic,1000,,,"), std::string::npos) << csv;
  EXPECT_NE(csv.find(kEuler + std::string(",\"pend,ulum \"\"x\"\"\",10,0.1,energy-drift,"
                                          "invariant,0.05,0,0.05,0.002")),
            std::string::npos)
      << csv;
}

TEST(ReportsMarkdown, ContainsCasesStatusAndTables) {
  const std::string md = render_markdown(synthetic_report());
  EXPECT_NE(md.find("# rodvv validation report"), std::string::npos);
  EXPECT_NE(md.find("**Status: FAIL**"), std::string::npos);
  EXPECT_NE(md.find("pendulum/libration-90/stormer-verlet"), std::string::npos);
  EXPECT_NE(md.find("pendulum/libration-90/explicit-euler"), std::string::npos);
  EXPECT_NE(md.find("| PASS |"), std::string::npos);
  EXPECT_NE(md.find("**FAIL**"), std::string::npos);
  EXPECT_NE(md.find("| period-error | 2.00 | 2.00, 2.00 | 2.00 | 1.0000 | 3 |"), std::string::npos)
      << md;
  EXPECT_NE(md.find("Richardson extrapolation and GCI"), std::string::npos);
  EXPECT_NE(md.find("energy-drift: not a smooth functional"), std::string::npos);
  EXPECT_NE(md.find("- energy-bound: bound measured at the default parameters"), std::string::npos);
  EXPECT_NE(md.find("| 1/1 (1 skipped) |"), std::string::npos) << md;
  EXPECT_NE(md.find("\\[1.90, 2.50\\]"), std::string::npos);  // gate window
  EXPECT_NE(md.find("\u2264 1.00e-07"), std::string::npos);
  EXPECT_NE(md.find("3.00e-03"), std::string::npos);  // error at dt = 0.1, 3 significant digits
  // Markup in a title is escaped, not interpreted.
  EXPECT_EQ(md.find("<b>"), std::string::npos);
  EXPECT_NE(md.find("\\<b\\>\\&\"'"), std::string::npos);
}

TEST(ReportsHtml, EscapesTextAndColoursStatus) {
  PlotManifest plots;
  plots.cases[kSymplectic] = {{"plots/a\"b.png", "caption <i>"}};
  plots.groups["pendulum/long-time-energy"] = {{"plots/group.png", "energy overlay"}};
  const std::string html = render_html(synthetic_report(), plots);
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("<style>"), std::string::npos);
  // One script, the page's own filters (no external resources: the page works offline).
  EXPECT_EQ(count(html, "<script"), 1u);
  EXPECT_EQ(html.find("<script src"), std::string::npos);
  EXPECT_EQ(html.find("<b>&"), std::string::npos);
  EXPECT_NE(html.find("Explicit Euler &lt;b&gt;&amp;&quot;&#39; drifts"), std::string::npos);
  EXPECT_NE(html.find("&lt;step&gt;"), std::string::npos);  // level failure text
  EXPECT_NE(html.find(kSymplectic), std::string::npos);
  EXPECT_NE(html.find(kEuler), std::string::npos);
  EXPECT_NE(html.find("class=\"pass\">PASS</td>"), std::string::npos);
  EXPECT_NE(html.find("class=\"fail\">FAIL</td>"), std::string::npos);
  EXPECT_NE(html.find("<img src=\"plots/a&quot;b.png\" alt=\"caption &lt;i&gt;\""),
            std::string::npos);
  EXPECT_NE(html.find("<img src=\"plots/group.png\""), std::string::npos);
  // Group overlays come before the group's first case.
  EXPECT_LT(html.find("plots/group.png"), html.find("<section class=\"case filterable\""));
  EXPECT_NE(html.find("href=\"#case-pendulum-libration-90-stormer-verlet\""), std::string::npos);
  EXPECT_EQ(html.find("plots unavailable"), std::string::npos);
  // Every container that is opened is closed.
  for (const char* tag : {"table", "section", "ul", "div", "figure", "dl", "nav", "svg", "form", "script"})
    EXPECT_EQ(count(html, std::string("<") + tag + ">") + count(html, std::string("<") + tag + " "),
              count(html, std::string("</") + tag + ">"))
        << tag;

  plots = {};
  plots.unavailable_reason = "matplotlib is not available";
  EXPECT_NE(render_html(synthetic_report(), plots).find("plots unavailable: matplotlib"),
            std::string::npos);
}

TEST(ReportsJunit, CountsGatesAndLevelFailures) {
  const std::string xml = render_junit(synthetic_report());
  EXPECT_EQ(xml.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>", 0), 0u);
  EXPECT_NE(xml.find("<testsuites name=\"rodvv\" tests=\"5\" failures=\"2\" errors=\"0\" "
                     "skipped=\"1\""),
            std::string::npos)
      << xml;
  EXPECT_NE(xml.find("<testsuite name=\"" + std::string(kSymplectic) +
                     "\" tests=\"2\" failures=\"1\" errors=\"0\" skipped=\"0\" time=\"0.750000\""),
            std::string::npos)
      << xml;
  EXPECT_NE(xml.find("<testsuite name=\"" + std::string(kEuler) +
                     "\" tests=\"3\" failures=\"1\" errors=\"0\" skipped=\"1\""),
            std::string::npos)
      << xml;
  EXPECT_NE(xml.find("name=\"energy-bound\" time=\"0.000000\">\n      <skipped message=\"energy-bound: "
                     "bound measured at the default parameters\"/>"),
            std::string::npos)
      << xml;
  EXPECT_NE(xml.find("<testcase classname=\"" + std::string(kSymplectic) +
                     "\" name=\"period-order\" time=\"0.375000\"/>"),
            std::string::npos)
      << xml;
  EXPECT_NE(xml.find("<failure message=\"drift 6.25e-07 &gt; 1e-07 at the finest level\" "
                     "type=\"upper-bound\">"),
            std::string::npos)
      << xml;
  EXPECT_NE(xml.find("name=\"level N=40\""), std::string::npos) << xml;
  EXPECT_NE(xml.find("message=\"Newton did not converge, residual 1e-3 &quot;bad&quot; "
                     "&lt;step&gt;\" type=\"level-failure\""),
            std::string::npos)
      << xml;
  EXPECT_EQ(count(xml, "<testcase "), 5u);
  EXPECT_EQ(count(xml, "<failure "), 2u);
}

TEST(ReportsWriter, WritesAllFilesEvenWithoutPython) {
  TempDir dir("nopython");
  WriteOptions options;
  options.python = "/nonexistent/python3";
  const fs::path out = dir.path() / "report dir with 'quotes'";
  const WrittenReport written = write_report_directory(synthetic_report(), out, options);
  EXPECT_FALSE(written.plots_ok);
  EXPECT_NE(written.plots_message.find("plots unavailable: cannot run /nonexistent/python3"),
            std::string::npos)
      << written.plots_message;
  for (const char* name : {"results.json", "results.csv", "report.md", "junit.xml", "index.html"})
    EXPECT_TRUE(fs::exists(out / name)) << name;
  EXPECT_EQ(written.files.back(), out / "index.html");
  EXPECT_NE(read_text(out / "index.html").find("plots unavailable: cannot run"), std::string::npos);
  // results.json reads back as the same report.
  const ValidationReport back = read_report_file(out / "results.json");
  ASSERT_EQ(back.cases.size(), 2u);
  expect_same(synthetic_report().cases[1], back.cases[1]);
}

TEST(ReportsWriter, ReportsAFailingPlotScript) {
  if (!fs::exists("/usr/bin/python3")) GTEST_SKIP() << "no /usr/bin/python3";
  TempDir dir("badscript");
  const fs::path script = dir.path() / "fail.py";
  write_text(script, "import sys\nprint('something went wrong', file=sys.stderr)\nsys.exit(5)\n");
  WriteOptions options;
  options.plot_script = script;
  const WrittenReport written =
      write_report_directory(synthetic_report(), dir.path() / "out", options);
  EXPECT_FALSE(written.plots_ok);
  EXPECT_NE(written.plots_message.find("something went wrong"), std::string::npos)
      << written.plots_message;
  EXPECT_TRUE(fs::exists(dir.path() / "out" / "plots" / "plot.log"));
  EXPECT_TRUE(fs::exists(dir.path() / "out" / "index.html"));
}

TEST(ReportsPlots, ScriptWritesManifestAndImages) {
  if (!python_has_matplotlib()) GTEST_SKIP() << "/usr/bin/python3 has no matplotlib";
  TempDir dir("plots");
  WriteOptions options;
  options.plot_script = RODVV_TEST_PLOT_SCRIPT;
  const auto start = std::chrono::steady_clock::now();
  const WrittenReport written = write_report_directory(synthetic_report(), dir.path(), options);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(written.plots_ok) << written.plots_message << "\n"
                                << read_text(dir.path() / "plots" / "plot.log");
  std::cout << "write_report_directory with plots: " << seconds << " s, "
            << written.plots_message << "\n";

  const PlotManifest manifest = read_plot_manifest(dir.path() / "plots" / "manifest.json");
  ASSERT_TRUE(manifest.cases.count(kSymplectic));
  ASSERT_TRUE(manifest.cases.count(kEuler));
  const auto& sym = manifest.cases.at(kSymplectic);
  ASSERT_EQ(sym.size(), 2u);  // convergence + energy series
  EXPECT_EQ(sym[0].file, "plots/pendulum-libration-90-stormer-verlet-convergence.png");
  EXPECT_EQ(sym[1].file, "plots/pendulum-libration-90-stormer-verlet-series-energy.png");
  // The Euler case has only an invariant metric: invariants converge too (|E - E(0)| -> 0), so it
  // gets a convergence plot as well as its series.
  ASSERT_EQ(manifest.cases.at(kEuler).size(), 2u);
  ASSERT_TRUE(manifest.groups.count("pendulum/long-time-energy"));
  EXPECT_EQ(manifest.groups.at("pendulum/long-time-energy").at(0).file,
            "plots/group-pendulum-long-time-energy-energy.png");
  for (const auto& [name, files] : manifest.cases)
    for (const auto& f : files) EXPECT_GT(fs::file_size(dir.path() / f.file), 1000u) << f.file;
  for (const auto& [name, files] : manifest.groups)
    for (const auto& f : files) EXPECT_GT(fs::file_size(dir.path() / f.file), 1000u) << f.file;

  const std::string html = read_text(dir.path() / "index.html");
  EXPECT_EQ(html.find("plots unavailable"), std::string::npos);
  // RODVV_TEST_REPORT_DIR=DIR keeps a copy of the sample report for looking at.
  if (const char* keep = std::getenv("RODVV_TEST_REPORT_DIR"); keep && *keep)
    write_report_directory(synthetic_report(), keep, options);
  EXPECT_NE(html.find("<img src=\"plots/group-pendulum-long-time-energy-energy.png\""),
            std::string::npos);
}

TEST(ReportsPlots, ScriptRejectsMalformedInput) {
  if (!python_has_matplotlib()) GTEST_SKIP() << "/usr/bin/python3 has no matplotlib";
  TempDir dir("plotbad");
  json j = to_json(synthetic_report());
  j["cases"][0]["levels"] = "oops";
  write_text(dir.path() / "results.json", j.dump());
  const std::string command = std::string("/usr/bin/python3 '") + RODVV_TEST_PLOT_SCRIPT + "' '" +
                              (dir.path() / "results.json").string() + "' '" +
                              (dir.path() / "plots").string() + "' 2>'" +
                              (dir.path() / "err.txt").string() + "'";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  EXPECT_NE(read_text(dir.path() / "err.txt").find("cases[0].levels"), std::string::npos);
}

TEST(ReportsFormat, CompactNumbersAndNotAvailable) {
  EXPECT_EQ(format_error(1.23456e-5), "1.23e-05");
  EXPECT_EQ(format_order(2.004), "2.00");
  EXPECT_EQ(format_value(6.283185307179586), "6.28319");
  EXPECT_EQ(format_shortest(0.1), "0.1");
  EXPECT_EQ(format_shortest(64.0), "64");
  EXPECT_EQ(format_error(std::nullopt), "n/a");
  EXPECT_EQ(format_order(std::numeric_limits<double>::quiet_NaN()), "n/a");
  EXPECT_EQ(format_seconds(std::numeric_limits<double>::infinity()), "n/a");
}

}  // namespace
