// DCDT bridge benchmark: a legacy Agora (this process) -> dcdt_bridge_node
// (a child process, private rosmaster on a free loopback port) -> a ROS
// subscriber (this process), throughput and one-way latency of XML percepts.
// Baseline in the same run: a raw DCDT TCP link between two Agoras (the same
// measurement as mrt_dcdt's dcdt_bench), so the ratio survives a noisy
// shared machine. Prints `name: value unit` lines.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <mrt_msgs/Percept.h>
#include <ros/ros.h>

#include "mrt_dcdt/agora.h"
#include "mrt_dcdt/testing/link_bench.h"
#include "mrt_dcdt/testing/process.h"
#include "mrt_dcdt/xml_message.h"

extern char** environ;

using namespace mrt::dcdt;
using namespace mrt::dcdt::test_support;
using Clock = std::chrono::steady_clock;

namespace {

pid_t spawn(const std::vector<std::string>& args) {
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

void stop(pid_t pid) {
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


bool wait_until(const std::function<bool()>& f, double seconds) {
  auto end = Clock::now() + std::chrono::milliseconds(static_cast<long>(seconds * 1000));
  while (Clock::now() < end && !f()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  return f();
}

// The private ROS graph: a rosmaster on a free port and the bridge node
// (mapping MSG_FROM_VISION -> /dcdt_bench/percepts, inner links in dir).
struct RosGraph {
  pid_t master = -1, bridge = -1;
  ~RosGraph() {
    stop(bridge);
    stop(master);
  }
  bool start(const std::string& dir) {
    const int port = free_port();
    const std::string uri = "http://127.0.0.1:" + std::to_string(port);
    ::setenv("ROS_MASTER_URI", uri.c_str(), 1);
    ::setenv("ROS_HOME", dir.c_str(), 1);
    ::setenv("ROS_LOG_DIR", dir.c_str(), 1);
    ::setenv("ROS_IP", "127.0.0.1", 1);
    {
      std::ofstream m(dir + "/mapping.yaml");
      m << "to_ros:\n  - {type: MSG_FROM_VISION, topic: /dcdt_bench/percepts, kind: percept}\n";
    }
    master = spawn({"rosmaster", "--core", "-p", std::to_string(port)});
    if (master <= 0) return false;
    bridge = spawn({DCDT_BRIDGE_NODE, "__name:=dcdt_bench_bridge", "_mapping:=" + dir + "/mapping.yaml",
                    "_inner_dir:=" + dir, "_queue_size:=100000"});
    int argc = 0;
    ros::init(argc, nullptr, "dcdt_bench", ros::init_options::NoSigintHandler | ros::init_options::AnonymousName);
    bool ok = false;
    for (int i = 0; i < 200 && !(ok = ros::master::check()); ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    return ok;
  }
};

// What the ROS subscriber counts: throughput messages and latencies (µs).
struct Received {
  std::atomic<size_t> got1{0};
  std::mutex m;
  std::vector<double> lat;
  void on_percept(const mrt_msgs::Percept::ConstPtr& p) {
    if (p->sensor == "latency") {
      std::lock_guard<std::mutex> l(m);
      lat.push_back((now_ns() - static_cast<int64_t>(p->header.stamp.toNSec())) / 1e3);
    } else {
      ++got1;
    }
  }
  size_t latencies() {
    std::lock_guard<std::mutex> l(m);
    return lat.size();
  }
};

// Sends n_throughput percepts as fast as the path takes them, then
// n_latency time-stamped ones 1 ms apart; fills out.
void measure(BenchSender& s, const XmlMessage& x, Received& rx, int n_throughput, int n_latency, BenchResult* out) {
  const std::string payload = encode_xml(x);
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  const size_t base = rx.got1;
  auto t0 = Clock::now();
  for (int i = 0; i < n_throughput; ++i) {
    s.send(MSG_FROM_VISION, DCDT_DW_GUARANTEED, payload);
    while (static_cast<size_t>(i) > rx.got1 - base + 2000) std::this_thread::yield();
  }
  wait_until([&] { return rx.got1 - base >= static_cast<size_t>(n_throughput); }, 10);
  out->received = rx.got1 - base;
  out->rate = out->received / std::chrono::duration<double>(Clock::now() - t0).count();
  for (int i = 0; i < n_latency; ++i) {
    XmlMessage y = x;
    y.sensor = "latency";
    const int64_t now = now_ns();
    y.sec = now / 1000000000;
    y.nsec = static_cast<uint32_t>(now % 1000000000);
    s.send(MSG_FROM_VISION, DCDT_DW_GUARANTEED, encode_xml(y));
    std::this_thread::sleep_for(std::chrono::microseconds(1000));
  }
  wait_until([&] { return rx.latencies() >= static_cast<size_t>(n_latency); }, 5);
  std::lock_guard<std::mutex> l(rx.m);
  out->p50 = percentile(rx.lat, 0.5);
  out->p99 = percentile(rx.lat, 0.99);
}

// Legacy Agora (this process) -> dcdt_bridge_node -> ROS subscriber (this process).
bool bridge_to_ros(BenchResult* out, int n_throughput, int n_latency) {
  char dir[] = "/tmp/dcdt_bench_ros_XXXXXX";
  if (!::mkdtemp(dir)) return false;
  const std::string d = dir;
  RosGraph graph;
  if (!graph.start(d)) return false;
  Received rx;
  ros::NodeHandle nh;
  auto sub = nh.subscribe<mrt_msgs::Percept>("/dcdt_bench/percepts", 100000,
                                             [&](const mrt_msgs::Percept::ConstPtr& p) { rx.on_percept(p); });
  ros::AsyncSpinner spinner(1);
  spinner.start();
  AgoraOptions o;
  o.inner_dir = d;
  Agora a(o);
  BenchSender s(&a);
  a.add_member(&s);
  XmlMessage x;
  x.sensor = "throughput";
  x.objects.push_back({"ball", "Ball", {{"distance", 2.4, "", 0.1, 0.9}, {"bearing", -0.35, "", 0.02, 0.9}}});
  bool ok = wait_until([&] { return a.stats().inner_peers >= 1 && sub.getNumPublishers() >= 1; }, 20);
  for (int i = 0; ok && i < 400 && rx.got1 == 0; ++i) {  // warm-up until the path delivers
    s.send(MSG_FROM_VISION, DCDT_DW_GUARANTEED, encode_xml(x));
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ok = ok && rx.got1 > 0;
  if (ok) measure(s, x, rx, n_throughput, n_latency, out);
  spinner.stop();
  sub.shutdown();
  ros::shutdown();
  return ok;
}

}  // namespace

int main() {
  // DCDT_BENCH_MESSAGES overrides the baseline's throughput message count (default 200000).
  const char* env = std::getenv("DCDT_BENCH_MESSAGES");
  const int kThroughput = env ? std::max(1000, std::atoi(env)) : 200000, kLatency = 5000;
  BenchResult tcp;
  {
    const int pa = free_port(), pb = free_port();
    Agora a(tcp_link_options(pa, pb)), b(tcp_link_options(pb, pa));
    tcp = measure_link(a, b, DCDT_DW_GUARANTEED, kThroughput, kLatency, std::string(16, 'x'));
    print_result("dcdt_tcp_link", tcp);
  }
  BenchResult ros_path;
  if (bridge_to_ros(&ros_path, 20000, 2000)) {
    print_result("legacy_agora_to_bridge_to_ros_subscriber", ros_path);
    std::printf("bridge_to_ros_vs_dcdt_tcp_p50_ratio: %.3f ratio\n", tcp.p50 > 0 ? ros_path.p50 / tcp.p50 : 0.0);
  } else {
    std::printf("# legacy_agora_to_bridge_to_ros_subscriber: skipped (no rosmaster or the bridge did not start)\n");
  }
  return 0;
}
