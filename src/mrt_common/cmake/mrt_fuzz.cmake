# The one way the stack builds its libFuzzer targets (loaded by every
# package that finds mrt_common through catkin). Fuzz targets are built
# only when the compiler is clang with libFuzzer (the sanitizer stage,
# scripts/sanitize.sh, configures the workspace so and adds
# -fsanitize=address,undefined to every file); elsewhere the functions do
# nothing. Harnesses live in <package>/fuzz/, the programs land in the
# package's devel lib directory (rosrun <package> <target>) and are never
# installed. scripts/fuzz_targets.txt lists which ones the stage runs.
#
#   mrt_add_fuzz_objects(NAME SOURCES...)
#       the core's sources compiled once, with coverage, for several
#       targets (an object library);
#   mrt_add_fuzz_target(NAME HARNESS [SOURCES src...] [OBJECTS name...]
#                       [LIBRARIES lib...] [DEFINITIONS def...])
#       a program: the harness (defines LLVMFuzzerTestOneInput) and the
#       core sources it exercises (SOURCES, or an mrt_add_fuzz_objects
#       library), with coverage, linked with LIBRARIES.

set(MRT_FUZZ_ENABLED OFF)
if(CMAKE_CXX_COMPILER_ID MATCHES Clang)
  include(CheckCXXSourceCompiles)
  set(CMAKE_REQUIRED_FLAGS "-fsanitize=fuzzer")
  check_cxx_source_compiles([=[
#include <cstddef>
#include <cstdint>
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t*, std::size_t) { return 0; }
]=] MRT_HAVE_LIBFUZZER)
  unset(CMAKE_REQUIRED_FLAGS)
  if(MRT_HAVE_LIBFUZZER)
    set(MRT_FUZZ_ENABLED ON)
  else()
    message(WARNING "${CMAKE_CXX_COMPILER} cannot link -fsanitize=fuzzer (Debian: libclang-rt-14-dev): "
                    "no fuzz targets")
  endif()
endif()

function(mrt_add_fuzz_objects name)
  if(NOT MRT_FUZZ_ENABLED)
    return()
  endif()
  add_library(${name} OBJECT ${ARGN})
  target_compile_options(${name} PRIVATE -fsanitize=fuzzer-no-link)
endfunction()

function(mrt_add_fuzz_target name harness)
  if(NOT MRT_FUZZ_ENABLED)
    return()
  endif()
  cmake_parse_arguments(F "" "" "SOURCES;OBJECTS;LIBRARIES;DEFINITIONS" ${ARGN})
  set(objects)
  foreach(o ${F_OBJECTS})
    list(APPEND objects $<TARGET_OBJECTS:${o}>)
  endforeach()
  add_executable(${name} ${harness} ${F_SOURCES} ${objects})
  target_compile_options(${name} PRIVATE -fsanitize=fuzzer)
  target_compile_definitions(${name} PRIVATE ${F_DEFINITIONS})
  target_link_libraries(${name} ${F_LIBRARIES} -fsanitize=fuzzer)
endfunction()
