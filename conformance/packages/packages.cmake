# The rotorcert-vectors packages (conformance/packages/python and node): a library maintainer
# certifies from their own test suite. Included from conformance/CMakeLists.txt after
# find_package(Python3). Each test installs this build into a scratch prefix (cmake --install: the
# tool and share/rotorcert/packages), installs its package from there into a scratch environment
# (offline), runs the package's unit tests and its example project through pytest / node --test
# with the installed tool's check, and plants defects that must fail (test_packages.py says what
# each run must show). Exit 77, a skip saying why, where python3-venv, pip, pytest >= 7 (Debian:
# python3-pytest), node >= 18 or npm is missing.
if(Python3_Interpreter_FOUND)
  foreach(language python node)
    set(work ${CMAKE_CURRENT_BINARY_DIR}/package_${language})
    set(prefix ${CMAKE_CURRENT_BINARY_DIR}/package_${language}_prefix)
    set(test_name conformance_package_python_pytest)
    if(language STREQUAL "node")
      set(test_name conformance_package_node_test)
    endif()
    add_test(NAME ${test_name}
      COMMAND sh -c "rm -rf '${prefix}' && '${CMAKE_COMMAND}' --install '${CMAKE_BINARY_DIR}' --prefix '${prefix}' >/dev/null && exec '${Python3_EXECUTABLE}' '${CMAKE_CURRENT_LIST_DIR}/test_packages.py' ${language} --rotorcert '${prefix}/bin/rotorcert' --packages '${prefix}/share/rotorcert/packages' --work '${work}'")
    set_tests_properties(${test_name} PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 300 LABELS "package;install")
  endforeach()
endif()
