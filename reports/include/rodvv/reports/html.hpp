#pragma once
// index.html: one self-contained page (inline CSS, no scripts, no external assets other than
// the plot images under plots/). Summary with totals, a table of contents grouped by family then
// group, each group's overlay plots, and per case the Markdown content plus its plots.
#include <string>

#include "rodvv/reports/plot_manifest.hpp"
#include "rodvv/reports/report_document.hpp"

namespace rodvv::reports {

std::string render_html(const ValidationReport& report, const PlotManifest& plots);

}  // namespace rodvv::reports
