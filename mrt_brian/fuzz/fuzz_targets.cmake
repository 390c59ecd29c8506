# The libFuzzer targets of mrt_brian (see CMakeLists.txt in this directory):
# one per parser, the list file and the engine. The core's sources are
# compiled again into an object library with
# -fsanitize=fuzzer-no-link,address,undefined, so libFuzzer gets coverage of
# the parsers and ASan/UBSan see into them; only the programs link the
# libFuzzer runtime. Included by ../CMakeLists.txt when the workspace
# compiler is clang, else by CMakeLists.txt here (a clang++ sub-build).
# Inputs: MRT_BRIAN_DIR (the package directory), MRT_BRIAN_FUZZ_OUTPUT_DIR
# (where the programs go); the include directories are the including
# scope's.
set(sanitizers address,undefined)
include(CheckCXXSourceCompiles)
set(CMAKE_REQUIRED_FLAGS "-fsanitize=fuzzer,${sanitizers}")
check_cxx_source_compiles([=[
#include <cstddef>
#include <cstdint>
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t*, std::size_t) { return 0; }
]=] MRT_BRIAN_HAVE_LIBFUZZER)
unset(CMAKE_REQUIRED_FLAGS)
if(NOT MRT_BRIAN_HAVE_LIBFUZZER)
  message(WARNING "mrt_brian: ${CMAKE_CXX_COMPILER} cannot link -fsanitize=fuzzer "
                  "(Debian: install libclang-rt-dev); the fuzz targets are not built")
else()
  include(${MRT_BRIAN_DIR}/cmake/core_sources.cmake)
  list(TRANSFORM MRT_BRIAN_CORE_SOURCES PREPEND ${MRT_BRIAN_DIR}/)

  # -fno-sanitize-recover: an UBSan report is a crash the fuzzer keeps.
  set(fuzz_flags -fsanitize=${sanitizers} -fno-sanitize-recover=all -fno-omit-frame-pointer -g -O1)

  add_library(brian_fuzz_core OBJECT ${MRT_BRIAN_CORE_SOURCES})
  target_compile_options(brian_fuzz_core PUBLIC ${fuzz_flags} -Wall -Wextra
                         PRIVATE -fsanitize=fuzzer-no-link)

  foreach(target fuzz_associations fuzz_behavior_list fuzz_crisp_input fuzz_definitions fuzz_engine
                 fuzz_list_file fuzz_rules fuzz_shapes)
    add_executable(brian_${target} ${MRT_BRIAN_DIR}/fuzz/${target}.cpp $<TARGET_OBJECTS:brian_fuzz_core>)
    target_compile_options(brian_${target} PRIVATE ${fuzz_flags} -fsanitize=fuzzer -Wall -Wextra)
    target_link_libraries(brian_${target} -fsanitize=fuzzer,${sanitizers})
    target_compile_definitions(brian_${target} PRIVATE MRT_BRIAN_FUZZ_DATA="${MRT_BRIAN_DIR}/test/data")
    set_target_properties(brian_${target} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${MRT_BRIAN_FUZZ_OUTPUT_DIR})
  endforeach()
endif()
