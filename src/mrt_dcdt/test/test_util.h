// Helpers shared by the DCDT tests: bounded waits and unique names.
#pragma once

#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <functional>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include "mrt_dcdt/agora.h"
#include "mrt_dcdt/channel.h"
#include "mrt_dcdt/testing/process.h"

namespace dcdt_test {

// The installed test support (Process, free_port, slurp ...).
using namespace mrt::dcdt::test_support;

/// Polls pred every 5 ms for at most timeout_ms; returns its last value.
inline bool WaitFor(const std::function<bool()>& pred, int timeout_ms = 3000) {
  auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeout_ms);
  while (std::chrono::steady_clock::now() < end) {
    if (pred()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return pred();
}

/// The temporary directories of this test program, removed when it exits.
struct TempDirRegistry {
  std::vector<std::string> dirs;
  ~TempDirRegistry() {
    std::error_code ec;
    for (const auto& d : dirs) std::filesystem::remove_all(d, ec);
  }
};
inline TempDirRegistry& TempDirs() {
  static TempDirRegistry r;
  return r;
}

/// A fresh directory for inner links (one per test, so tests never cross-talk).
inline std::string TempDir(const std::string& tag) {
  std::string t = "/tmp/dcdt_test_" + tag + "_" + std::to_string(::getpid()) + "_XXXXXX";
  char* p = ::mkdtemp(t.data());
  if (!p) return t;
  TempDirs().dirs.push_back(p);
  return p;
}

/// A channel that records what it is asked to send (for routing tests).
class FakeChannel : public mrt::dcdt::Channel {
 public:
  explicit FakeChannel(mrt::dcdt::ChannelMode m, int lvl = 0) {
    mode = m;
    level = lvl;
  }
  void start() override {}
  void stop() override {}
  bool send(const mrt::dcdt::MsgPtr& m) override {
    std::lock_guard<std::mutex> l(mu);
    sent.push_back(m);
    return true;
  }
  mrt::dcdt::ChannelStats stats() const override { return {}; }
  size_t count() {
    std::lock_guard<std::mutex> l(mu);
    return sent.size();
  }
  std::mutex mu;
  std::vector<mrt::dcdt::MsgPtr> sent;
};

inline mrt::dcdt::AgoraOptions IsolatedOptions(mrt::dcdt::PostOfficePolicy p = mrt::dcdt::PostOfficePolicy::SLWB) {
  mrt::dcdt::AgoraOptions o;
  o.inner_links = false;
  o.config.policy = p;
  return o;
}

}  // namespace dcdt_test
