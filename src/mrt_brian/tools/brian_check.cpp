// brian_check <dir | BrianConfigs.ini>
// The checker of manual §10.4.7: prints every problem as `file:line: message`.
// Exit 0 when clean, 1 when anything is reported, 2 on usage errors.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <system_error>

#include "mrt_brian/checker.h"
#include "mrt_common/cli.h"

int main(int argc, char** argv) {
  std::string path;
  CLI::App app{"Checks a Mr. BRIAN configuration (manual 10.4.7): prints every problem as\n"
               "`file:line: message`; exit 0 when clean, 1 when anything is reported, 2 on usage errors.",
               "brian_check"};
  app.add_option("config", path, "configuration directory or its BrianConfigs.ini")->required();
  if (const int rc = mrt::cli::parse_cli(app, argc, argv); rc >= 0) return rc;
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    std::fprintf(stderr, "brian_check: %s: %s\n", path.c_str(),
                 ec ? ec.message().c_str() : "no such file or directory");
    return 2;
  }
  try {
    const auto diags = mrt::brian::Checker().check_path(path);
    for (const auto& d : diags) std::printf("%s\n", d.str().c_str());
    return diags.empty() ? 0 : 1;
  } catch (const std::exception& e) {  // not a finding in the rule base: the tool failed
    std::fprintf(stderr, "brian_check: %s: %s\n", path.c_str(), e.what());
    return 2;
  }
}
