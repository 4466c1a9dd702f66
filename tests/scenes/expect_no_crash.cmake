# Runs `hexant check` on a scene the fuzzer once crashed on and passes when
# it ends as a scene may: read (exit 0) or an error reported with its place
# (exit 1). A scene that reads is then rendered as the fuzzer renders it
# (tests/fuzz/sdl_fuzzer.cpp: frame 1 of 3, 8 by 8 pixels, one sample, one thread), and
# must again end in an image or a reported error: some finds hung only in
# the render (fuzz_found/flat_cells.pov). The test's TIMEOUT catches a hang.
# A signal or any other exit fails.
# Called as: cmake -DHEXANT=... -DSCENE=... -DOUT=<image path> -P expect_no_crash.cmake
function(expect_clean_end what)
  execute_process(COMMAND "${HEXANT}" ${ARGN}
                  RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT (result STREQUAL "0" OR result STREQUAL "1"))
    message(FATAL_ERROR "${what}: expected exit code 0 or 1, got '${result}'\n${err}")
  endif()
  if(result STREQUAL "1" AND NOT err MATCHES "error: ")
    message(FATAL_ERROR "${what}: exit 1 without an error message\n${err}")
  endif()
  set(last_result "${result}" PARENT_SCOPE)
endfunction()

expect_clean_end("hexant check" check "${SCENE}")
if(last_result STREQUAL "0")
  expect_clean_end("hexant render" render "${SCENE}" -W 8 -H 8 --frame-count 3 --frames 1 --spp 1
                   --threads 1 -o "${OUT}")
endif()
