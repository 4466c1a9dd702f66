# Run at every build (cmake -P, app/CMakeLists.txt): writes OUTPUT with the
# source tree's commit as HEXANT_GIT_COMMIT ("" outside a git tree or
# without git; "-dirty" when tracked files differ from it). The file is
# rewritten only when its text changes, so an unchanged commit rebuilds
# nothing and a new one recompiles app/version.cpp alone.
set(commit "")
find_package(Git QUIET)
if(GIT_FOUND)
  # Only hexant's own tree: a source tarball unpacked inside another git
  # work tree must not take that tree's commit.
  execute_process(COMMAND ${GIT_EXECUTABLE} -C ${SOURCE_DIR} rev-parse --show-toplevel
                  OUTPUT_VARIABLE top OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  execute_process(COMMAND ${GIT_EXECUTABLE} -C ${SOURCE_DIR} rev-parse --short=12 HEAD
                  OUTPUT_VARIABLE commit OUTPUT_STRIP_TRAILING_WHITESPACE
                  RESULT_VARIABLE failed ERROR_QUIET)
  file(REAL_PATH "${SOURCE_DIR}" source)
  if(top)
    file(REAL_PATH "${top}" top)
  endif()
  if(failed OR NOT top STREQUAL source)
    set(commit "")
  else()
    # status, not diff-index: a file only touched is not a change. No
    # optional locks: a build must not hold the index while git writes it.
    execute_process(COMMAND ${GIT_EXECUTABLE} -C ${SOURCE_DIR} --no-optional-locks status
                            --porcelain --untracked-files=no
                    OUTPUT_VARIABLE changed ERROR_QUIET)
    if(NOT changed STREQUAL "")
      string(APPEND commit "-dirty")
    endif()
  endif()
endif()
set(text "// Written by cmake/git_commit.cmake at build time; not in git.\n#define HEXANT_GIT_COMMIT \"${commit}\"\n")
if(EXISTS ${OUTPUT})
  file(READ ${OUTPUT} old)
endif()
if(NOT "${old}" STREQUAL "${text}")
  file(WRITE ${OUTPUT} "${text}")
endif()
