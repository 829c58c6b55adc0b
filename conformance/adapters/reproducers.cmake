# Reproducers of known third-party defects (README.md, "Reproducers"): one file per library and
# clause, conformance/adapters/<adapter>/reproducers/<CLAUSE>.<cpp|py|js|rs>, each calling the library
# directly. Every file becomes the ctest reproducer_<adapter>_<CLAUSE> (label `reproducer`): exit 0
# = the defect is shown (PASS), 1 = it is not shown any more (FAIL: the library changed, update the
# known defects), 77 = the library cannot be loaded here (SKIP). Included by CMakeLists.txt of this
# directory, after it looked for CQRlib, assimp and Bullet.

# C++: the library behind each adapter's reproducers, and whether it was found. glm and Eigen3 are
# required by the top-level CMakeLists.txt; CQRlib, assimp and Bullet are optional (CMakeLists.txt
# above). Bullet's reproducers build against Debian's default build (bullet.pc, btScalar = float).
set(_repro_cxx_libs_glm glm::glm)
set(_repro_cxx_libs_eigen Eigen3::Eigen)
set(_repro_cxx_libs_cqrlib CQRlib::CQRlib)
set(_repro_cxx_libs_assimp assimp::assimp)
set(_repro_cxx_libs_bullet Bullet::bullet)
# Further builds of a library that its reproducers also run against, each a ctest
# reproducer_<adapter>_<CLAUSE>_<variant>: Debian ships Bullet twice, and the plugin certifies both
# (bullet.pc, btScalar = float, above; bullet-float64.pc, -DBT_USE_DOUBLE_PRECISION, here). Each
# reproducer picks the suite's worst input of the build it was compiled for.
set(_repro_cxx_variants_bullet float64)
set(_repro_cxx_libs_bullet_float64 Bullet::bullet_float64)

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

# Rust: each NAME/reproducers/CLAUSE.rs is an example target of the adapter's Cargo crate (listed
# in NAME/Cargo.toml), built with cargo against the crate version its committed Cargo.lock pins, in
# the target directory scripts/setup-adapters built the adapter in ($env/NAME/target), --frozen: no
# fetching, no re-resolution at test time. cargo missing at configure time, or the adapter's
# environment not installed (status.json), is a skip (77); a reproducer that does not build is a
# failure (2), never a skip.
find_program(ROTORCERT_CARGO_EXECUTABLE NAMES cargo DOC "cargo, for the Rust reproducers")
mark_as_advanced(ROTORCERT_CARGO_EXECUTABLE)
# sh -c SCRIPT sh DEFAULT_ENV ADAPTER CARGO_TOML EXAMPLE CARGO
set(_repro_run_rs [=[
env="${ROTORCERT_ADAPTERS_ENV:-$1}"
if [ ! -x "$5" ]
then
  echo "reproducer skipped: cargo was not found at configure time"
  exit 77
fi
if ! grep -q '"installed": true' "$env/$2/status.json" 2>/dev/null
then
  echo "reproducer skipped: $2 is not installed in $env (run scripts/setup-adapters; $env/$2/status.json)"
  exit 77
fi
if ! "$5" build --quiet --release --frozen --manifest-path "$3" --target-dir "$env/$2/target" --example "$4"
then
  echo "reproducer FAILED: cargo could not build the example $4 of $3"
  exit 2
fi
exec "$env/$2/target/release/examples/$4"]=])

file(GLOB _repro_files CONFIGURE_DEPENDS
  ${CMAKE_CURRENT_SOURCE_DIR}/*/reproducers/*.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/*/reproducers/*.py
  ${CMAKE_CURRENT_SOURCE_DIR}/*/reproducers/*.js
  ${CMAKE_CURRENT_SOURCE_DIR}/*/reproducers/*.rs)
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
      foreach(_variant IN LISTS _repro_cxx_variants_${_adapter})
        set(_vname ${_name}_${_variant})
        add_executable(${_vname} ${_file})
        target_link_libraries(${_vname} PRIVATE ${_repro_cxx_libs_${_adapter}_${_variant}})
        set_target_properties(${_vname} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/reproducers
                                                   OUTPUT_NAME ${_adapter}_${_clause}_${_variant})
        rotorcert_warnings(${_vname})
        add_test(NAME ${_vname} COMMAND ${_vname})
        set_tests_properties(${_vname} PROPERTIES LABELS reproducer SKIP_RETURN_CODE 77 TIMEOUT 120)
      endforeach()
    endif()
  elseif(_ext STREQUAL ".rs")
    add_test(NAME ${_name}
      COMMAND sh -c "${_repro_run_rs}" sh "${_repro_env_default}" ${_adapter} ${_dir}/Cargo.toml ${_clause}
              "${ROTORCERT_CARGO_EXECUTABLE}")
    set_tests_properties(${_name} PROPERTIES FIXTURES_REQUIRED adapters_env)
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
