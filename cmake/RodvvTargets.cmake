# rodvv_add_library(<name> SOURCES ... DEPENDS ...)
# One folder = one library target rodvv_<name>, aliased rodvv::<name>, with public headers in
# <folder>/include/rodvv/<name>/ and warnings/sanitizers applied per target (never globally).
function(rodvv_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                           -Wno-sign-conversion)
endfunction()

function(rodvv_sanitize target)
  if(RODVV_SANITIZE)
    target_compile_options(${target} PRIVATE -fsanitize=address,undefined -fno-omit-frame-pointer
                                             -fno-sanitize-recover=undefined)
    target_link_options(${target} PUBLIC -fsanitize=address,undefined)
  endif()
endfunction()

function(rodvv_add_library name)
  cmake_parse_arguments(ARG "EXPORT" "" "SOURCES;PUBLIC_DEPENDS;PRIVATE_DEPENDS" ${ARGN})
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
  if(ARG_EXPORT)
    install(TARGETS rodvv_${name} EXPORT rodvvTargets
            ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
            LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
    install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  endif()
endfunction()
