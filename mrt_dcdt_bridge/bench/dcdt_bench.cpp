// DCDT benchmark: throughput and one-way latency of a raw DCDT TCP link on
// loopback (two Agoras in one process joined by an `ip link` channel), of
// the inner link (two Agoras of one machine), and of the bridge's DCDT side
// (inner link + XML decode + conversion input). Baseline in the same run: a
// plain TCP socket on loopback carrying the same small payload, so the
// ratios survive a noisy shared machine. Prints `name: value unit` lines.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <thread>
#include <vector>

#include <mrt_msgs/Percept.h>
#include <ros/ros.h>
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <mutex>

#include "mrt_dcdt_bridge/agora.h"
#include "mrt_dcdt_bridge/xml_message.h"

extern char** environ;

using namespace mrt::dcdt;
using Clock = std::chrono::steady_clock;

namespace {

class Sender : public Member {
 public:
  explicit Sender(Agora* a) : Member(a) {}
  void DoYourJob(int) override {}
  void Send(int type, int warranty, const std::string& payload) {
    Msg* m = CreateMsg(type, warranty);
    m->SetPayload(payload);
    ShareMsg(m);
  }
};

int FreePort() {
  int t = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ::bind(t, reinterpret_cast<sockaddr*>(&a), sizeof a);
  socklen_t l = sizeof a;
  getsockname(t, reinterpret_cast<sockaddr*>(&a), &l);
  ::close(t);
  return ntohs(a.sin_port);
}

double Percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<size_t>(p * v.size()))];
}

struct Result {
  double rate = 0, p50 = 0, p99 = 0;
  size_t received = 0;
};

// Sender Agora -> receiver Agora; the receiver's mailbox is drained by a thread.
Result Measure(Agora& a, Agora& b, int warranty, int n_throughput, int n_latency, const std::string& payload,
               bool decode_xml = false) {
  Result r;
  Sender s(&a);
  a.AddMember(&s);
  MailBox box;
  box.member_id = 4242;
  b.GetPostOffice().Register(&box);
  b.GetPostOffice().Subscribe(4242, 1, DCDT_ALL_MSG);
  b.GetPostOffice().Subscribe(4242, 2, DCDT_ALL_MSG);
  std::atomic<size_t> got1{0}, got2{0};
  std::vector<double> lat;
  lat.reserve(n_latency);
  std::atomic<bool> stop{false};
  std::thread rx([&] {
    while (!stop) {
      b.GetPostOffice().WaitForMail(&box, &stop, std::chrono::milliseconds(20));
      while (auto m = b.GetPostOffice().Pop(&box)) {
        if (decode_xml) DecodeXml(m->PayloadString());
        if (m->ReadType() == 1) {
          ++got1;
        } else {
          lat.push_back((Now() - m->ReadCreationTime()) / 1e3);  // µs
          ++got2;
        }
      }
    }
  });
  // Warm-up: until the path delivers.
  for (int i = 0; i < 200 && got1 == 0; ++i) {
    s.Send(1, warranty, payload);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  const size_t base = got1;
  auto t0 = Clock::now();
  const auto give_up = t0 + std::chrono::seconds(20);
  for (int i = 0; i < n_throughput; ++i) {
    s.Send(1, warranty, payload);
    // Keep at most ~50k in flight (mailbox and send queues are bounded).
    while (static_cast<size_t>(i) > got1 - base + 50000 && Clock::now() < give_up) std::this_thread::yield();
  }
  // Until everything arrived, or nothing arrived for 300 ms (a lossy path).
  auto last_change = Clock::now();
  auto last_end = t0;
  size_t last = got1;
  while (got1 - base < static_cast<size_t>(n_throughput) && Clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::microseconds(200));
    if (got1 != last) {
      last = got1;
      last_change = last_end = Clock::now();
    } else if (Clock::now() - last_change > std::chrono::milliseconds(300)) {
      break;
    }
  }
  if (got1 - base >= static_cast<size_t>(n_throughput)) last_end = Clock::now();
  r.received = got1 - base;
  r.rate = r.received / std::chrono::duration<double>(last_end - t0).count();
  // Latency: one message every 200 µs, one way, creation -> receiver's Member.
  for (int i = 0; i < n_latency; ++i) {
    s.Send(2, warranty, payload);
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  const auto d2 = Clock::now() + std::chrono::seconds(5);
  while (got2 < static_cast<size_t>(n_latency) && Clock::now() < d2) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  stop = true;
  rx.join();
  r.p50 = Percentile(lat, 0.50);
  r.p99 = Percentile(lat, 0.99);
  b.GetPostOffice().Unregister(&box);
  return r;
}

// Baseline: a plain TCP stream, 16-byte records with a send timestamp.
Result RawTcp(int n_throughput, int n_latency) {
  Result r;
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
        if (ts != 0) lat.push_back((Now() - ts) / 1e3);
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
    int64_t ts = Now();
    std::memcpy(rec, &ts, 8);
    [[maybe_unused]] ssize_t w = ::write(c, rec, 16);
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  rx.join();
  r.p50 = Percentile(lat, 0.50);
  r.p99 = Percentile(lat, 0.99);
  ::close(c);
  ::close(s);
  ::close(l);
  return r;
}

pid_t Spawn(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  // Children's logs go to /dev/null: stdout carries only `name: value unit` lines.
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = -1;
  const int rc = posix_spawnp(&pid, argv[0], &fa, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  return rc == 0 ? pid : -1;
}

void Stop(pid_t pid) {
  if (pid <= 0) return;
  ::kill(pid, SIGINT);
  for (int i = 0; i < 300; ++i) {
    int st;
    if (waitpid(pid, &st, WNOHANG) == pid) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ::kill(pid, SIGKILL);
  int st;
  waitpid(pid, &st, 0);
}

// Legacy Agora (this process) -> dcdt_bridge_node (a child process, private
// rosmaster on a free loopback port) -> ROS subscriber (this process).
bool BridgeToRos(Result* out, int n_throughput, int n_latency) {
  char dir[] = "/tmp/dcdt_bench_ros_XXXXXX";
  if (!::mkdtemp(dir)) return false;
  const std::string d = dir;
  const int port = FreePort();
  const std::string uri = "http://127.0.0.1:" + std::to_string(port);
  ::setenv("ROS_MASTER_URI", uri.c_str(), 1);
  ::setenv("ROS_HOME", d.c_str(), 1);
  ::setenv("ROS_LOG_DIR", d.c_str(), 1);
  ::setenv("ROS_IP", "127.0.0.1", 1);
  {
    std::ofstream m(d + "/mapping.yaml");
    m << "to_ros:\n  - {type: MSG_FROM_VISION, topic: /dcdt_bench/percepts, kind: percept}\n";
  }
  pid_t master = Spawn({"rosmaster", "--core", "-p", std::to_string(port)});
  if (master <= 0) return false;
  pid_t bridge = Spawn({DCDT_BRIDGE_NODE, "__name:=dcdt_bench_bridge", "_mapping:=" + d + "/mapping.yaml",
                        "_inner_dir:=" + d, "_queue_size:=100000"});
  int argc = 0;
  ros::init(argc, nullptr, "dcdt_bench", ros::init_options::NoSigintHandler | ros::init_options::AnonymousName);
  bool ok = false;
  for (int i = 0; i < 200 && !(ok = ros::master::check()); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  if (ok) {
    std::atomic<size_t> got1{0};
    std::mutex m;
    std::vector<double> lat;
    ros::NodeHandle nh;
    auto sub = nh.subscribe<mrt_msgs::Percept>(
        "/dcdt_bench/percepts", 100000, [&](const mrt_msgs::Percept::ConstPtr& p) {
          if (p->sensor == "latency") {
            std::lock_guard<std::mutex> l(m);
            lat.push_back((Now() - static_cast<int64_t>(p->header.stamp.toNSec())) / 1e3);
          } else {
            ++got1;
          }
        });
    ros::AsyncSpinner spinner(1);
    spinner.start();
    AgoraOptions o;
    o.inner_dir = d;
    Agora a(o);
    Sender s(&a);
    a.AddMember(&s);
    XmlMessage x;
    x.sensor = "throughput";
    x.objects.push_back({"ball", "Ball", {{"distance", 2.4, "", 0.1, 0.9}, {"bearing", -0.35, "", 0.02, 0.9}}});
    const std::string payload = EncodeXml(x);
    auto wait_until = [](const std::function<bool()>& f, double s) {
      auto end = Clock::now() + std::chrono::milliseconds(static_cast<long>(s * 1000));
      while (Clock::now() < end && !f()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
      return f();
    };
    ok = wait_until([&] { return a.Stats().inner_peers >= 1 && sub.getNumPublishers() >= 1; }, 20);
    for (int i = 0; ok && i < 400 && got1 == 0; ++i) {  // warm-up until the path delivers
      s.Send(MSG_FROM_VISION, DCDT_DW_GUARANTEED, payload);
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    ok = ok && got1 > 0;
    if (ok) {
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
      const size_t base = got1;
      auto t0 = Clock::now();
      for (int i = 0; i < n_throughput; ++i) {
        s.Send(MSG_FROM_VISION, DCDT_DW_GUARANTEED, payload);
        while (static_cast<size_t>(i) > got1 - base + 2000) std::this_thread::yield();
      }
      wait_until([&] { return got1 - base >= static_cast<size_t>(n_throughput); }, 10);
      out->received = got1 - base;
      out->rate = out->received / std::chrono::duration<double>(Clock::now() - t0).count();
      for (int i = 0; i < n_latency; ++i) {
        XmlMessage y = x;
        y.sensor = "latency";
        const int64_t now = Now();
        y.sec = now / 1000000000;
        y.nsec = static_cast<uint32_t>(now % 1000000000);
        s.Send(MSG_FROM_VISION, DCDT_DW_GUARANTEED, EncodeXml(y));
        std::this_thread::sleep_for(std::chrono::microseconds(1000));
      }
      wait_until([&] { std::lock_guard<std::mutex> l(m); return lat.size() >= static_cast<size_t>(n_latency); }, 5);
      std::lock_guard<std::mutex> l(m);
      out->p50 = Percentile(lat, 0.5);
      out->p99 = Percentile(lat, 0.99);
    }
    spinner.stop();
    sub.shutdown();
    ros::shutdown();
  }
  Stop(bridge);
  Stop(master);
  return ok;
}

void Print(const char* name, const Result& r) {
  std::printf("%s_throughput: %.0f msg/s\n", name, r.rate);
  std::printf("%s_latency_p50: %.1f us\n", name, r.p50);
  std::printf("%s_latency_p99: %.1f us\n", name, r.p99);
}

}  // namespace

int main() {
  // DCDT_BENCH_MESSAGES overrides the throughput message count (default 200000).
  const char* env = std::getenv("DCDT_BENCH_MESSAGES");
  const int kThroughput = env ? std::max(1000, std::atoi(env)) : 200000, kLatency = 5000;
  const std::string small(16, 'x');

  Result raw = RawTcp(kThroughput, kLatency);
  Print("baseline_raw_tcp", raw);

  Result tcp;
  {
    const int pa = FreePort(), pb = FreePort();
    auto opts = [](int l, int r) {
      AgoraOptions o;
      o.network = true;
      o.inner_links = false;
      o.finder = false;
      o.config = ParseAgoraConfig("127.0.0.1 239.255.0.1 9\nPostOffice: SLWB\nip link 0 127.0.0.1 " +
                                      std::to_string(l) + " 127.0.0.1 " + std::to_string(r) + "\n",
                                  "bench.cfg");
      return o;
    };
    Agora a(opts(pa, pb)), b(opts(pb, pa));
    tcp = Measure(a, b, DCDT_DW_GUARANTEED, kThroughput, kLatency, small);
    Print("dcdt_tcp_link", tcp);
    Result udp = Measure(a, b, DCDT_DW_NONE, kThroughput / 4, kLatency, small);
    Print("dcdt_udp_link", udp);
    std::printf("dcdt_udp_link_delivered_in_burst: %.1f %%\n", 100.0 * udp.received / (kThroughput / 4));
  }
  {
    char dir[] = "/tmp/dcdt_bench_XXXXXX";
    ::mkdtemp(dir);
    AgoraOptions o;
    o.inner_dir = dir;
    Agora a(o), b(o);
    Result inner = Measure(a, b, DCDT_DW_GUARANTEED, kThroughput / 4, kLatency, small);
    Print("dcdt_inner_link", inner);
    XmlMessage x;
    x.sec = 1700000000;
    x.sensor = "omnivision";
    x.objects.push_back({"ball", "Ball", {{"distance", 2.4, "", 0.1, 0.9}, {"bearing", -0.35, "", 0.02, 0.9}}});
    Result bridge = Measure(a, b, DCDT_DW_GUARANTEED, 20000, 2000, EncodeXml(x), true);
    Print("legacy_agora_to_bridge_member_xml", bridge);
  }
  Result ros_path;
  if (BridgeToRos(&ros_path, 20000, 2000)) {
    Print("legacy_agora_to_bridge_to_ros_subscriber", ros_path);
    std::printf("bridge_to_ros_vs_dcdt_tcp_p50_ratio: %.3f ratio\n", tcp.p50 > 0 ? ros_path.p50 / tcp.p50 : 0.0);
  } else {
    std::printf("# legacy_agora_to_bridge_to_ros_subscriber: skipped (no rosmaster or the bridge did not start)\n");
  }
  std::printf("dcdt_tcp_vs_raw_tcp_throughput_ratio: %.3f ratio\n", tcp.rate / raw.rate);
  std::printf("dcdt_tcp_vs_raw_tcp_p99_ratio: %.3f ratio\n", raw.p99 > 0 ? tcp.p99 / raw.p99 : 0.0);
  std::printf("dcdt_tcp_meets_50k_msgs_target: %d bool\n", tcp.rate >= 50000 ? 1 : 0);
  std::printf("dcdt_tcp_meets_p99_1ms_target: %d bool\n", tcp.p99 < 1000 ? 1 : 0);
  return 0;
}
