// Finder (manual §3.1): announces this Agora by UDP multicast and opens a
// TCP `link` channel to every Agora it hears of on another machine (internal).
#pragma once

#include <atomic>
#include <chrono>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "mrt_dcdt/config.h"
#include "net_util.h"

namespace mrt::dcdt {

class Agora;

class Finder {
 public:
  Finder(Agora* agora, const AgoraConfig& cfg, const std::string& inner_dir, int period_ms);
  ~Finder();
  void start();
  void stop();
  /// Agoras heard from during the last 3 s.
  int peers();
  std::vector<int> peer_ids();

 private:
  void loop();
  Agora* agora_;
  AgoraConfig cfg_;
  std::string host_key_;
  int period_ms_;
  int mcast_fd_ = -1, listen_fd_ = -1;
  std::atomic<bool> stop_{false};
  net::Waker waker_;
  std::thread thread_;
  std::mutex mutex_;
  std::map<int, std::chrono::steady_clock::time_point> seen_;
  std::map<int, std::chrono::steady_clock::time_point> last_dial_;
};

}  // namespace mrt::dcdt
