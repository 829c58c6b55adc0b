# ctest bench_smoke (bench.cmake): runs rotorcert_bench on a tiny configuration (with two frame
# benchmarks and their frame_pose twins on the medium character), then checks the JSON it wrote.
# Variables: BENCH, PYTHON, CHECKER, OUT.
file(REMOVE ${OUT})
execute_process(
  COMMAND ${BENCH}
    "--benchmark_filter=^((op/(slerp|blend_qlb)/rotor_simd/float|op/(dq_sclerp|skin_dual_quaternion)/dq/double|baseline/glm_(slerp|mix)/float|roofline)/|frame(_pose)?/medium/(rotor_simd/float/LBS|dq/double/DQS)$)"
    --sizes=1,64,65536 --stream-mib=8 --benchmark_min_time=0.001
    --benchmark_out=${OUT} --benchmark_out_format=json
  RESULT_VARIABLE bench_rc)
if(NOT bench_rc EQUAL 0)
  message(FATAL_ERROR "rotorcert_bench failed: ${bench_rc}")
endif()
execute_process(
  COMMAND ${PYTHON} ${CHECKER} ${OUT}
    --expect op/slerp/rotor_simd/float/ --expect op/blend_qlb/rotor_simd/float/
    --expect op/dq_sclerp/dq/double/ --expect op/skin_dual_quaternion/dq/double/
    --expect baseline/glm_slerp/float/ --expect baseline/glm_mix/float/
    --expect roofline/peak_fma/float --expect roofline/peak_fma/double
    --expect roofline/bandwidth/read --expect roofline/bandwidth/triad
    --expect frame/medium/rotor_simd/float/LBS --expect frame/medium/dq/double/DQS
    --expect frame_pose/medium/rotor_simd/float/LBS --expect frame_pose/medium/dq/double/DQS
    --sizes 1,64,65536
  RESULT_VARIABLE check_rc)
if(NOT check_rc EQUAL 0)
  message(FATAL_ERROR "check_bench_json.py rejected ${OUT}")
endif()
