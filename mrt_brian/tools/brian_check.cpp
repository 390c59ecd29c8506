// brian_check <dir | BrianConfigs.ini>
// The checker of manual §10.4.7: prints every problem as `file:line: message`.
// Exit 0 when clean, 1 when anything is reported, 2 on usage errors.
#include <cstdio>
#include <filesystem>
#include <string>
#include <system_error>

#include "mrt_brian/checker.h"

int main(int argc, char** argv) {
  if (argc != 2 || std::string(argv[1]) == "-h" || std::string(argv[1]) == "--help") {
    std::fprintf(stderr, "usage: brian_check <dir | BrianConfigs.ini>\n");
    return 2;
  }
  std::error_code ec;
  if (!std::filesystem::exists(argv[1], ec)) {
    std::fprintf(stderr, "brian_check: %s: %s\n", argv[1],
                 ec ? ec.message().c_str() : "no such file or directory");
    return 2;
  }
  try {
    const auto diags = mrt::brian::Checker().check_path(argv[1]);
    for (const auto& d : diags) std::printf("%s\n", d.str().c_str());
    return diags.empty() ? 0 : 1;
  } catch (const std::exception& e) {  // not a finding in the rule base: the tool failed
    std::fprintf(stderr, "brian_check: %s: %s\n", argv[1], e.what());
    return 2;
  }
}
