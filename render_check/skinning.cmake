# Posing and skinning the characters with each implementation and with the MPFR reference, and
# the vertex error between them (VIS-1): library rotorcert::skinning and its tests
# (tests/test_skin_*.cpp, targets render_check_test_skin_* created by CMakeLists.txt's glob).
add_library(rotorcert_skinning STATIC
  src/method.cpp
  src/pose_job.cpp
  src/skin_job.cpp
  src/reference_pose.cpp
  src/vertex_error.cpp)
add_library(rotorcert::skinning ALIAS rotorcert_skinning)
target_include_directories(rotorcert_skinning PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/include)
target_link_libraries(rotorcert_skinning PUBLIC rotorcert::gltf rotorcert::impls rotorcert::reference)
rotorcert_warnings(rotorcert_skinning)

file(GLOB render_check_skin_tests CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/tests/test_skin_*.cpp)
foreach(src IN LISTS render_check_skin_tests)
  get_filename_component(stem ${src} NAME_WE)
  target_link_libraries(render_check_${stem} PRIVATE rotorcert::skinning)
  # impls/*/expected_failures.json tell which tables are known to fail a clause a method uses.
  target_compile_definitions(render_check_${stem} PRIVATE ROTORCERT_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
endforeach()
