// Runs a command-line tool as a program, for the tests of the stack's
// CLIs (`--help` exits 0, usage errors exit 2 with "<tool>: " on stderr and
// nothing on stdout). Header-only, POSIX (popen).
#pragma once

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace mrt::common::testing {

struct Output {
  int code = -1;
  std::string text;
};

// Runs `cmd` through the shell; `text` is what it wrote on the stream left
// on the pipe (the command's own redirections pick stdout or stderr).
inline Output run(const std::string& cmd) {
  Output o;
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return o;
  std::array<char, 4096> buf{};
  for (std::size_t n; (n = std::fread(buf.data(), 1, buf.size(), p)) > 0;) o.text.append(buf.data(), n);
  const int status = pclose(p);
  o.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return o;
}

inline Output help(const std::string& tool) { return run("'" + tool + "' --help 2>/dev/null"); }
// stderr only; stdout must stay empty on a usage error, so it is checked apart.
inline Output err(const std::string& tool, const std::string& args) {
  return run("'" + tool + "' " + args + " 2>&1 >/dev/null");
}
inline std::string out(const std::string& tool, const std::string& args) {
  return run("'" + tool + "' " + args + " 2>/dev/null").text;
}

}  // namespace mrt::common::testing
