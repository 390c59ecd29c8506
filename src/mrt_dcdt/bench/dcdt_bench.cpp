// DCDT benchmark (no ROS): throughput and one-way latency of a raw DCDT TCP
// link on loopback (two Agoras in one process joined by an `ip link`
// channel), of the UDP link, of the inner link (two Agoras of one machine),
// and of the bridge's DCDT side (inner link + XML decode). Baseline in the
// same run: a plain TCP socket on loopback carrying the same small payload,
// so the ratios survive a noisy shared machine. Prints `name: value unit`
// lines. The Agora -> bridge -> ROS path is measured by mrt_dcdt_bridge's
// dcdt_bridge_bench.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <thread>
#include <vector>

#include "mrt_dcdt/agora.h"
#include "mrt_dcdt/testing/link_bench.h"
#include "mrt_dcdt/testing/process.h"
#include "mrt_dcdt/xml_message.h"

using namespace mrt::dcdt;
using namespace mrt::dcdt::test_support;
using Clock = std::chrono::steady_clock;

namespace {

// Baseline: a plain TCP stream, 16-byte records with a send timestamp.
BenchResult raw_tcp(int n_throughput, int n_latency) {
  BenchResult r;
  int l = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ::bind(l, reinterpret_cast<sockaddr*>(&a), sizeof a);
  ::listen(l, 1);
  socklen_t al = sizeof a;
  getsockname(l, reinterpret_cast<sockaddr*>(&a), &al);
  int c = ::socket(AF_INET, SOCK_STREAM, 0);
  ::connect(c, reinterpret_cast<sockaddr*>(&a), sizeof a);
  int s = ::accept(l, nullptr, nullptr);
  int one = 1;
  setsockopt(c, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
  std::vector<double> lat;
  std::atomic<size_t> got{0};
  std::thread rx([&] {
    char buf[65536];
    size_t have = 0;
    const size_t total = static_cast<size_t>(n_throughput + n_latency) * 16;
    size_t done = 0;
    while (done < total) {
      ssize_t k = ::read(s, buf + have, sizeof buf - have);
      if (k <= 0) break;
      have += static_cast<size_t>(k);
      size_t off = 0;
      for (; off + 16 <= have; off += 16) {
        int64_t ts;
        std::memcpy(&ts, buf + off, 8);
        if (ts != 0) lat.push_back((now_ns() - ts) / 1e3);
        ++got;
        done += 16;
      }
      std::memmove(buf, buf + off, have - off);
      have -= off;
    }
  });
  char rec[16] = {0};
  auto t0 = Clock::now();
  for (int i = 0; i < n_throughput; ++i) [[maybe_unused]] ssize_t w = ::write(c, rec, 16);
  while (got < static_cast<size_t>(n_throughput)) std::this_thread::yield();
  r.rate = n_throughput / std::chrono::duration<double>(Clock::now() - t0).count();
  for (int i = 0; i < n_latency; ++i) {
    int64_t ts = now_ns();
    std::memcpy(rec, &ts, 8);
    [[maybe_unused]] ssize_t w = ::write(c, rec, 16);
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  rx.join();
  r.p50 = percentile(lat, 0.50);
  r.p99 = percentile(lat, 0.99);
  ::close(c);
  ::close(s);
  ::close(l);
  return r;
}

}  // namespace

int main() {
  // DCDT_BENCH_MESSAGES overrides the throughput message count (default 200000).
  const char* env = std::getenv("DCDT_BENCH_MESSAGES");
  const int kThroughput = env ? std::max(1000, std::atoi(env)) : 200000, kLatency = 5000;
  const std::string small(16, 'x');

  BenchResult raw = raw_tcp(kThroughput, kLatency);
  print_result("baseline_raw_tcp", raw);

  BenchResult tcp;
  {
    const int pa = free_port(), pb = free_port();
    Agora a(tcp_link_options(pa, pb)), b(tcp_link_options(pb, pa));
    tcp = measure_link(a, b, DCDT_DW_GUARANTEED, kThroughput, kLatency, small);
    print_result("dcdt_tcp_link", tcp);
    BenchResult udp = measure_link(a, b, DCDT_DW_NONE, kThroughput / 4, kLatency, small);
    print_result("dcdt_udp_link", udp);
    std::printf("dcdt_udp_link_delivered_in_burst: %.1f %%\n", 100.0 * udp.received / (kThroughput / 4));
  }
  {
    char dir[] = "/tmp/dcdt_bench_XXXXXX";
    ::mkdtemp(dir);
    AgoraOptions o;
    o.inner_dir = dir;
    Agora a(o), b(o);
    BenchResult inner = measure_link(a, b, DCDT_DW_GUARANTEED, kThroughput / 4, kLatency, small);
    print_result("dcdt_inner_link", inner);
    XmlMessage x;
    x.sec = 1700000000;
    x.sensor = "omnivision";
    x.objects.push_back({"ball", "Ball", {{"distance", 2.4, "", 0.1, 0.9}, {"bearing", -0.35, "", 0.02, 0.9}}});
    BenchResult bridge = measure_link(a, b, DCDT_DW_GUARANTEED, 20000, 2000, encode_xml(x), true);
    print_result("legacy_agora_to_bridge_member_xml", bridge);
  }
  std::printf("dcdt_tcp_vs_raw_tcp_throughput_ratio: %.3f ratio\n", tcp.rate / raw.rate);
  std::printf("dcdt_tcp_vs_raw_tcp_p99_ratio: %.3f ratio\n", raw.p99 > 0 ? tcp.p99 / raw.p99 : 0.0);
  std::printf("dcdt_tcp_meets_50k_msgs_target: %d bool\n", tcp.rate >= 50000 ? 1 : 0);
  std::printf("dcdt_tcp_meets_p99_1ms_target: %d bool\n", tcp.p99 < 1000 ? 1 : 0);
  return 0;
}
