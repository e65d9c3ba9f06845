# The Debian package (./run package; docs/packaging.md): CPack's DEB generator over the install
# rules, built from a tree configured with CMAKE_INSTALL_PREFIX=/usr so that every adapter lands in
# the folder its host searches (frei0r: /usr/lib/frei0r-1; GStreamer and OBS: their folders under
# /usr/lib/<triplet>; Python: /usr/lib/python3/dist-packages) and the programs find their plugins
# in /usr/lib/pfx/plugins. Dependencies are read off what the binaries link (dpkg-shlibdeps).
#
# Also installed by every install, packaged or not: the licence, the README and docs/ in DOCDIR.
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs
        PATTERN "*.py" EXCLUDE PATTERN "*.txt" EXCLUDE)

option(PFX_DEBIAN_PACKAGE "Configure for the Debian package: Debian's copyright and changelog files in DOCDIR" OFF)
# Whoever publishes a package names themselves here; the default says who wrote pfx.
set(PFX_PACKAGE_MAINTAINER "The pfx developers <pfx-developers@example.org>" CACHE STRING
    "The Debian package's Maintainer field and changelog signature: 'Name <address>'")
if(PFX_DEBIAN_PACKAGE)
  # Debian's policy names the licence file "copyright", in its machine-readable format, and wants a
  # compressed changelog beside it.
  set(PFX_DEBIAN_DOC_DIR ${PROJECT_BINARY_DIR}/debian-doc)
  file(READ ${PROJECT_SOURCE_DIR}/LICENSE licence_text)
  string(REGEX REPLACE "\n\n" "\n.\n" licence_text "${licence_text}")
  string(REGEX REPLACE "\n([^\n])" "\n \\1" licence_text "${licence_text}")
  file(WRITE ${PFX_DEBIAN_DOC_DIR}/copyright
       "Format: https://www.debian.org/doc/packaging-manuals/copyright-format/1.0/\n"
       "Upstream-Name: pfx\n\nFiles: *\nCopyright: 2026 The pfx developers\nLicense: MIT\n\n"
       "License: MIT\n ${licence_text}")
  # A native package (its version has no Debian revision): the changelog is changelog.gz.
  string(TIMESTAMP changelog_date "%a, %d %b %Y %H:%M:%S +0000" UTC)
  file(WRITE ${PFX_DEBIAN_DOC_DIR}/changelog
       "pfx (${PROJECT_VERSION}) unstable; urgency=medium\n\n"
       "  * Built from the pfx source tree with ./run package.\n\n"
       " -- ${PFX_PACKAGE_MAINTAINER}  ${changelog_date}\n")
  execute_process(COMMAND gzip -9nf ${PFX_DEBIAN_DOC_DIR}/changelog COMMAND_ERROR_IS_FATAL ANY)
  install(FILES ${PFX_DEBIAN_DOC_DIR}/copyright ${PFX_DEBIAN_DOC_DIR}/changelog.gz
          DESTINATION ${CMAKE_INSTALL_DOCDIR})
  # libpfxhost and the other libraries in /usr/lib/<triplet>: the loader's cache is renewed by
  # dpkg's ldconfig trigger (CPack's maintainer scripts also call ldconfig themselves).
  file(WRITE ${PFX_DEBIAN_DOC_DIR}/triggers "activate-noawait ldconfig\n")
  set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA ${PFX_DEBIAN_DOC_DIR}/triggers)
endif()

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME pfx)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT "${PFX_PACKAGE_MAINTAINER}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "plugin-based post effects for OpenGL 4.5 hosts")
set(CPACK_PACKAGE_DESCRIPTION
    "pfx runs post effects (bloom, glare, depth of field, tiled lighting) as\n"
    "plugins over OpenGL 4.5 frames: a command-line renderer and a viewer, the\n"
    "runtime and SDK for engines, frei0r plugins for ffmpeg and MLT, a GStreamer\n"
    "element, OBS Studio filters, a Python module, and pfx-inject for unmodified\n"
    "OpenGL and Vulkan applications.")
string(REPLACE ";" "" CPACK_PACKAGE_DESCRIPTION "${CPACK_PACKAGE_DESCRIPTION}")
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_PACKAGING_INSTALL_PREFIX ${CMAKE_INSTALL_PREFIX})
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# dpkg-shlibdeps finds libpfxhost, which the package itself ships, in the staging folder.
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS ON)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
# What no binary links but the Python module needs to be imported: the interpreter whose ABI it
# was built for, and numpy, which it imports for its pictures. Recommended, not required: the rest
# of the package runs without Python.
find_package(Python3 COMPONENTS Interpreter QUIET)
if(Python3_VERSION_MAJOR AND Python3_VERSION_MINOR)
  math(EXPR python_next_minor "${Python3_VERSION_MINOR} + 1")
  set(CPACK_DEBIAN_PACKAGE_RECOMMENDS
      "python3 (>= ${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}), python3 (<< ${Python3_VERSION_MAJOR}.${python_next_minor}), python3-numpy")
endif()
# The hosts whose plugin folders the package fills.
set(CPACK_DEBIAN_PACKAGE_ENHANCES "ffmpeg, melt, gstreamer1.0-plugins-base, obs-studio, python3")
include(CPack)
