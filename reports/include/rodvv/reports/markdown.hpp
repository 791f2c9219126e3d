#pragma once
// report.md: the human-readable report as GitHub-flavoured Markdown (summary, then per case the
// description, parameters, levels, observed orders, Richardson/GCI and gates).
#include <string>

#include "rodvv/reports/report_document.hpp"

namespace rodvv::reports {

std::string render_markdown(const ValidationReport& report);

}  // namespace rodvv::reports
