# cmake --install: everything another engine needs to build against pfx or embed its runtime.
#
#   PREFIX/include/pfx/*.h               the C ABI (all a plugin or a foreign host must include)
#   PREFIX/include/pfx/host/*.hpp        libpfxhost's C++ API
#   PREFIX/LIBDIR/libpfxhost.so*         the runtime, with its soname links
#   PREFIX/lib/pfx/plugins/*.so          the effects (pfx_add_plugin installs them: cmake/PfxPlugin.cmake)
#   PREFIX/bin/pfx-*                     the programs (each program's CMakeLists installs itself)
#   PREFIX/LIBDIR/cmake/pfx/             find_package(pfx): pfx::sdk, pfx::host, pfx_PLUGIN_DIR,
#                                        pfx_PLUGIN_VERSION_SCRIPT
#   PREFIX/LIBDIR/pkgconfig/pfx.pc       the same for pkg-config
#
# glad is not installed: it is a build-tree detail of our own targets. A plugin author brings their
# own GL loader and fills it through pfx_host::get_proc_address (docs/sdk.md).
include(CMakePackageConfigHelpers)

# The programs look for plugins at BIN/../lib/pfx/plugins (host/lib/common/plugin_directory.cpp), so
# this path is fixed, not LIBDIR: with PREFIX=/usr, LIBDIR is lib/x86_64-linux-gnu on Debian.
# PFX_INSTALL_PLUGINDIR itself is set in PfxPlugin.cmake, which is included before any plugin exists.
set(PFX_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/pfx)

# ---- Headers -------------------------------------------------------------------------------------
# Trailing slashes: copy the contents, so both land in the one include/pfx tree.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/sdk/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.h")
install(DIRECTORY ${PROJECT_SOURCE_DIR}/sdk/host/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.hpp")
# The header-only C++ helpers for plugin authors, once sdk/helpers exists (pfx::sdk already puts
# them on the build-tree include path).
if(EXISTS ${PROJECT_SOURCE_DIR}/sdk/helpers/include)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/sdk/helpers/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endif()

# The plugin folder exists even while no plugin is built, so the programs and pfx_PLUGIN_DIR always
# name a real directory (an empty one loads zero plugins; a missing one is an error).
install(DIRECTORY DESTINATION ${PFX_INSTALL_PLUGINDIR})

# ---- The two targets and their CMake package -----------------------------------------------------
# Consumers see pfx::sdk and pfx::host, the same names the build tree uses.
set_target_properties(pfx_sdk PROPERTIES EXPORT_NAME sdk)
set_target_properties(pfx_host PROPERTIES EXPORT_NAME host)
# The host headers use C++17 (nested namespaces, std::function in the API): a consumer's compiler
# must be told, not left to guess from an error deep in a header.
set_property(TARGET pfx_host APPEND PROPERTY INTERFACE_COMPILE_FEATURES cxx_std_17)

install(TARGETS pfx_sdk pfx_host EXPORT pfxTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(EXPORT pfxTargets NAMESPACE pfx:: DESTINATION ${PFX_INSTALL_CMAKEDIR})

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/pfxConfig.cmake.in
  ${PROJECT_BINARY_DIR}/cmake/pfxConfig.cmake
  INSTALL_DESTINATION ${PFX_INSTALL_CMAKEDIR}
  PATH_VARS PFX_INSTALL_PLUGINDIR PFX_INSTALL_CMAKEDIR)
# libpfxhost's soname carries the major version, so the package promises exactly what the soname does.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/cmake/pfxConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMajorVersion)
install(FILES ${PROJECT_BINARY_DIR}/cmake/pfxConfig.cmake ${PROJECT_BINARY_DIR}/cmake/pfxConfigVersion.cmake
              ${CMAKE_CURRENT_LIST_DIR}/plugin.map
        DESTINATION ${PFX_INSTALL_CMAKEDIR})

# ---- pkg-config ----------------------------------------------------------------------------------
# Relocatable: the prefix is found from the .pc file's own folder, so `cmake --install --prefix X`
# (chosen after configure) and a copied install tree both give right paths.
# A /usr install (the Debian package) is not moved: its paths are written out plainly.
if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}" OR IS_ABSOLUTE "${CMAKE_INSTALL_INCLUDEDIR}" OR CMAKE_INSTALL_PREFIX STREQUAL "/usr")
  set(PFX_PC_PREFIX "${CMAKE_INSTALL_PREFIX}")
  set(PFX_PC_LIBDIR "${CMAKE_INSTALL_FULL_LIBDIR}")
  set(PFX_PC_INCLUDEDIR "${CMAKE_INSTALL_FULL_INCLUDEDIR}")
else()
  # From PREFIX/LIBDIR/pkgconfig back up to PREFIX ("../.." for lib, "../../.." for lib/<triplet>).
  file(RELATIVE_PATH pc_to_prefix /pfx-root/${CMAKE_INSTALL_LIBDIR}/pkgconfig /pfx-root)
  string(REGEX REPLACE "/$" "" pc_to_prefix "${pc_to_prefix}")
  set(PFX_PC_PREFIX "\${pcfiledir}/${pc_to_prefix}")
  set(PFX_PC_LIBDIR "\${prefix}/${CMAKE_INSTALL_LIBDIR}")
  set(PFX_PC_INCLUDEDIR "\${prefix}/${CMAKE_INSTALL_INCLUDEDIR}")
endif()
configure_file(${CMAKE_CURRENT_LIST_DIR}/pfx.pc.in ${PROJECT_BINARY_DIR}/cmake/pfx.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/cmake/pfx.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

# ---- RPATH of the installed programs -------------------------------------------------------------
# An install under any prefix must find its own libpfxhost, not one on the system or in the build
# tree. INSTALL_RPATH is read when a target is created and this file is included after every
# add_subdirectory, so the property is set on each executable here, which also covers programs
# added later without touching their CMakeLists.
file(RELATIVE_PATH bin_to_lib /pfx-root/${CMAKE_INSTALL_BINDIR} /pfx-root/${CMAKE_INSTALL_LIBDIR})
set(PFX_PROGRAM_INSTALL_RPATH "\$ORIGIN/${bin_to_lib}")
function(pfx_set_program_rpath directory)
  get_property(targets DIRECTORY ${directory} PROPERTY BUILDSYSTEM_TARGETS)
  foreach(target IN LISTS targets)
    get_target_property(type ${target} TYPE)
    if(type STREQUAL "EXECUTABLE")
      set_target_properties(${target} PROPERTIES INSTALL_RPATH "${PFX_PROGRAM_INSTALL_RPATH}")
    endif()
  endforeach()
  get_property(subdirectories DIRECTORY ${directory} PROPERTY SUBDIRECTORIES)
  foreach(subdirectory IN LISTS subdirectories)
    pfx_set_program_rpath(${subdirectory})
  endforeach()
endfunction()
pfx_set_program_rpath(${PROJECT_SOURCE_DIR})
