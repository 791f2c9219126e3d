#pragma once
// junit.xml for CI dashboards: one <testsuite> per case, one <testcase> per gate (a <failure>
// when it failed), one extra failing <testcase> per level that threw (LevelResult.failure) and
// one <skipped/> <testcase> per entry of SweepResult::skipped_gates.
#include <string>

#include "rodvv/reports/report_document.hpp"

namespace rodvv::reports {

std::string render_junit(const ValidationReport& report);

}  // namespace rodvv::reports
