#pragma once
// results.csv: one row per (case, level, metric) for spreadsheets and pandas.
//   case,family,level,h,metric,kind,computed,reference,error,wall_seconds
// RFC 4180 quoting; doubles in shortest round-trip form (full precision); an absent or
// non-finite value is an empty field (read as missing by pandas and spreadsheets).
#include <string>

#include "rodvv/reports/report_document.hpp"

namespace rodvv::reports {

std::string render_csv(const ValidationReport& report);

}  // namespace rodvv::reports
