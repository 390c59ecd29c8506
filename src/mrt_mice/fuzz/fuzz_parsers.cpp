// libFuzzer target of the mrt_mice file parsers (clang only): the YAML
// parameter file, the readings CSV and the calibration CSV. Anything but a
// ParseError escaping a parser is a bug.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "mrt_mice/mice_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    switch (data[0] % 3) {
      case 0:
        mrt::mice::parse_params(text, "fuzz.yaml");
        break;
      case 1: {
        std::istringstream in(text);
        mrt::mice::parse_readings_csv(in, "fuzz.csv");
        break;
      }
      default: {
        std::istringstream in(text);
        const auto runs = mrt::mice::parse_calibration_csv(in, "fuzz.csv");
        try {
          mrt::mice::calibrate(runs);
        } catch (const std::invalid_argument&) {
        }
      }
    }
  } catch (const mrt::common::ParseError&) {
  }
  return 0;
}
