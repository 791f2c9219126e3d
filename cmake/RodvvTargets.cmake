# rodvv_add_library(<name> SOURCES ... DEPENDS ...)
# One folder = one library target rodvv_<name>, aliased rodvv::<name>, with public headers in
# <folder>/include/rodvv/<name>/ and warnings/sanitizers applied per target (never globally).
function(rodvv_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                           -Wno-sign-conversion)
endfunction()

# UndefinedBehaviorSanitizer without five checks that double the compile time of the Eigen-heavy files
# (superhelix/dynamics.cpp: 57 s with them, 28 s without, 15 s in release) and that AddressSanitizer
# already covers where it matters: null and alignment (a null or misaligned access is ASan's SEGV
# report, and x86 tolerates misalignment), pointer-overflow and object-size (the out-of-bounds
# access that follows is ASan's), vptr (no polymorphic type is downcast here). The arithmetic checks
# (signed overflow, shifts, division by zero, float-to-int overflow), bounds, bool, enum, return and
# unreachable stay.
set(RODVV_UBSAN_SKIPPED_CHECKS alignment,null,pointer-overflow,object-size,vptr)

function(rodvv_sanitize target)
  if(RODVV_SANITIZE)
    target_compile_options(${target} PRIVATE -fsanitize=address,undefined
                                             -fno-sanitize=${RODVV_UBSAN_SKIPPED_CHECKS}
                                             -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
    target_link_options(${target} PUBLIC -fsanitize=address,undefined)
  endif()
endfunction()

# Precompiled headers: the standard library and Eigen headers that almost every translation unit
# parses (about 1 s of a 2 s harness case file; measured with -fsyntax-only), parsed once per
# target instead of once per file. RODVV_PRECOMPILED_HEADERS=OFF builds without them, which is
# how to check that every file includes what it uses.
option(RODVV_PRECOMPILED_HEADERS "Precompile the common standard-library and Eigen headers" ON)
set(RODVV_PRECOMPILED_HEADER_LIST
    <algorithm> <array> <cmath> <functional> <map> <memory> <optional> <stdexcept> <string>
    <utility> <vector> <Eigen/Dense>)

# rodvv_precompile(<target> [<extra header>...]): the common list plus the target's own heavy
# headers (nlohmann/json, GoogleTest).
function(rodvv_precompile target)
  if(RODVV_PRECOMPILED_HEADERS)
    target_precompile_headers(${target} PRIVATE ${RODVV_PRECOMPILED_HEADER_LIST} ${ARGN})
  endif()
endfunction()

function(rodvv_add_library name)
  cmake_parse_arguments(ARG "EXPORT" "" "SOURCES;PUBLIC_DEPENDS;PRIVATE_DEPENDS;PRECOMPILE" ${ARGN})
  add_library(rodvv_${name} ${ARG_SOURCES})
  add_library(rodvv::${name} ALIAS rodvv_${name})
  set_target_properties(rodvv_${name} PROPERTIES EXPORT_NAME ${name} OUTPUT_NAME rodvv_${name}
                                                 POSITION_INDEPENDENT_CODE ON)
  target_compile_features(rodvv_${name} PUBLIC cxx_std_20)
  target_include_directories(rodvv_${name} PUBLIC
      $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
      $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_link_libraries(rodvv_${name} PUBLIC ${ARG_PUBLIC_DEPENDS} PRIVATE ${ARG_PRIVATE_DEPENDS})
  rodvv_warnings(rodvv_${name})
  rodvv_sanitize(rodvv_${name})
  rodvv_precompile(rodvv_${name} ${ARG_PRECOMPILE})
  if(ARG_EXPORT)
    install(TARGETS rodvv_${name} EXPORT rodvvTargets
            ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
            LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
    install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  endif()
endfunction()
