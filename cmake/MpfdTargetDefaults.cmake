# mpfd_target_defaults(<target>): warnings, sanitizers and CPU tuning shared by
# every MPFD target, so that no folder sets its own flags.
function(mpfd_target_defaults target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow
                                           -Wnon-virtual-dtor -Wconversion -Wno-sign-conversion)
  # Lets loops over EOS and flux kernels vectorise (sqrt, exp); IEEE results unchanged.
  target_compile_options(${target} PRIVATE -fno-math-errno -fno-trapping-math)
  if(MPFD_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
  if(CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    # An `omp simd` loop clang leaves scalar is a missed optimisation, not a
    # fault: a warning, not an error; silent in the sanitizer tree (-O1), where
    # no loop is expected to vectorise.
    if(MPFD_SANITIZE)
      target_compile_options(${target} PRIVATE -Wno-pass-failed)
    else()
      target_compile_options(${target} PRIVATE -Wno-error=pass-failed)
    endif()
  endif()
  if(MPFD_NATIVE)
    target_compile_options(${target} PRIVATE -march=native)
  endif()
  if(MPFD_SANITIZE)
    target_compile_options(${target} PRIVATE -fsanitize=address,undefined -fno-omit-frame-pointer
                                             -fno-sanitize-recover=undefined)
    target_link_options(${target} PRIVATE -fsanitize=address,undefined)
  endif()
endfunction()

# mpfd_add_unit_test(<name> SOURCES <files...> LIBS <targets...> [LABELS <labels...>]
#                    [TIMEOUT <s>]): one GoogleTest executable under the "unit" label.
# Without extra labels CTest sees it test by test. With extra labels (e.g. `full`)
# it is one CTest entry: gtest_discover_tests (CMake 3.25) cannot pass a list
# property, so the labels would otherwise reach CTest as "unit" alone.
function(mpfd_add_unit_test name)
  cmake_parse_arguments(arg "" "TIMEOUT" "SOURCES;LIBS;LABELS" ${ARGN})
  add_executable(${name} ${arg_SOURCES})
  target_link_libraries(${name} PRIVATE ${arg_LIBS} GTest::gtest GTest::gtest_main)
  mpfd_target_defaults(${name})
  if(NOT arg_TIMEOUT)
    set(arg_TIMEOUT 120)
  endif()
  if(arg_LABELS)
    add_test(NAME ${name} COMMAND ${name} WORKING_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR})
    set_tests_properties(${name} PROPERTIES LABELS "unit;${arg_LABELS}" TIMEOUT ${arg_TIMEOUT})
  else()
    gtest_discover_tests(${name} WORKING_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}
                         TEST_PREFIX "${name}."
                         PROPERTIES LABELS unit TIMEOUT ${arg_TIMEOUT}
                         DISCOVERY_TIMEOUT 60)
  endif()
endfunction()
