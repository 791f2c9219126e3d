# cmake -P script run on every build (see reports/CMakeLists.txt):
#   -DGIT_EXECUTABLE=... -DSOURCE_DIR=... -DTEMPLATE=git_revision.cpp.in -DOUTPUT=git_revision.cpp
# Writes the commit of SOURCE_DIR, with "-dirty" when `git status --porcelain` lists changes,
# or "unknown" without git or a repository. configure_file leaves OUTPUT untouched when the
# text is unchanged, so an unchanged revision triggers no recompilation.
set(RODVV_GIT_COMMIT "unknown")
if(GIT_EXECUTABLE AND EXISTS "${SOURCE_DIR}/.git")
  execute_process(COMMAND "${GIT_EXECUTABLE}" rev-parse HEAD
                  WORKING_DIRECTORY "${SOURCE_DIR}"
                  RESULT_VARIABLE _head_result OUTPUT_VARIABLE _head
                  ERROR_QUIET OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(_head_result EQUAL 0 AND _head MATCHES "^[0-9a-f]+$")
    set(RODVV_GIT_COMMIT "${_head}")
    execute_process(COMMAND "${GIT_EXECUTABLE}" status --porcelain
                    WORKING_DIRECTORY "${SOURCE_DIR}"
                    RESULT_VARIABLE _status_result OUTPUT_VARIABLE _status
                    ERROR_QUIET OUTPUT_STRIP_TRAILING_WHITESPACE)
    if(NOT _status_result EQUAL 0)
      set(RODVV_GIT_COMMIT "${_head}-unknown-status")
    elseif(NOT _status STREQUAL "")
      set(RODVV_GIT_COMMIT "${_head}-dirty")
    endif()
  endif()
endif()
configure_file("${TEMPLATE}" "${OUTPUT}" @ONLY)
