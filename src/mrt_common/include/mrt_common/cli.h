// Shared pieces of the stack's command-line tools (header-only, ROS-free):
//   parse_cli()  CLI11 parsing with the stack's exit codes: --help prints to
//                stdout and gives 0, any usage error prints
//                "<tool>: <message>" and a hint to stderr and gives 2;
//   Progress     a "tool: 42% ETA 3 s" line on stderr, only when stderr is a
//                terminal (nothing at all when it is a file or a pipe).
// Needs CLI11 (Debian's libcli11-dev, header-only).
#pragma once

#include <unistd.h>

#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

namespace mrt::cli {

// Exit code of every usage error (unknown option, missing value, bad number).
constexpr int kUsageError = 2;

// Parses argv into `app`. Returns -1 when the tool should go on, otherwise
// the exit code main() must return (0 after --help, 2 on a usage error).
inline int parse_cli(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // CLI11 checks required options before unknown ones: name the unknown first.
    const auto extra = app.remaining(true);
    std::cerr << app.get_name() << ": " << (extra.empty() ? e.what() : CLI::ExtrasError(extra).what()) << "\n"
              << "Run with --help for more information.\n";
    return kUsageError;
  }
  return -1;
}

// Progress of a long loop: update(done) with done in [0, total]. Prints at
// most 5 times a second, and only when stderr is a terminal.
class Progress {
 public:
  Progress(std::string tool, double total)
      : tool_(std::move(tool)), total_(total), enabled_(isatty(STDERR_FILENO) == 1),
        start_(Clock::now()), last_(start_) {}
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;
  ~Progress() { finish(); }

  void update(double done) {
    if (!enabled_ || !(total_ > 0)) return;
    const auto now = Clock::now();
    if (shown_ && now - last_ < std::chrono::milliseconds(200)) return;
    last_ = now;
    shown_ = true;
    const double f = std::fmin(std::fmax(done / total_, 0.0), 1.0);
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    std::fprintf(stderr, "\r%s: %3.0f%%", tool_.c_str(), 100.0 * f);
    if (f > 0.0) std::fprintf(stderr, " ETA %.0f s   ", elapsed * (1.0 - f) / f);
    std::fflush(stderr);
  }

  // Ends the line (once), so later messages start on a new one.
  void finish() {
    if (!shown_) return;
    std::fputc('\n', stderr);
    shown_ = false;
  }

 private:
  using Clock = std::chrono::steady_clock;
  std::string tool_;
  double total_;
  bool enabled_;
  bool shown_ = false;
  Clock::time_point start_, last_;
};

}  // namespace mrt::cli

