# Manual pages: one per installed program, made at build time from the program's own --help by
# Debian's help2man (so `man pfx-render` says what --help says, and the two cannot drift), gzipped
# as Debian installs them, into PREFIX/share/man/man1.
#
# Not in a sanitizer build: running its programs at build time would mix AddressSanitizer's reports
# into the pages, and that build is never installed. Without help2man the configure stops with the
# package to install (./run installs it).
if(PFX_SANITIZE)
  return()
endif()
find_program(PFX_HELP2MAN help2man)
if(NOT PFX_HELP2MAN)
  message(FATAL_ERROR "help2man not found: it makes the manual pages (apt install help2man; ./run installs it)")
endif()

# NAME: the program; TARGET: what builds it (its file, or the script the target copies into the
# runtime folder); DESCRIPTION: the one line `man -k` shows.
function(pfx_manual_page name target description)
  if(NOT TARGET ${target})
    return()
  endif()
  get_target_property(type ${target} TYPE)
  if(type STREQUAL "EXECUTABLE")
    set(program $<TARGET_FILE:${target}>)
  else()
    set(program ${CMAKE_RUNTIME_OUTPUT_DIRECTORY}/${name})
  endif()
  set(page ${PROJECT_BINARY_DIR}/man/man1/${name}.1)
  add_custom_command(
    OUTPUT ${page}.gz
    COMMAND ${CMAKE_COMMAND} -E make_directory ${PROJECT_BINARY_DIR}/man/man1
    COMMAND ${PFX_HELP2MAN} --no-info --no-discard-stderr --version-string=${PROJECT_VERSION}
            --name=${description} --section=1 --output=${page} ${program}
    COMMAND gzip -9nf ${page}
    DEPENDS ${target}
    COMMENT "manual page of ${name}"
    VERBATIM)
  add_custom_target(${name}-manual-page ALL DEPENDS ${page}.gz)
  install(FILES ${page}.gz DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
endfunction()

pfx_manual_page(pfx-render pfx-render "render a scene, a picture or a sequence through a chain of pfx effects")
pfx_manual_page(pfx-view pfx-view "look at pfx effect chains and tune their parameters in a window")
pfx_manual_page(pfx-bench pfx-bench "time pfx effects against a plain copy pass, with their error")
pfx_manual_page(pfx-validate pfx-validate "check pfx plugins against the contract of the pfx C ABI")
pfx_manual_page(pfx-import pfx-import "import a 3D model through pfx's importer plugins")
pfx_manual_page(pfx-farm pfx-farm "render a sequence with pfx-render as Slurm jobs")
pfx_manual_page(pfx-inject pfx-inject "run pfx effects inside an unmodified OpenGL or Vulkan application")
pfx_manual_page(pfx-fx-check pfx-fx-check "compile, run and compare every ReShade FX effect of shader folders")
pfx_manual_page(pfx-libretro-check pfx-libretro-check "run and compare every libretro shader preset of shader folders")
