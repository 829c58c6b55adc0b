# The render check as one call and the `rotorcert render` command (spec VIS-1..3):
# library rotorcert::render_check (include/rotorcert/render/render_check.hpp) on top of the
# skinning and renderer libraries, and its tests (tests/test_vis_*.cpp, targets
# render_check_test_vis_* created by CMakeLists.txt's glob).
add_library(rotorcert_render_check STATIC src/render_check.cpp)
add_library(rotorcert::render_check ALIAS rotorcert_render_check)
target_include_directories(rotorcert_render_check PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/include)
# certify: the known defects (impls/*/expected_failures.json) that decide what a method is
# expected to do, write_atomically, and the spec's clause levels.
target_link_libraries(rotorcert_render_check PUBLIC rotorcert::skinning rotorcert_render rotorcert::certify
  nlohmann_json::nlohmann_json)
target_compile_definitions(rotorcert_render_check PRIVATE ROTORCERT_VERSION="${PROJECT_VERSION}")
rotorcert_warnings(rotorcert_render_check)

# `rotorcert render`: the subcommand's source lives with the other commands (conformance/src), but
# the tool's target is defined before render_check/, so the source and the library are added here.
target_sources(rotorcert PRIVATE ${PROJECT_SOURCE_DIR}/conformance/src/cmd_render.cpp)
target_link_libraries(rotorcert PRIVATE rotorcert::render_check)

file(GLOB render_check_vis_tests CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/tests/test_vis_*.cpp)
foreach(src IN LISTS render_check_vis_tests)
  get_filename_component(stem ${src} NAME_WE)
  target_link_libraries(render_check_${stem} PRIVATE rotorcert::render_check)
  target_compile_definitions(render_check_${stem} PRIVATE ROTORCERT_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    ROTORCERT_BINARY="$<TARGET_FILE:rotorcert>")
  add_dependencies(render_check_${stem} rotorcert)
endforeach()
