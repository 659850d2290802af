# Writes the shared libraries that PLUGIN loads, one path per line, in the order the dynamic loader
# loads them (breadth first, as ldd prints them), to OUTPUT. base/plugin_library preloads them in
# reverse order before the plugin: see there why. Run as `cmake -DPLUGIN=... -DOUTPUT=... -P`.
# Without ldd, or when it fails, the list is empty and the plugin is loaded as it is.
execute_process(COMMAND ldd "${PLUGIN}" OUTPUT_VARIABLE listing RESULT_VARIABLE status ERROR_QUIET)
set(paths "")
if(status EQUAL 0)
  string(REPLACE "\n" ";" lines "${listing}")
  foreach(line IN LISTS lines)
    if(line MATCHES "=> (/[^ ]+) \\(")
      string(APPEND paths "${CMAKE_MATCH_1}\n")
    endif()
  endforeach()
endif()
file(WRITE "${OUTPUT}" "${paths}")
