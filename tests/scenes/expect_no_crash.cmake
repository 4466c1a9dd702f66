# Runs `hexant check` on a scene the fuzzer once crashed on and passes when
# it ends as a scene may: read (exit 0) or an error reported with its place
# (exit 1). A signal or any other exit fails.
# Called as: cmake -DHEXANT=... -DSCENE=... -P expect_no_crash.cmake
execute_process(COMMAND "${HEXANT}" check "${SCENE}"
                RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT (result STREQUAL "0" OR result STREQUAL "1"))
  message(FATAL_ERROR "expected exit code 0 or 1, got '${result}'\n${err}")
endif()
if(result STREQUAL "1" AND NOT err MATCHES "error: ")
  message(FATAL_ERROR "exit 1 without an error message\n${err}")
endif()
