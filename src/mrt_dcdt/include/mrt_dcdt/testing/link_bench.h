// Benchmark support (header-only, no ROS): throughput and one-way latency
// of a DCDT path between two Agoras, measured by a sending Member in the
// first and a mailbox drained by a thread in the second. Used by the
// benchmarks of mrt_dcdt (dcdt_bench) and mrt_dcdt_bridge (dcdt_bridge_bench,
// for its baseline in the same run).
#pragma once

#include <algorithm>
#include <cstdio>
#include <atomic>
#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "mrt_dcdt/agora.h"
#include "mrt_dcdt/config.h"
#include "mrt_dcdt/xml_message.h"

namespace mrt::dcdt::test_support {

using BenchClock = std::chrono::steady_clock;

class BenchSender : public Member {
 public:
  explicit BenchSender(Agora* a) : Member(a) {}
  void do_your_job(int) override {}
  void send(int type, int warranty, const std::string& payload) {
    Msg* m = create_msg(type, warranty);
    m->set_payload(payload);
    share_msg(m);
  }
};

inline double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<size_t>(p * v.size()))];
}

struct BenchResult {
  double rate = 0, p50 = 0, p99 = 0;
  size_t received = 0;
};

// Sender Agora -> receiver Agora; the receiver's mailbox is drained by a thread.
inline BenchResult measure_link(Agora& a, Agora& b, int warranty, int n_throughput, int n_latency,
                                const std::string& payload, bool decode = false) {
  BenchResult r;
  BenchSender s(&a);
  a.add_member(&s);
  MailBox box;
  box.member_id = 4242;
  b.post_office().register_mailbox(&box);
  b.post_office().subscribe(4242, 1, DCDT_ALL_MSG);
  b.post_office().subscribe(4242, 2, DCDT_ALL_MSG);
  std::atomic<size_t> got1{0}, got2{0};
  std::vector<double> lat;
  lat.reserve(n_latency);
  std::atomic<bool> stop{false};
  std::thread rx([&] {
    while (!stop) {
      b.post_office().wait_for_mail(&box, &stop, std::chrono::milliseconds(20));
      while (auto m = b.post_office().pop(&box)) {
        if (decode) decode_xml(m->payload_string());
        if (m->type() == 1) {
          ++got1;
        } else {
          lat.push_back((now_ns() - m->creation_time()) / 1e3);  // µs
          ++got2;
        }
      }
    }
  });
  // Warm-up: until the path delivers.
  for (int i = 0; i < 200 && got1 == 0; ++i) {
    s.send(1, warranty, payload);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  const size_t base = got1;
  auto t0 = BenchClock::now();
  const auto give_up = t0 + std::chrono::seconds(20);
  for (int i = 0; i < n_throughput; ++i) {
    s.send(1, warranty, payload);
    // Keep at most ~50k in flight (mailbox and send queues are bounded).
    while (static_cast<size_t>(i) > got1 - base + 50000 && BenchClock::now() < give_up) std::this_thread::yield();
  }
  // Until everything arrived, or nothing arrived for 300 ms (a lossy path).
  auto last_change = BenchClock::now();
  auto last_end = t0;
  size_t last = got1;
  while (got1 - base < static_cast<size_t>(n_throughput) && BenchClock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::microseconds(200));
    if (got1 != last) {
      last = got1;
      last_change = last_end = BenchClock::now();
    } else if (BenchClock::now() - last_change > std::chrono::milliseconds(300)) {
      break;
    }
  }
  if (got1 - base >= static_cast<size_t>(n_throughput)) last_end = BenchClock::now();
  r.received = got1 - base;
  r.rate = r.received / std::chrono::duration<double>(last_end - t0).count();
  // Latency: one message every 200 µs, one way, creation -> receiver's Member.
  for (int i = 0; i < n_latency; ++i) {
    s.send(2, warranty, payload);
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  const auto d2 = BenchClock::now() + std::chrono::seconds(5);
  while (got2 < static_cast<size_t>(n_latency) && BenchClock::now() < d2) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  stop = true;
  rx.join();
  r.p50 = percentile(lat, 0.50);
  r.p99 = percentile(lat, 0.99);
  b.post_office().unregister_mailbox(&box);
  return r;
}

/// Options of one of two NETWORK Agoras joined by an `ip link` channel on
/// loopback (local port l, remote port r), without inner links and Finder.
inline AgoraOptions tcp_link_options(int l, int r) {
  AgoraOptions o;
  o.network = true;
  o.inner_links = false;
  o.finder = false;
  o.config = parse_agora_config("127.0.0.1 239.255.0.1 9\nPostOffice: SLWB\nip link 0 127.0.0.1 " + std::to_string(l) +
                                    " 127.0.0.1 " + std::to_string(r) + "\n",
                                "bench.cfg");
  return o;
}

/// Prints a result as `name_throughput`, `name_latency_p50/p99` lines.
inline void print_result(const char* name, const BenchResult& r) {
  std::printf("%s_throughput: %.0f msg/s\n", name, r.rate);
  std::printf("%s_latency_p50: %.1f us\n", name, r.p50);
  std::printf("%s_latency_p99: %.1f us\n", name, r.p99);
}

}  // namespace mrt::dcdt::test_support
