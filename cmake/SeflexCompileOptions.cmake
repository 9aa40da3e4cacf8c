# Warnings and sanitizers for every seflex target: call seflex_target_options(<target>).
add_library(seflex_options INTERFACE)
target_compile_options(seflex_options INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wcast-align -Woverloaded-virtual
  -Wno-maybe-uninitialized)
if(SEFLEX_SANITIZE)
  target_compile_options(seflex_options INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  target_link_options(seflex_options INTERFACE -fsanitize=address,undefined)
endif()
# Release builds: optimise for this machine's ISA level but stay portable across x86-64 CPUs.
if(CMAKE_SYSTEM_PROCESSOR MATCHES "x86_64|AMD64")
  target_compile_options(seflex_options INTERFACE $<$<CONFIG:Release>:-march=x86-64-v2>)
endif()
target_compile_definitions(seflex_options INTERFACE $<$<CONFIG:Debug>:SEFLEX_DEBUG_CHECKS=1>)

function(seflex_target_options target)
  target_link_libraries(${target} PRIVATE seflex_options)
endfunction()
