# The libFuzzer targets of mrt_dcdt (see CMakeLists.txt in this directory):
# the frame decoder, the Agora configuration parser and the XML codec. The
# library's sources are compiled again into an object library with
# -fsanitize=fuzzer-no-link,address,undefined, so libFuzzer gets coverage
# from inside the library and ASan/UBSan see into it; only the programs link
# the libFuzzer runtime. Included by ../CMakeLists.txt when the workspace
# compiler is clang, else by CMakeLists.txt here (a clang++ sub-build).
# Inputs: MRT_DCDT_DIR (the package directory), MRT_DCDT_DTD_SOURCE (the
# generated DTD source), MRT_DCDT_FUZZ_OUTPUT_DIR (where the programs go);
# MRT_DCDT_FUZZ_LIBRARIES (libxml2) when not set by the including scope.
set(sanitizers address,undefined)
include(CheckCXXSourceCompiles)
set(CMAKE_REQUIRED_FLAGS "-fsanitize=fuzzer,${sanitizers}")
check_cxx_source_compiles([=[
#include <cstddef>
#include <cstdint>
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t*, std::size_t) { return 0; }
]=] MRT_DCDT_HAVE_LIBFUZZER)
unset(CMAKE_REQUIRED_FLAGS)
if(NOT MRT_DCDT_HAVE_LIBFUZZER)
  message(WARNING "mrt_dcdt: ${CMAKE_CXX_COMPILER} cannot link -fsanitize=fuzzer "
                  "(Debian: install libclang-rt-dev); the fuzz targets are not built")
else()
  include(${MRT_DCDT_DIR}/cmake/core_sources.cmake)
  list(TRANSFORM MRT_DCDT_CORE_SOURCES PREPEND ${MRT_DCDT_DIR}/)
  if(NOT MRT_DCDT_FUZZ_LIBRARIES)
    set(MRT_DCDT_FUZZ_LIBRARIES ${LIBXML2_LIBRARIES})
  endif()

  # -fno-sanitize-recover: an UBSan report is a crash the fuzzer keeps.
  set(fuzz_flags -fsanitize=${sanitizers} -fno-sanitize-recover=all -fno-omit-frame-pointer -g -O1)

  add_library(dcdt_fuzz_core OBJECT ${MRT_DCDT_CORE_SOURCES} ${MRT_DCDT_DTD_SOURCE})
  target_compile_options(dcdt_fuzz_core PUBLIC ${fuzz_flags} -Wall -Wextra
                         PRIVATE -fsanitize=fuzzer-no-link)

  foreach(t frame config xml)
    add_executable(dcdt_fuzz_${t} ${MRT_DCDT_DIR}/fuzz/fuzz_${t}.cpp $<TARGET_OBJECTS:dcdt_fuzz_core>)
    target_compile_options(dcdt_fuzz_${t} PRIVATE ${fuzz_flags} -fsanitize=fuzzer -Wall -Wextra)
    target_link_libraries(dcdt_fuzz_${t} -fsanitize=fuzzer,${sanitizers} ${MRT_DCDT_FUZZ_LIBRARIES} Threads::Threads)
    set_target_properties(dcdt_fuzz_${t} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${MRT_DCDT_FUZZ_OUTPUT_DIR})
  endforeach()
endif()
