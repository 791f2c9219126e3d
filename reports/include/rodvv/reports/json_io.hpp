#pragma once
// results.json: the canonical, lossless serialisation of a ValidationReport, and merging of
// reports written by separate runs (`rodvv run CASE --json part.json`, `rodvv report --from DIR`).
//
// Absent optionals and non-finite doubles are written as null, never NaN or Infinity. Reading a
// null where a plain double is required gives a quiet NaN (renderers print "n/a"); reading a null
// parameter bound gives -inf (min) / +inf (max), an unbounded side. Enumerations are written as
// the strings of harness::to_string. Unknown fields are ignored, so newer writers stay readable.
// Malformed input throws rodvv::InputError (parameter "results file") whose message names the
// source and the field path, e.g.
//   part.json: field 'cases[3].levels[0].metrics': expected an object, got a string
#include <filesystem>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "rodvv/reports/report_document.hpp"

namespace rodvv::reports {

nlohmann::json to_json(const ValidationReport& report);
nlohmann::json to_json(const harness::SweepResult& result);

// `source_name` (a file path or "<stdin>") prefixes every error message and becomes
// report.source.
ValidationReport report_from_json(const nlohmann::json& document, std::string_view source_name);

// The text of a results file (what read_report_file reads from disk); a fuzz target's entry point.
ValidationReport report_from_json_text(std::string_view text, std::string_view source_name);
ValidationReport read_report_file(const std::filesystem::path& path);
// Pretty-printed with a 2-space indent; doubles are written in shortest round-trip form, so
// reading the file back gives bit-identical values.
void write_report_file(const std::filesystem::path& path, const ValidationReport& report);

// Concatenates the cases of `reports` in order. The result keeps the first report's provenance
// and lists every input's source (or, for an input that is itself a merge, its merged_from) in
// merged_from. A case name present twice throws InputError naming the case and both sources.
ValidationReport merge_reports(std::vector<ValidationReport> reports);

// Every regular file `*.json` directly in `dir`, sorted by name, read with read_report_file.
// Throws InputError if `dir` is not a directory or holds no *.json file. Note: a results.json
// written earlier into the same directory is read too.
std::vector<ValidationReport> read_reports_from_directory(const std::filesystem::path& dir);

}  // namespace rodvv::reports
