# rotorcert_add_certification(): certify a library's rotorcert plugin from the library's own build.
#
#   rotorcert_add_certification(<plugin-target>
#     [NAME <test-name>]           # default: rotorcert_certify_<plugin-target>
#     [LEVELS <level>...]          # levels that must be met (LEVEL-1); default: every level the
#                                  # plugin's tables claim
#     [SCALAR float|double|both]   # which tables (default both)
#     [ARGS <argument>...])        # more `rotorcert certify` options, e.g. --cases 64 --level Core
#
# Adds a ctest test that runs `rotorcert certify --plugin $<TARGET_FILE:plugin>` and fails (exit
# 1) when a required level is not met; the report (report.html, report.md, report.json) goes to
# <build dir>/rotorcert/<test-name>. The plugin is a MODULE or SHARED library exporting
# rotorcert_impl_entry (impl_abi.h, target rotorcert::abi).
include_guard(GLOBAL)

function(rotorcert_add_certification plugin)
  cmake_parse_arguments(ARG "" "NAME;SCALAR" "LEVELS;ARGS" ${ARGN})
  if(ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "rotorcert_add_certification: unknown arguments ${ARG_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT TARGET ${plugin})
    message(FATAL_ERROR "rotorcert_add_certification: ${plugin} is not a target")
  endif()
  if(NOT TARGET rotorcert::rotorcert)
    message(FATAL_ERROR "rotorcert_add_certification: no rotorcert::rotorcert (find_package(rotorcert) first)")
  endif()
  if(NOT ARG_NAME)
    set(ARG_NAME rotorcert_certify_${plugin})
  endif()
  if(NOT ARG_SCALAR)
    set(ARG_SCALAR both)
  endif()
  set(require --require-claimed-levels)
  if(ARG_LEVELS)
    set(require)
    foreach(level IN LISTS ARG_LEVELS)
      list(APPEND require --require-level ${level})
    endforeach()
  endif()
  add_test(NAME ${ARG_NAME}
    COMMAND rotorcert::rotorcert certify --plugin $<TARGET_FILE:${plugin}> --scalar ${ARG_SCALAR} ${require}
            --out ${CMAKE_CURRENT_BINARY_DIR}/rotorcert/${ARG_NAME} -q ${ARG_ARGS})
  set_tests_properties(${ARG_NAME} PROPERTIES LABELS rotorcert)
endfunction()
