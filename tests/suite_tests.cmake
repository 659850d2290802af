# Writes a ctest file with one test per GoogleTest suite of a test binary (run after it is built):
# every test of the suite runs in one process, so the ~260 libraries a tier's binary loads
# (OpenImageIO, OpenVDB) are loaded once per suite instead of once per test (docs/TESTING.md).
#
#   cmake -D EXE=<binary> -D OUT=<file.cmake> -D LABEL=<tier> -P suite_tests.cmake
execute_process(COMMAND "${EXE}" --gtest_list_tests OUTPUT_VARIABLE listing RESULT_VARIABLE status
                TIMEOUT 60)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${EXE} --gtest_list_tests failed (${status}):\n${listing}")
endif()
string(REPLACE "\n" ";" lines "${listing}")
set(script "")
foreach(line IN LISTS lines)
  # A suite's line starts in the first column and ends in a dot (a typed or parameterized suite
  # adds a comment after it); its tests are indented below it.
  if(line MATCHES "^([^ #][^ ]*)\\.( .*)?$")
    set(suite "${CMAKE_MATCH_1}")
    string(APPEND script
      "add_test([==[${suite}]==] [==[${EXE}]==] [==[--gtest_filter=${suite}.*]==])\n"
      "set_tests_properties([==[${suite}]==] PROPERTIES LABELS [==[${LABEL}]==] WORKING_DIRECTORY [==[${WORKDIR}]==])\n")
  endif()
endforeach()
file(WRITE "${OUT}" "${script}")
