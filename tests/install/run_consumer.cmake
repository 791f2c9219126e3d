# cmake -P script: install the build tree, configure/build the consumer against it, run it.
file(REMOVE_RECURSE "${WORK_DIR}")
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "command failed (${code}): ${ARGN}\n${out}\n${err}")
  endif()
  message(STATUS "${out}")
endfunction()
run(${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${WORK_DIR}/prefix")
run(${CMAKE_COMMAND} -S "${CONSUMER_SOURCE}" -B "${WORK_DIR}/build" -G "${GENERATOR}"
    "-DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix" "-DCMAKE_BUILD_TYPE=${BUILD_TYPE}")
run(${CMAKE_COMMAND} --build "${WORK_DIR}/build")
run("${WORK_DIR}/build/consumer")
# The installed CTest function: the consumer's two rodvv cases pass (labels rodvv and their family),
# the one at a bad parameter fails, and the per-case JSON merges into one report.
run(${CMAKE_CTEST_COMMAND} --test-dir "${WORK_DIR}/build" -L rodvv --output-on-failure)
run(${CMAKE_CTEST_COMMAND} --test-dir "${WORK_DIR}/build" -L elastica -N)
execute_process(COMMAND ${CMAKE_CTEST_COMMAND} --test-dir "${WORK_DIR}/build" -L must_fail
                RESULT_VARIABLE code OUTPUT_QUIET ERROR_QUIET)
if(code EQUAL 0)
  message(FATAL_ERROR "the rodvv case at a bad parameter passed as a CTest test")
endif()
run("${WORK_DIR}/prefix/bin/rodvv" report --from "${WORK_DIR}/build/rodvv-results" --out "${WORK_DIR}/report"
    --no-plots)
