# Compiler settings shared by every penumbra target: warnings, sanitizers, ccache.

add_library(penumbra_warnings INTERFACE)
if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  target_compile_options(penumbra_warnings INTERFACE -Wall -Wextra -Wpedantic -Wshadow
                                                     -Wnon-virtual-dtor -Wconversion -Wno-sign-conversion)
  if(PENUMBRA_WARNINGS_AS_ERRORS)
    target_compile_options(penumbra_warnings INTERFACE -Werror)
  endif()
endif()

if(PENUMBRA_SANITIZE)
  string(REPLACE ";" "," _penumbra_sanitizers "${PENUMBRA_SANITIZE}")
  add_compile_options(-fsanitize=${_penumbra_sanitizers} -fno-omit-frame-pointer)
  add_link_options(-fsanitize=${_penumbra_sanitizers})
  # A report is a failure: undefined behaviour stops the program as an address error does.
  if("undefined" IN_LIST PENUMBRA_SANITIZE)
    add_compile_options(-fno-sanitize-recover=undefined)
    add_link_options(-fno-sanitize-recover=undefined)
    # CGAL's arrangements downcast by design: their types are left out of the vptr check.
    if(CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
      add_compile_options(-fsanitize-ignorelist=${PROJECT_SOURCE_DIR}/cmake/sanitize-ignorelist.txt)
    else()
      add_compile_options(-fno-sanitize=vptr)
    endif()
  endif()
endif()

# libFuzzer's coverage instrumentation in every target, the library's included; the fuzz
# programs themselves link with -fsanitize=fuzzer (tests/fuzz/CMakeLists.txt).
if(PENUMBRA_BUILD_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "PENUMBRA_BUILD_FUZZ needs clang (CMAKE_CXX_COMPILER=clang++): libFuzzer is clang's")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()

if(PENUMBRA_USE_CCACHE)
  find_program(PENUMBRA_CCACHE ccache)
  if(PENUMBRA_CCACHE)
    # Precompiled headers are only cacheable with this sloppiness.
    set(CMAKE_CXX_COMPILER_LAUNCHER
        ${CMAKE_COMMAND} -E env CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime
        ${PENUMBRA_CCACHE})
  endif()
endif()
