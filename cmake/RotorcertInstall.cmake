# `cmake --install` and the Debian package (CPack): the rotorcert tool and everything it reads at
# run time, laid out as conformance/include/rotorcert/spec/data_layout.hpp expects, so that the
# installed tool finds its files relative to itself and never reads the source tree:
#   bin/rotorcert, libexec/rotorcert/rotorcert_bench,
#   lib/rotorcert/{mutants,adapter_plugins}/*.so (installed where they are built),
#   share/rotorcert/{spec,impls/NAME/expected_failures.json,mutants/mutants.json,adapters},
#   include/rotorcert/ (the ABI and the reference), lib/cmake/rotorcert/ (the package).
# Fixed relative directories (not GNUInstallDirs' multiarch lib/): the tool computes them.
include(CMakePackageConfigHelpers)

set(ROTORCERT_INSTALL_CMAKEDIR lib/cmake/rotorcert)

# The exported targets: rotorcert::rotorcert, rotorcert::abi, rotorcert::reference.
set_target_properties(rotorcert_impl_interface PROPERTIES EXPORT_NAME abi)
set_target_properties(rotorcert_reference PROPERTIES EXPORT_NAME reference)
install(TARGETS rotorcert EXPORT rotorcertTargets RUNTIME DESTINATION bin COMPONENT tool)
install(TARGETS rotorcert_impl_interface rotorcert_reference EXPORT rotorcertTargets COMPONENT tool)
install(TARGETS rotorcert_bench RUNTIME DESTINATION libexec/rotorcert COMPONENT tool)

# Headers: the C ABI with its C++ helpers for writing a plugin, and the reference algebra.
install(FILES
    ${PROJECT_SOURCE_DIR}/impls/include/rotorcert/impl_abi.h
    ${PROJECT_SOURCE_DIR}/impls/include/rotorcert/abi_op_list.h
    ${PROJECT_SOURCE_DIR}/impls/include/rotorcert/op_id.hpp
    ${PROJECT_SOURCE_DIR}/impls/include/rotorcert/impl.hpp
    ${PROJECT_SOURCE_DIR}/impls/include/rotorcert/impl_table.hpp
  DESTINATION include/rotorcert COMPONENT tool)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/impls/include/rotorcert/runtime DESTINATION include/rotorcert COMPONENT tool)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/reference/include/rotorcert/reference DESTINATION include/rotorcert COMPONENT tool)

# What the tool reads at run time.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/spec/ DESTINATION share/rotorcert/spec COMPONENT tool)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/impls/ DESTINATION share/rotorcert/impls COMPONENT tool
  FILES_MATCHING PATTERN "expected_failures.json")
install(FILES ${PROJECT_SOURCE_DIR}/conformance/mutants/mutants.json DESTINATION share/rotorcert/mutants COMPONENT tool)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/conformance/adapters/ DESTINATION share/rotorcert/adapters COMPONENT tool
  PATTERN "CMakeLists.txt" EXCLUDE PATTERN "*.cmake" EXCLUDE PATTERN "__pycache__" EXCLUDE PATTERN "node_modules" EXCLUDE)
# The adapters' environments for `rotorcert thirdparty` (into ~/.cache/rotorcert/adapters).
install(PROGRAMS ${PROJECT_SOURCE_DIR}/scripts/setup-adapters DESTINATION share/rotorcert COMPONENT tool)
# The Python and JavaScript packages a library's own test suite certifies with (pytest plugin,
# node:test helper): `pip install PREFIX/share/rotorcert/packages/python`, `npm install .../node`.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/conformance/packages/python ${PROJECT_SOURCE_DIR}/conformance/packages/node
  DESTINATION share/rotorcert/packages COMPONENT tool
  PATTERN "__pycache__" EXCLUDE PATTERN "node_modules" EXCLUDE PATTERN ".pytest_cache" EXCLUDE PATTERN "*.egg-info" EXCLUDE)

# The CMake package.
install(EXPORT rotorcertTargets NAMESPACE rotorcert:: DESTINATION ${ROTORCERT_INSTALL_CMAKEDIR} COMPONENT tool)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/rotorcertConfig.cmake.in
  ${PROJECT_BINARY_DIR}/rotorcertConfig.cmake INSTALL_DESTINATION ${ROTORCERT_INSTALL_CMAKEDIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/rotorcertConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES
    ${PROJECT_BINARY_DIR}/rotorcertConfig.cmake
    ${PROJECT_BINARY_DIR}/rotorcertConfigVersion.cmake
    ${PROJECT_SOURCE_DIR}/cmake/RotorcertCertification.cmake
  DESTINATION ${ROTORCERT_INSTALL_CMAKEDIR} COMPONENT tool)

# The Debian package of the tool: `cpack -G DEB` in the build directory.
set(CPACK_PACKAGE_NAME rotorcert)
set(CPACK_PACKAGE_VENDOR "rotorcert")
set(CPACK_PACKAGE_CONTACT "rotorcert maintainers <rotorcert@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
# Run-time libraries from the Debian packages the build used.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_COMPONENTS_ALL tool)
set(CPACK_DEB_COMPONENT_INSTALL OFF)
include(CPack)
