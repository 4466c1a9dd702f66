# Run by the build (app/CMakeLists.txt): `HEXANT man-page` into OUTPUT and
# OUTPUT.gz (gzip -9n: no name or time stamp inside, the same bytes at every
# build). Each file is written beside its name and renamed, so a failed run
# leaves no half-written page.
execute_process(COMMAND ${HEXANT} man-page OUTPUT_FILE ${OUTPUT}.part RESULT_VARIABLE failed)
if(failed)
  file(REMOVE ${OUTPUT}.part)
  message(FATAL_ERROR "${HEXANT} man-page failed: ${failed}")
endif()
execute_process(COMMAND gzip -9n -c ${OUTPUT}.part OUTPUT_FILE ${OUTPUT}.gz.part RESULT_VARIABLE failed)
if(failed)
  file(REMOVE ${OUTPUT}.part ${OUTPUT}.gz.part)
  message(FATAL_ERROR "gzip of ${OUTPUT} failed: ${failed}")
endif()
file(RENAME ${OUTPUT}.part ${OUTPUT})
file(RENAME ${OUTPUT}.gz.part ${OUTPUT}.gz)
