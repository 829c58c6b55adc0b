# rotorcert_bench (conformance/bench/README.md): Google Benchmark over every op of every built-in
# implementation, the glm baselines and the roofline. Included from conformance/CMakeLists.txt.
find_package(hwy REQUIRED)  # its imported target is local to impls/rotor_simd's directory

set(rotorcert_bench_dir ${CMAKE_CURRENT_LIST_DIR})
add_executable(rotorcert_bench
  ${rotorcert_bench_dir}/main.cpp
  ${rotorcert_bench_dir}/options.cpp
  ${rotorcert_bench_dir}/machine.cpp
  ${rotorcert_bench_dir}/inputs.cpp
  ${rotorcert_bench_dir}/ops_bench.cpp
  ${rotorcert_bench_dir}/baselines.cpp
  ${rotorcert_bench_dir}/roofline.cpp
  ${rotorcert_bench_dir}/roofline_kernels.cpp
  ${rotorcert_bench_dir}/frame_job.cpp
  ${rotorcert_bench_dir}/vertex_kernels.cpp
  ${rotorcert_bench_dir}/frame_bench.cpp)
# foreach_target.h re-includes roofline_kernels.cpp and vertex_kernels.cpp as "bench/<file>".
target_include_directories(rotorcert_bench PRIVATE ${rotorcert_bench_dir}/..)
# rotorcert::skinning (render_check/skinning.cmake, defined after this file: resolved at generate
# time): the render check's PoseJob/SkinJob, which the frame benchmarks' guard compares against.
target_link_libraries(rotorcert_bench PRIVATE rotorcert::impls rotorcert::skinning benchmark::benchmark glm::glm hwy::hwy
                                              rotor_gen_kernels_interface)
target_compile_definitions(rotorcert_bench PRIVATE ROTORCERT_VERSION="${PROJECT_VERSION}"
                                                   ROTORCERT_BUILD_TYPE="${CMAKE_BUILD_TYPE}"
                                                   ROTORCERT_SHARED_DIR="${ROTORCERT_SHARED_DIR}")
rotorcert_warnings(rotorcert_bench)

# bench_smoke: a tiny run (two ops of two tables, the baselines, the roofline; sizes 1, 64 and a
# streaming 65536 over a few MiB; two frame benchmarks of the medium character) written as JSON, then check_bench_json.py validates the file's
# structure and counters. It asserts no speed: benchmarks are never timed unit tests.
find_package(Python3 COMPONENTS Interpreter)
if(Python3_Interpreter_FOUND)
  add_test(NAME bench_smoke
    COMMAND ${CMAKE_COMMAND}
      -DBENCH=$<TARGET_FILE:rotorcert_bench>
      -DPYTHON=${Python3_EXECUTABLE}
      -DCHECKER=${rotorcert_bench_dir}/check_bench_json.py
      -DOUT=${CMAKE_CURRENT_BINARY_DIR}/bench_smoke.json
      -P ${rotorcert_bench_dir}/bench_smoke.cmake)
  set_tests_properties(bench_smoke PROPERTIES LABELS bench TIMEOUT 300)
endif()

# The frame pipeline's FrameJob against the render check's PoseJob + SkinJob (VIS-1's strict
# bars) for every method on the built-in simple and medium characters. Not a timing test.
rotorcert_add_test(bench_test_frame_job
  ${rotorcert_bench_dir}/test_frame_job.cpp
  ${rotorcert_bench_dir}/frame_job.cpp
  ${rotorcert_bench_dir}/vertex_kernels.cpp)
target_include_directories(bench_test_frame_job PRIVATE ${rotorcert_bench_dir}/..)
target_link_libraries(bench_test_frame_job PRIVATE rotorcert::skinning rotorcert::impls nlohmann_json::nlohmann_json hwy::hwy)
target_compile_definitions(bench_test_frame_job PRIVATE ROTORCERT_SPEC_DIR="${PROJECT_SOURCE_DIR}/spec")
set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${CMAKE_CURRENT_BINARY_DIR}/bench_test_frame_job_labels.cmake)
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/bench_test_frame_job_labels.cmake
  "set_tests_properties(\${bench_test_frame_job_TESTS} PROPERTIES LABELS bench)\n")
