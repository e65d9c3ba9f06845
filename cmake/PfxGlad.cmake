# Generates a GL 4.5 core loader with Debian's python3-glad at configure time, into the build tree.
# Nothing is fetched: --reproducible uses the Khronos XML that the package ships.
find_program(GLAD_EXECUTABLE glad REQUIRED)
set(PFX_GLAD_DIR ${PROJECT_BINARY_DIR}/glad)
if(NOT EXISTS ${PFX_GLAD_DIR}/src/gl.c)
  execute_process(
    COMMAND ${GLAD_EXECUTABLE} --api gl:core=4.5 --extensions "" --out-path ${PFX_GLAD_DIR}
            --reproducible --quiet c
    RESULT_VARIABLE glad_result OUTPUT_QUIET ERROR_VARIABLE glad_error)
  if(NOT glad_result EQUAL 0)
    message(FATAL_ERROR "glad failed to generate the GL loader: ${glad_error}")
  endif()
endif()

# A static, hidden-visibility copy: every shared library that links it (libpfxhost, each plugin)
# gets its own private function-pointer table, loaded from the host's get_proc_address.
add_library(pfx_glad STATIC ${PFX_GLAD_DIR}/src/gl.c)
target_include_directories(pfx_glad SYSTEM PUBLIC $<BUILD_INTERFACE:${PFX_GLAD_DIR}/include>)
set_target_properties(pfx_glad PROPERTIES C_VISIBILITY_PRESET hidden POSITION_INDEPENDENT_CODE ON)
