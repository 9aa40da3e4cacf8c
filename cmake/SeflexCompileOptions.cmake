# Warnings and sanitizers for every seflex target: call seflex_target_options(<target>).
add_library(seflex_options INTERFACE)
target_compile_options(seflex_options INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wcast-align -Woverloaded-virtual
  -Wno-maybe-uninitialized)
if(SEFLEX_SANITIZE)
  target_compile_options(seflex_options INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  target_link_options(seflex_options INTERFACE -fsanitize=address,undefined)
endif()
# Instruction set of Release builds (x86-64). seflex is built where it runs (scripts/bootstrap.sh),
# so `auto` compiles for x86-64-v3 (AVX2 and FMA: the dense kernels of the time loop and of the FE
# assembly run 1.5-3x faster) when the build host has it (cmake/arch_check.c), and for x86-64-v2
# otherwise. Set SEFLEX_ARCH=x86-64-v2 to build binaries for older CPUs, or any -march value.
set(SEFLEX_ARCH "auto" CACHE STRING "Release -march: auto (x86-64-v3 if the build host has it, else x86-64-v2) or a -march value")
if(CMAKE_SYSTEM_PROCESSOR MATCHES "x86_64|AMD64")
  set(seflex_march "${SEFLEX_ARCH}")
  if(SEFLEX_ARCH STREQUAL "auto")
    set(seflex_march x86-64-v2)
    if(NOT CMAKE_CROSSCOMPILING)
      try_run(seflex_arch_run seflex_arch_compiled ${CMAKE_BINARY_DIR}/arch-check
              ${CMAKE_CURRENT_LIST_DIR}/arch_check.c)
      if(seflex_arch_compiled AND seflex_arch_run EQUAL 0)
        set(seflex_march x86-64-v3)
      endif()
    endif()
  endif()
  if(CMAKE_BUILD_TYPE STREQUAL "Release")
    message(STATUS "seflex: Release code for -march=${seflex_march} (SEFLEX_ARCH=${SEFLEX_ARCH})")
  endif()
  target_compile_options(seflex_options INTERFACE $<$<CONFIG:Release>:-march=${seflex_march}>)
endif()
target_compile_definitions(seflex_options INTERFACE $<$<CONFIG:Debug>:SEFLEX_DEBUG_CHECKS=1>)

function(seflex_target_options target)
  target_link_libraries(${target} PRIVATE seflex_options)
endfunction()
