// libFuzzer target of the calibration-file parser (clang only). Anything
// but a ParseError escaping parse_calibration is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "mrt_common/parse_error.h"
#include "mrt_recvision/calibration.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    mrt::recvision::parse_calibration(text, "/nonexistent/fuzz.yaml");
  } catch (const mrt::common::ParseError&) {
  }
  return 0;
}
