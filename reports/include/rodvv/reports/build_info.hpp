#pragma once
// Facts fixed when rodvv was built, for the provenance block of every report. Generated sources:
// build_info.cpp (configure time: version, compiler, flags) and git_revision.cpp (re-checked on
// every build by reports/git_revision.cmake).
#include <string_view>

namespace rodvv::reports {

struct BuildInfo {
  std::string_view version;           // rodvv project version, "0.1.0"
  std::string_view compiler_id;       // CMAKE_CXX_COMPILER_ID, "GNU"
  std::string_view compiler_version;  // "12.2.0"
  std::string_view build_type;        // "Release"
  std::string_view compile_flags;     // CMAKE_CXX_FLAGS + CMAKE_CXX_FLAGS_<CONFIG> (+ sanitizers)
  std::string_view git_commit;        // 40 hex digits [+ "-dirty"], or "unknown"
};

BuildInfo build_info();

namespace detail {
std::string_view git_revision();  // defined in the generated git_revision.cpp
}  // namespace detail

}  // namespace rodvv::reports
