# Warning and sanitizer flags applied to the project's own targets only
# (third-party headers are included as SYSTEM so their warnings stay out).
add_library(isosid_options INTERFACE)
target_compile_options(isosid_options INTERFACE -Wall -Wextra -Wpedantic)
# Our code exports nothing: its Eigen template instances would otherwise be exported from the
# programs and bind libgmsh's calls of the same instances, compiled with another Eigen
# configuration (measured under ASan: gmsh's matrix inverse freed memory our instance had not
# allocated). Everything links statically into executables, so hidden visibility costs nothing.
target_compile_options(isosid_options INTERFACE -fvisibility=hidden -fvisibility-inlines-hidden)
# GCC 12 reports -Wrestrict inside libstdc++'s std::string concatenation at -O2, a known false
# positive (GCC bug 105329, fixed in GCC 13); it says nothing about project code.
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
  target_compile_options(isosid_options INTERFACE -Wno-restrict)
endif()
if(ISOSID_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "ISOSID_FUZZ needs clang (libFuzzer): configure with CC=clang CXX=clang++")
  endif()
  # coverage for libFuzzer in every library the targets link, with the sanitizers
  target_compile_options(isosid_options INTERFACE
    -fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  target_link_options(isosid_options INTERFACE -fsanitize=address,undefined)
elseif(ISOSID_SANITIZE)
  # -g1: line tables and function names, all a sanitizer report prints; full debug info made
  # this build a third slower (modal_analysis.cpp 41 s -> 31 s) and its objects four times larger
  target_compile_options(isosid_options INTERFACE
    -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined -g1)
  target_link_options(isosid_options INTERFACE -fsanitize=address,undefined)
endif()

# The numerical libraries (isosid_prep, isosid_runtime) under ASan skip use-after-scope
# poisoning: their Eigen fixed-size temporaries make it the dominant cost (scene A 12.3 s ->
# 4.6 s CPU, Release 0.5 s), which kept the stability set out of the sanitizer run. Heap,
# stack-overflow and UB checks stay; format/ and common/, which parse hostile input, keep it.
function(isosid_numerical_sanitizer_options target)
  if(ISOSID_SANITIZE AND NOT ISOSID_FUZZ AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    target_compile_options(${target} PRIVATE -fno-sanitize-address-use-after-scope)
  endif()
endfunction()

# Precompiled standard, Eigen (and, for tests, Catch2) headers: parsing them was about 2 s of
# each translation unit's 5-40 s, and CI builds the project three times (Release build 8.5 ->
# 6.2 min on 2 cores). Nothing in the project configures Eigen by macro, so a precompiled Eigen
# is the same Eigen. The fuzz build turns them off (fuzz/configure), so every library file still
# compiles with its own includes. GCC 12 no longer treats headers from a precompiled header as
# system headers and reports its libstdc++ false positives in std::string concatenation
# (-Wstringop-overflow, -Warray-bounds inside basic_string::insert, the sibling of the -Wrestrict
# one above) at our string code; they are off for these targets, and real overflows are
# AddressSanitizer's to find.
set(ISOSID_COMMON_HEADERS <algorithm> <cmath> <functional> <map> <memory> <optional> <string>
  <vector> <Eigen/Dense>)
function(isosid_precompiled_headers target)
  target_precompile_headers(${target} PRIVATE ${ISOSID_COMMON_HEADERS} ${ARGN})
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13 AND NOT CMAKE_DISABLE_PRECOMPILE_HEADERS)
    target_compile_options(${target} PRIVATE -Wno-stringop-overflow -Wno-array-bounds)
  endif()
endfunction()

# add_subdirectory for each named part that this checkout has (a part may be left out of a
# source package)
function(isosid_add_existing_subdirectories)
  foreach(part ${ARGN})
    if(EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/${part}/CMakeLists.txt)
      add_subdirectory(${part})
    endif()
  endforeach()
endfunction()
