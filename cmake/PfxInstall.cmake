# cmake --install: the SDK headers (extended by the install issue work: libpfxhost, plugins, programs,
# CMake package and pkg-config file).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/sdk/include/pfx DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
