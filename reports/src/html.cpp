#include "rodvv/reports/html.hpp"

#include <set>

#include "rodvv/reports/markup_escape.hpp"
#include "rodvv/reports/overview.hpp"
#include "rodvv/reports/report_tables.hpp"

namespace rodvv::reports {

namespace {

constexpr const char* kStyle = R"css(
body{font-family:system-ui,-apple-system,"Segoe UI",Roboto,"Helvetica Neue",Arial,sans-serif;
  color:#1f2328;max-width:1280px;margin:0 auto;padding:1em 2em 4em;line-height:1.45}
h1{margin:.4em 0 .2em}h2{border-bottom:2px solid #d0d7de;padding-bottom:.2em;margin-top:1.6em}
h3{margin-top:1.4em;color:#344}h5{margin:1.1em 0 .3em;font-size:.95em;color:#444}
a{color:#0969da;text-decoration:none}a:hover{text-decoration:underline}
table{border-collapse:collapse;margin:.3em 0 .8em;font-size:.88em}
th,td{border:1px solid #d0d7de;padding:.25em .6em;vertical-align:top;text-align:left}
th{background:#f3f5f8;font-weight:600}
tbody tr:nth-child(even) td{background:#fafbfc}
td.num{text-align:right;white-space:nowrap;font-variant-numeric:tabular-nums}
td.pass,tbody tr td.pass{background:#dafbe1;color:#116329;font-weight:700;text-align:center}
td.fail,tbody tr td.fail{background:#ffebe9;color:#a40e26;font-weight:700}
.scroll{overflow-x:auto;max-width:100%}
.badge{display:inline-block;padding:.05em .55em;border-radius:.8em;font-size:.78em;
  font-weight:700;color:#fff;vertical-align:middle;letter-spacing:.03em}
.badge.pass{background:#1a7f37}.badge.fail{background:#cf222e}
.summary{border:1px solid #d0d7de;border-radius:8px;padding:.8em 1.2em;margin:1em 0;
  display:flex;gap:2.5em;flex-wrap:wrap;align-items:center}
.summary.pass{border-left:8px solid #1a7f37}.summary.fail{border-left:8px solid #cf222e}
.summary .big{font-size:1.8em;font-weight:800}.summary .pass{color:#1a7f37}
.summary .fail{color:#cf222e}.summary .stat{font-size:1.05em}
.summary .stat b{font-size:1.3em}
.note{background:#fff8c5;border:1px solid #d4a72c;border-radius:6px;padding:.4em .8em}
nav.toc ul{list-style:none;padding-left:1.2em;margin:.2em 0}nav.toc>ul{padding-left:0}
nav.toc li{margin:.1em 0}.family{font-weight:700}.group{font-style:italic;color:#444}
section.case{border-top:1px solid #d0d7de;margin-top:1.6em;padding-top:.2em}
section.case h4{font-size:1.15em;margin:.6em 0 .2em}
.title{color:#57606a;margin:0 0 .5em}
dl.info{display:grid;grid-template-columns:max-content 1fr;gap:.2em 1em;margin:.4em 0 .8em}
dl.info dt{font-weight:600;color:#444}dl.info dd{margin:0}
.plots{display:flex;flex-wrap:wrap;gap:.6em 1.2em;align-items:flex-start;margin:.4em 0 .8em}
figure{margin:0;max-width:100%}
figure img{max-width:100%;border:1px solid #d0d7de;border-radius:4px}
figcaption{font-size:.82em;color:#57606a;max-width:560px}
p.skipped{margin:.4em 0 0;font-size:.9em;color:#57606a}
ul.notes{margin:.2em 0 .8em;font-size:.9em;color:#57606a}
footer{margin-top:3em;color:#57606a;font-size:.85em}
.filters{position:sticky;top:0;z-index:2;background:#fff;border-bottom:1px solid #d0d7de;
  padding:.5em 0;display:flex;gap:1.2em;flex-wrap:wrap;align-items:center;font-size:.92em}
.filters label{font-weight:600}.filters select,.filters input{margin-left:.4em;font:inherit}
.filtered-out{display:none}
svg.overview{width:100%;max-width:1000px;height:auto;font-size:12px;fill:#1f2328}
svg.overview .heading{font-weight:700;font-size:13px}
svg.overview line.grid{stroke:#d0d7de;stroke-width:.7}
svg.overview line.zero{stroke:#cf222e;stroke-width:1.2}
svg.overview line.diagonal{stroke:#57606a;stroke-dasharray:4 3}
svg.overview line.window{stroke:#8c959f;stroke-width:1}
svg.overview rect.failzone{fill:#ffebe9}
svg.overview circle{stroke:#fff;stroke-width:.8;fill-opacity:.75}
svg.overview circle.pass{fill:#1a7f37}svg.overview circle.fail{fill:#cf222e}
svg.overview circle.clipped{stroke:#1f2328;stroke-width:1.5}
svg.overview a.point:hover circle{stroke:#0969da;stroke-width:2}
)css";

// The page's filters (family, status, name): everything of a case carries class "filterable" and
// data-* attributes (case_filter_attributes); a "filter-container" (a family or group block, a
// contents entry) is hidden when none of its filterables is shown. The URL's query string
// (?family=...&status=...&name=...) sets the initial state, so a filtered view can be linked.
constexpr const char* kFilterScript = R"js(
(function () {
  var family = document.getElementById('filter-family');
  var status = document.getElementById('filter-status');
  var name = document.getElementById('filter-name');
  var count = document.getElementById('filter-count');
  function matches(el) {
    var d = el.dataset, f = family.value, s = status.value, n = name.value.trim().toLowerCase();
    if (f && d.family !== f) return false;
    if (s === 'skipped' ? d.skipped !== '1' : (s && d.status !== s)) return false;
    return !n || d.name.toLowerCase().indexOf(n) >= 0;
  }
  function apply() {
    document.querySelectorAll('.filterable').forEach(function (el) {
      el.classList.toggle('filtered-out', !matches(el));
    });
    document.querySelectorAll('.filter-container').forEach(function (el) {
      el.classList.toggle('filtered-out', !el.querySelector('.filterable:not(.filtered-out)'));
    });
    var cases = document.querySelectorAll('section.case');
    var shown = document.querySelectorAll('section.case:not(.filtered-out)').length;
    count.textContent = 'showing ' + shown + ' of ' + cases.length + ' cases';
  }
  var query = new URLSearchParams(window.location.search);
  if (query.has('family')) family.value = query.get('family');
  if (query.has('status')) status.value = query.get('status');
  if (query.has('name')) name.value = query.get('name');
  family.addEventListener('change', apply);
  status.addEventListener('change', apply);
  name.addEventListener('input', apply);
  apply();
})();
)js";

const char* css_class(CellStyle style) {
  switch (style) {
    case CellStyle::Number: return " class=\"num\"";
    case CellStyle::Pass: return " class=\"pass\"";
    case CellStyle::Fail: return " class=\"fail\"";
    case CellStyle::Text: return "";
  }
  return "";
}

std::string badge(bool passed) {
  return std::string("<span class=\"badge ") + (passed ? "pass" : "fail") + "\">" +
         status_text(passed) + "</span>";
}

// row_attributes: empty, or one attribute string per row (" class=... data-...").
void append_table(std::string& out, const Table& table, const std::vector<std::string>& row_attributes = {}) {
  out += "<div class=\"scroll\"><table>\n<thead><tr>";
  for (const auto& h : table.header) out += "<th>" + escape_xml(h) + "</th>";
  out += "</tr></thead>\n<tbody>\n";
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    out += "<tr" + (row_attributes.empty() ? std::string() : row_attributes[r]) + ">";
    for (const auto& cell : table.rows[r])
      out += std::string("<td") + css_class(cell.style) + ">" + escape_xml(cell.text) + "</td>";
    out += "</tr>\n";
  }
  out += "</tbody></table></div>\n";
}

void append_section(std::string& out, const char* heading, const Table& table) {
  if (table.empty()) return;
  out += std::string("<h5>") + heading + "</h5>\n";
  append_table(out, table);
}

void append_figures(std::string& out, const std::vector<PlotFile>& plots) {
  for (const auto& plot : plots) {
    const std::string alt = plot.caption.empty() ? plot.file : plot.caption;
    out += "<figure><img src=\"" + escape_xml_attribute(plot.file) + "\" alt=\"" +
           escape_xml_attribute(alt) + "\" loading=\"lazy\"><figcaption>" +
           escape_xml(plot.caption) + "</figcaption></figure>\n";
  }
}

// Unique element ids derived from names (distinct names can share a slug).
class IdMaker {
 public:
  std::string make(const std::string& prefix, const std::string& name) {
    const std::string base = prefix + slugify(name);
    std::string id = base;
    for (int n = 2; !used_.insert(id).second; ++n) id = base + "-" + std::to_string(n);
    return id;
  }

 private:
  std::set<std::string> used_;
};

void append_info(std::string& out, const harness::CaseInfo& info) {
  auto field = [&out](const char* label, const std::string& value) {
    if (value.empty()) return;
    out += std::string("<dt>") + label + "</dt><dd>" + escape_xml(value) + "</dd>\n";
  };
  out += "<dl class=\"info\">\n";
  field("Physics", info.physics);
  field("Reference", info.reference);
  field("Citation", info.citation);
  field("Method", info.method);
  if (!info.resolution.name.empty())
    field("Resolution", info.resolution.name + " (" + harness::to_string(info.resolution.scale) +
                            ")" +
                            (info.resolution.description.empty()
                                 ? ""
                                 : ": " + info.resolution.description));
  out += "</dl>\n";
}

void append_case(std::string& out, const harness::SweepResult& result, const std::string& id,
                 const PlotManifest& plots) {
  const auto& info = result.info;
  out += "<section class=\"case filterable\" id=\"" + escape_xml_attribute(id) + "\"" +
         case_filter_attributes(result) + ">\n<h4>" +
         escape_xml(info.name) + " " + badge(result.passed()) + "</h4>\n";
  if (!info.title.empty()) out += "<p class=\"title\">" + escape_xml(info.title) + "</p>\n";
  append_info(out, info);
  const CaseTables t = case_tables(result);
  append_section(out, "Metrics", t.metrics);
  append_section(out, "Parameters", t.parameters);
  append_section(out, "Levels", t.levels);
  append_section(out, "Observed order", t.orders);
  if (!t.richardson.empty() || !t.richardson_notes.empty()) {
    out += "<h5>Richardson extrapolation and GCI</h5>\n";
    if (!t.richardson.empty()) append_table(out, t.richardson);
    if (!t.richardson_notes.empty()) {
      out += "<ul class=\"notes\">\n";
      for (const auto& note : t.richardson_notes) out += "<li>" + escape_xml(note) + "</li>\n";
      out += "</ul>\n";
    }
  }
  append_section(out, "Gates", t.gates);
  if (!t.skipped_gates.empty()) {
    out += "<p class=\"skipped\">Skipped gates (not evaluated):</p>\n<ul class=\"notes\">\n";
    for (const auto& s : t.skipped_gates) out += "<li>" + escape_xml(s) + "</li>\n";
    out += "</ul>\n";
  }
  if (const auto it = plots.cases.find(info.name); it != plots.cases.end() && !it->second.empty()) {
    out += "<h5>Plots</h5>\n<div class=\"plots\">\n";
    append_figures(out, it->second);
    out += "</div>\n";
  }
  out += "</section>\n";
}

std::string family_label(const std::string& f) { return f.empty() ? std::string("(no family)") : f; }
std::string group_label(const std::string& g) { return g.empty() ? std::string("(ungrouped)") : g; }

// Family, status and name filters, sticky at the top of the page (script: kFilterScript).
void append_filter_bar(std::string& out, const ValidationReport& report, const std::vector<CaseGroup>& groups) {
  const ReportTotals sum = totals(report);
  out += "<form class=\"filters\" id=\"filters\" onsubmit=\"return false\">\n"
         "<label>Family<select id=\"filter-family\"><option value=\"\">all</option>";
  for (std::size_t g = 0; g < groups.size(); ++g)
    if (g == 0 || groups[g].family != groups[g - 1].family)
      out += "<option value=\"" + escape_xml_attribute(groups[g].family) + "\">" +
             escape_xml(family_label(groups[g].family)) + "</option>";
  out += "</select></label>\n<label>Status<select id=\"filter-status\"><option value=\"\">all</option>"
         "<option value=\"fail\">failed (" + std::to_string(sum.cases - sum.cases_passed) +
         ")</option><option value=\"pass\">passed (" + std::to_string(sum.cases_passed) +
         ")</option><option value=\"skipped\">with skipped gates</option></select></label>\n"
         "<label>Case<input id=\"filter-name\" type=\"search\" placeholder=\"name contains\"></label>\n"
         "<span id=\"filter-count\"></span>\n</form>\n";
}

// Rows of a table that belong to cases (row_cases[r]: the case of row r): filterable by the page's filters.
void append_case_rows_table(std::string& out, const Table& table, const ValidationReport& report,
                            const std::vector<std::size_t>& row_cases) {
  std::vector<std::string> attributes;
  for (const std::size_t c : row_cases)
    attributes.push_back(" class=\"filterable\"" + case_filter_attributes(report.cases[c]));
  append_table(out, table, attributes);
}

// The first screen after the status: the overview figure, then failed gates and the closest
// calls, then skipped gates (overview.hpp defines the margins).
void append_at_a_glance(std::string& out, const ValidationReport& report, const std::vector<std::string>& case_ids) {
  constexpr std::size_t kClosestCalls = 12;
  const auto margins = gate_margins(report);
  out += "<section id=\"at-a-glance\">\n<h2>At a glance</h2>\n";
  out += "<figure class=\"overview\">\n" + overview_svg(report, margins, case_ids) +
         "<figcaption>Every evaluated gate. Left: observed against theoretical order (dashed: as predicted; "
         "bars: the accepted window). Right: headroom of bound gates, log10(bound / measured) (bounds that are "
         "not positive: the relative distance); outlined points lie beyond the axis. Red fails; hover for "
         "the gate, click for its case.</figcaption>\n</figure>\n";
  const auto attention = needs_attention(margins, kClosestCalls);
  std::size_t failed = 0;
  for (const auto& m : attention) failed += m.passed ? 0 : 1;
  out += "<h5>Failed gates (" + std::to_string(failed) + ") and the " +
         std::to_string(attention.size() - failed) + " closest calls</h5>\n";
  std::vector<std::size_t> row_cases;
  for (const auto& m : attention) row_cases.push_back(m.case_index);
  append_case_rows_table(out, attention_table(report, attention), report, row_cases);
  const Table skipped = skipped_gates_table(report);
  if (!skipped.empty()) {
    row_cases.clear();
    for (std::size_t c = 0; c < report.cases.size(); ++c)
      for (std::size_t k = 0; k < report.cases[c].skipped_gates.size(); ++k) row_cases.push_back(c);
    out += "<h5>Skipped gates (" + std::to_string(skipped.rows.size()) + ")</h5>\n";
    append_case_rows_table(out, skipped, report, row_cases);
  }
  out += "</section>\n";
}

}  // namespace

std::string render_html(const ValidationReport& report, const PlotManifest& plots) {
  const ReportTotals sum = totals(report);
  const bool passed = report.passed();
  const auto groups = group_cases(report);

  // Ids first: the table of contents links to them.
  IdMaker ids;
  std::vector<std::string> case_ids(report.cases.size());
  for (std::size_t i = 0; i < report.cases.size(); ++i)
    case_ids[i] = ids.make("case-", report.cases[i].info.name);
  std::vector<std::string> group_ids, family_ids;
  for (const auto& g : groups) {
    family_ids.push_back(ids.make("family-", g.family));
    group_ids.push_back(ids.make("group-", g.family + "-" + g.group));
  }

  std::string out;
  out.reserve(64 * 1024);
  out += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
         "<title>rodvv validation report \u2014 ";
  out += status_text(passed);
  out += "</title>\n<style>";
  out += kStyle;
  out += "</style>\n</head>\n<body>\n<h1>rodvv validation report</h1>\n";

  // Summary with totals.
  const char* cls = passed ? "pass" : "fail";
  out += std::string("<div class=\"summary ") + cls + "\">\n<div class=\"big " + cls + "\">" +
         status_text(passed) + "</div>\n";
  out += "<div class=\"stat\"><b>" + std::to_string(sum.cases_passed) + "</b> / " +
         std::to_string(sum.cases) + " cases passed</div>\n";
  out += "<div class=\"stat\"><b>" + std::to_string(sum.gates_passed) + "</b> / " +
         std::to_string(sum.gates) + " gates passed" +
         (sum.gates_skipped ? " (" + std::to_string(sum.gates_skipped) + " skipped)" : "") +
         "</div>\n";
  out += "<div class=\"stat\"><b>" + std::to_string(sum.levels_failed) + "</b> / " +
         std::to_string(sum.levels) + " levels failed</div>\n";
  out += "<div class=\"stat\">" + escape_xml(report.provenance.date_utc) + "<br>commit " +
         escape_xml(report.provenance.git_commit.substr(0, 12)) + "</div>\n</div>\n";
  if (!plots.unavailable_reason.empty())
    out += "<p class=\"note\">plots unavailable: " + escape_xml(plots.unavailable_reason) + "</p>\n";
  if (!passed) {
    out += "<p>Failing cases: ";
    bool first = true;
    for (std::size_t i = 0; i < report.cases.size(); ++i) {
      if (report.cases[i].passed()) continue;
      out += std::string(first ? "" : ", ") + "<a href=\"#" + escape_xml_attribute(case_ids[i]) +
             "\">" + escape_xml(report.cases[i].info.name) + "</a>";
      first = false;
    }
    out += "</p>\n";
  }

  append_filter_bar(out, report, groups);
  append_at_a_glance(out, report, case_ids);

  // Table of contents: family -> group -> case.
  out += "<nav class=\"toc\">\n<h2>Contents</h2>\n<ul>\n";
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const bool new_family = g == 0 || groups[g].family != groups[g - 1].family;
    if (new_family) {
      if (g != 0) out += "</ul></li>\n";
      out += "<li class=\"filter-container\"><a class=\"family\" href=\"#" + escape_xml_attribute(family_ids[g]) +
             "\">" + escape_xml(family_label(groups[g].family)) + "</a>\n<ul>\n";
    }
    out += "<li class=\"filter-container\"><a class=\"group\" href=\"#" + escape_xml_attribute(group_ids[g]) +
           "\">" + escape_xml(group_label(groups[g].group)) + "</a>\n<ul>\n";
    for (const std::size_t i : groups[g].cases) {
      const auto& c = report.cases[i];
      out += "<li class=\"filterable\"" + case_filter_attributes(c) + ">" + badge(c.passed()) + " <a href=\"#" +
             escape_xml_attribute(case_ids[i]) + "\">" + escape_xml(c.info.name) + "</a>" +
             (c.info.title.empty() ? "" : " \u2014 " + escape_xml(c.info.title)) + "</li>\n";
    }
    out += "</ul></li>\n";
  }
  if (!groups.empty()) out += "</ul></li>\n";
  out += "</ul>\n</nav>\n";

  out += "<h2>Summary</h2>\n";
  append_table(out, summary_table(report));
  out += "<h2>Provenance</h2>\n";
  append_table(out, provenance_table(report));

  // Family and group blocks: filter containers, hidden when the filters leave them no case.
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const bool new_family = g == 0 || groups[g].family != groups[g - 1].family;
    if (new_family) {
      if (g != 0) out += "</div>\n";
      out += "<div class=\"family-block filter-container\">\n<h2 id=\"" + escape_xml_attribute(family_ids[g]) +
             "\">" + escape_xml(family_label(groups[g].family)) + "</h2>\n";
    }
    out += "<div class=\"group-block filter-container\">\n<h3 id=\"" + escape_xml_attribute(group_ids[g]) + "\">" +
           escape_xml(group_label(groups[g].group)) + "</h3>\n";
    if (const auto it = plots.groups.find(groups[g].group);
        !groups[g].group.empty() && it != plots.groups.end() && !it->second.empty()) {
      out += "<div class=\"plots group-plots\">\n";
      append_figures(out, it->second);
      out += "</div>\n";
    }
    for (const std::size_t i : groups[g].cases) append_case(out, report.cases[i], case_ids[i], plots);
    out += "</div>\n";
  }
  if (!groups.empty()) out += "</div>\n";

  out += "<footer>Rendered from results.json (the canonical result format; full precision "
         "there and in results.csv).</footer>\n<script>";
  out += kFilterScript;
  out += "</script>\n</body>\n</html>\n";
  return out;
}

}  // namespace rodvv::reports
