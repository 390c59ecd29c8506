// InnerLinkManager (manual §3.1): the Agoras of one machine reach each other
// through Unix datagram sockets `<dir>/<agora id>.sock` (internal header).
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "mrt_dcdt/msg.h"
#include "net_util.h"

namespace mrt::dcdt {

class InnerLinkManager {
 public:
  using ReceiveFn = std::function<void(std::shared_ptr<Msg>)>;
  InnerLinkManager(std::string dir, int agora_id, ReceiveFn rx);
  ~InnerLinkManager();
  void start();
  void stop();
  /// Sends msg to every other Agora of the directory.
  void send(const Msg& msg);
  int peers();
  /// Agora ids of the peers (from their socket names).
  std::vector<int> peer_ids();
  uint64_t errors() const { return errors_; }

 private:
  void loop();
  void refresh_peers(bool force);

  std::string dir_, path_;
  int agora_id_;
  ReceiveFn rx_;
  int fd_ = -1;
  std::atomic<bool> stop_{false};
  std::atomic<uint64_t> errors_{0};
  net::Waker waker_;
  std::thread thread_;
  std::mutex peers_mutex_;
  std::vector<std::string> peers_;
  int64_t peers_time_ = 0;
};

}  // namespace mrt::dcdt
