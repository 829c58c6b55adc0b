# Reproducers of known third-party defects (README.md, "Reproducers"): one file per library and
# clause, conformance/adapters/<adapter>/reproducers/<CLAUSE>.<cpp|py|js>, each calling the library
# directly. Every file becomes the ctest reproducer_<adapter>_<CLAUSE> (label `reproducer`): exit 0
# = the defect is shown (PASS), 1 = it is not shown any more (FAIL: the library changed, update the
# known defects), 77 = the library cannot be loaded here (SKIP). Included by CMakeLists.txt of this
# directory, after find_package(CQRlib).

# C++: the library behind each adapter's reproducers, and whether it was found. glm and Eigen3 are
# required by the top-level CMakeLists.txt; CQRlib is optional (CQRlib_FOUND above).
set(_repro_cxx_libs_glm glm::glm)
set(_repro_cxx_libs_eigen Eigen3::Eigen)
set(_repro_cxx_libs_cqrlib CQRlib::CQRlib)

# Python and JavaScript run from the environments of scripts/setup-adapters: $ROTORCERT_ADAPTERS_ENV
# at test time, else build/adapters of this checkout (as `rotorcert thirdparty`). A missing
# interpreter or package directory is a skip (77), said on stdout.
set(_repro_env_default "${PROJECT_SOURCE_DIR}/build/adapters")
find_program(ROTORCERT_NODE_EXECUTABLE NAMES node nodejs DOC "Node.js, for the JavaScript reproducers")
mark_as_advanced(ROTORCERT_NODE_EXECUTABLE)
# sh -c SCRIPT sh DEFAULT_ENV ADAPTER FILE [NODE]
# (The scripts use newlines, not semicolons: a semicolon would split a CMake list.)
set(_repro_run_py [=[
env="${ROTORCERT_ADAPTERS_ENV:-$1}"
py="$env/$2/venv/bin/python"
if [ ! -x "$py" ]
then
  echo "reproducer skipped: $py not found (run scripts/setup-adapters)"
  exit 77
fi
exec "$py" "$3"]=])
set(_repro_run_js [=[
env="${ROTORCERT_ADAPTERS_ENV:-$1}"
mods="$env/$2/node_modules"
if [ ! -x "$4" ]
then
  echo "reproducer skipped: node was not found at configure time"
  exit 77
fi
if [ ! -d "$mods" ]
then
  echo "reproducer skipped: $mods not found (run scripts/setup-adapters)"
  exit 77
fi
NODE_PATH="$mods" exec "$4" "$3"]=])
set(_repro_skip [=[
echo "reproducer skipped: $1"
exit 77]=])

file(GLOB _repro_files CONFIGURE_DEPENDS
  ${CMAKE_CURRENT_SOURCE_DIR}/*/reproducers/*.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/*/reproducers/*.py
  ${CMAKE_CURRENT_SOURCE_DIR}/*/reproducers/*.js)
list(SORT _repro_files)
foreach(_file IN LISTS _repro_files)
  get_filename_component(_dir ${_file} DIRECTORY)
  get_filename_component(_dir ${_dir} DIRECTORY)
  get_filename_component(_adapter ${_dir} NAME)
  get_filename_component(_clause ${_file} NAME_WLE)
  get_filename_component(_ext ${_file} LAST_EXT)
  set(_name reproducer_${_adapter}_${_clause})

  if(_ext STREQUAL ".cpp")
    set(_libs ${_repro_cxx_libs_${_adapter}})
    set(_missing "")
    if(NOT _libs)
      set(_missing "no library is known for adapter ${_adapter} (conformance/adapters/reproducers.cmake)")
    endif()
    foreach(_lib IN LISTS _libs)
      if(NOT TARGET ${_lib})
        set(_missing "${_lib} was not found at configure time")
      endif()
    endforeach()
    if(_missing)
      add_test(NAME ${_name} COMMAND sh -c "${_repro_skip}" sh "${_missing}")
    else()
      # One plain C++20 translation unit against the library's own headers and the project's warning
      # set (-Werror with ROTORCERT_WERROR): the reproducers compile warning-free with gcc 12 and clang 14.
      add_executable(${_name} ${_file})
      target_link_libraries(${_name} PRIVATE ${_libs})
      set_target_properties(${_name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/reproducers
                                                OUTPUT_NAME ${_adapter}_${_clause})
      rotorcert_warnings(${_name})
      add_test(NAME ${_name} COMMAND ${_name})
    endif()
  elseif(_ext STREQUAL ".py")
    add_test(NAME ${_name} COMMAND sh -c "${_repro_run_py}" sh "${_repro_env_default}" ${_adapter} ${_file})
    set_tests_properties(${_name} PROPERTIES FIXTURES_REQUIRED adapters_env)
  else()
    add_test(NAME ${_name}
      COMMAND sh -c "${_repro_run_js}" sh "${_repro_env_default}" ${_adapter} ${_file} "${ROTORCERT_NODE_EXECUTABLE}")
    set_tests_properties(${_name} PROPERTIES FIXTURES_REQUIRED adapters_env)
  endif()
  set_tests_properties(${_name} PROPERTIES LABELS reproducer SKIP_RETURN_CODE 77 TIMEOUT 120)
endforeach()
