// libFuzzer target (clang only): a BrianConfigs.ini and the whole load of
// the files it names (nine files, or errors); only ParseError may come out.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "mrt_brian/brian.h"
#include "mrt_brian/checker.h"
#include "mrt_common/parse_error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace fs = std::filesystem;
  static const fs::path dir = [] {
    const fs::path d = fs::temp_directory_path() / ("brian_fuzz_list_" + std::to_string(::getpid()));
    fs::create_directories(d);
    for (const auto& e : fs::directory_iterator(MRT_BRIAN_FUZZ_DATA "/synth"))
      fs::copy_file(e.path(), d / e.path().filename(), fs::copy_options::overwrite_existing);
    return d;
  }();
  const fs::path list = dir / "BrianConfigs.ini";
  {
    std::ofstream out(list, std::ios::binary);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    mrt::brian::Brian b(mrt::brian::ConfigFiles::from_list_file(list.string()));
    b.run({{"x", 25.0, 1.0}});
  } catch (const mrt::common::ParseError&) {
  }
  mrt::brian::Checker().check_path(list.string());
  return 0;
}
