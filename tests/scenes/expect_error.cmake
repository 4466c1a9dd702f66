# Runs `hexant check` on a broken scene and passes only if it fails the way the
# scene's first line says:
#   // error: [FILE:]LINE:COLUMN: SUBSTRING
# (FILE relative to the scene's folder, for errors inside an #include), with
# exit code 1, the place as file:line:column, the substring, and a caret.
# A line `// flags: ...` adds command-line flags.
# Called as: cmake -DHEXANT=... -DSCENE=... -P expect_error.cmake
file(STRINGS "${SCENE}" header LIMIT_COUNT 3)
set(expect "")
set(flags "")
foreach(line IN LISTS header)
  if(line MATCHES "^// error: (.*)$")
    set(expect "${CMAKE_MATCH_1}")
  elseif(line MATCHES "^// flags: (.*)$")
    separate_arguments(flags UNIX_COMMAND "${CMAKE_MATCH_1}")
  endif()
endforeach()
if(NOT expect MATCHES "^(([^:]+):)?([0-9]+):([0-9]+): (.+)$")
  message(FATAL_ERROR "${SCENE}: first line must be // error: [FILE:]LINE:COLUMN: SUBSTRING")
endif()
get_filename_component(folder "${SCENE}" DIRECTORY)
if(CMAKE_MATCH_2)
  set(where "${folder}/${CMAKE_MATCH_2}:${CMAKE_MATCH_3}:${CMAKE_MATCH_4}:")
else()
  set(where "${SCENE}:${CMAKE_MATCH_3}:${CMAKE_MATCH_4}:")
endif()
set(substring "${CMAKE_MATCH_5}")

execute_process(COMMAND "${HEXANT}" check "${SCENE}" ${flags}
                RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT result EQUAL 1)
  message(FATAL_ERROR "expected exit code 1, got '${result}'\n${err}")
endif()
string(FIND "${err}" "${where} error:" at)
if(at EQUAL -1)
  message(FATAL_ERROR "expected the error at ${where}\n${err}")
endif()
string(FIND "${err}" "${substring}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "expected the message to contain '${substring}'\n${err}")
endif()
if(NOT err MATCHES "\n *\\^")
  message(FATAL_ERROR "expected a caret under the source line\n${err}")
endif()
