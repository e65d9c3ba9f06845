# pfx_add_plugin(NAME src...): a plugin shared library that exports exactly one symbol
# (pfx_get_entry), has no "lib" prefix, and lands in build/plugins/ unless OUTPUT_DIR says otherwise.
# It links nothing that brings GL or a window system: GL comes through the host.
#
# Plugins built into the default folder are the shipped effects, so `cmake --install` puts them in
# PREFIX/lib/pfx/plugins, where the installed programs look (BIN/../lib/pfx/plugins). Plugins given
# another OUTPUT_DIR are test fixtures and are never installed.
set(PFX_INSTALL_PLUGINDIR lib/pfx/plugins)

function(pfx_add_plugin name)
  cmake_parse_arguments(ARG "" "OUTPUT_DIR" "SOURCES" ${ARGN})
  set(shipped FALSE)
  if(NOT ARG_OUTPUT_DIR OR ARG_OUTPUT_DIR STREQUAL PFX_PLUGIN_OUTPUT_DIR)
    set(ARG_OUTPUT_DIR ${PFX_PLUGIN_OUTPUT_DIR})
    set(shipped TRUE)
  endif()
  add_library(${name} MODULE ${ARG_SOURCES} ${ARG_UNPARSED_ARGUMENTS})
  target_link_libraries(${name} PRIVATE pfx::sdk)
  set_target_properties(${name} PROPERTIES
    PREFIX ""
    LIBRARY_OUTPUT_DIRECTORY ${ARG_OUTPUT_DIR})
  target_link_options(${name} PRIVATE
    "LINKER:--version-script=${PROJECT_SOURCE_DIR}/cmake/plugin.map"
    "LINKER:--no-undefined" "LINKER:--as-needed")
  if(shipped)
    install(TARGETS ${name} LIBRARY DESTINATION ${PFX_INSTALL_PLUGINDIR})
    # For what is made from the shipped plugins once they are built (the per-effect frei0r plugins).
    set_property(GLOBAL APPEND PROPERTY PFX_SHIPPED_PLUGINS ${name})
  endif()
endfunction()
