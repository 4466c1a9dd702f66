# What `cmake --install` puts beside bin/hexant and its man page (those two
# are installed by app/CMakeLists.txt, the include files by
# language/CMakeLists.txt), and the Debian package CPack builds from the
# same install (`make package`; README.md, "Install").

# `make install` and CPack install what was built, without building `all`
# first (the tests): the Makefile's install and package build the installed
# targets, hexant and hexant_man_page, and nothing else.
set(CMAKE_SKIP_INSTALL_ALL_DEPENDENCY ON)

# The manual and the example scenes it walks through.
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/examples/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/examples)

# The Debian packages of the FFmpeg libraries --video loads with dlopen
# (tracer/ffmpeg_library.cpp), by the sonames of the headers built against:
# dpkg-shlibdeps cannot see them, so they are named here, as Recommends
# (hexant renders without them; only --video needs them). The package is
# whichever owns lib<name>.so.<major> here, else Debian's naming rule.
set(HEXANT_RECOMMENDS povray-includes fonts-povray)
foreach(library avcodec avformat swscale avutil)
  string(REGEX MATCH "^[0-9]+" major "${LIBAV_lib${library}_VERSION}")
  set(package lib${library}${major})
  find_program(HEXANT_DPKG dpkg)
  if(HEXANT_DPKG)
    execute_process(COMMAND ${HEXANT_DPKG} -S "*/lib${library}.so.${major}"
                    OUTPUT_VARIABLE owner ERROR_QUIET RESULT_VARIABLE failed)
    if(NOT failed AND owner MATCHES "^([^:,]+)")
      set(package ${CMAKE_MATCH_1})
    endif()
  endif()
  list(APPEND HEXANT_RECOMMENDS ${package})
endforeach()
list(JOIN HEXANT_RECOMMENDS ", " HEXANT_RECOMMENDS)

set(HEXANT_PACKAGE_MAINTAINER "hexant maintainers <maintainers@users.noreply.h-seed-5940d172.example>"
    CACHE STRING "The Debian package's Maintainer field")
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME hexant)
set(CPACK_PACKAGE_VENDOR "hexant")
set(CPACK_PACKAGE_CONTACT "${HEXANT_PACKAGE_MAINTAINER}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "spacetime ray tracer for POV-Ray-style animated scenes")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)  # as Debian ships binaries
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # hexant_0.1.0-1_amd64.deb
set(CPACK_DEBIAN_PACKAGE_RELEASE 1)
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${HEXANT_PACKAGE_MAINTAINER}")
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
# Depends from the libraries bin/hexant (and any module) links, by
# dpkg-shlibdeps (dpkg-dev, with build-essential; it needs `file`).
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "${HEXANT_RECOMMENDS}")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "povray")
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
# The long description (CPack puts the summary above it).
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
    "hexant renders animations written in a subset of POV-Ray 3.7's scene
language with Glassner's spacetime ray tracing: the whole animation is one
static object in 4D spacetime, sorted once into one hierarchy, and every ray
carries its own time, so motion blur, moving shadows and a moving camera
come out of the same tracer. It reads POV-Ray .ini files and switches and
writes frames, contact sheets, animated GIFs and (with FFmpeg's libraries)
videos.")
include(CPack)
