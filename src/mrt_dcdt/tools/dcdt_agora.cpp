// dcdt_agora: a legacy-style Agora built only on the DCDT library. Publishes
// and subscribes test messages from the command line or from XML files: the
// stand-in for a legacy MRT module in tests and demos. Run with --help.
#include <CLI/CLI.hpp>

#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <iostream>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "mrt_common/cli.h"
#include "mrt_common/parse_error.h"
#include "mrt_dcdt/agora.h"
#include "mrt_dcdt/xml_message.h"

using namespace mrt::dcdt;

namespace {

const char* kFooter = R"(Received messages are printed one per line:
  recv type=T agora=A member=M seq=S hops=H scope=local|remote warranty=W len=L payload=P
roslaunch's __name:= and __log:= arguments are ignored.)";

std::atomic<bool> g_signal{false};
void OnSignal(int) { g_signal = true; }

std::string Escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    if (c == '\n') o += "\\n";
    else if (c == '\\') o += "\\\\";
    else if (static_cast<unsigned char>(c) < 0x20) o += ' ';
    else o += c;
  }
  return o;
}

std::string ReadFile(const std::string& p) {
  std::ifstream f(p, std::ios::binary);
  if (!f) throw std::runtime_error("cannot read " + p);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

struct Options {
  AgoraOptions agora;
  int publish_type = -1;
  int warranty = DCDT_DW_GUARANTEED;
  std::string text = "message {i}";
  std::vector<std::string> xml_payloads;
  long count = 1;
  double rate = 10;
  int wait_peers = 0;
  std::vector<std::pair<int, RequestType>> subs;
  long expect = -1;
  long linger_ms = 0;
  double duration = 10;
  std::string out;
};

class Output {
 public:
  explicit Output(const std::string& path) {
    if (!path.empty()) {
      f_ = std::fopen(path.c_str(), "w");
      if (!f_) throw std::runtime_error("cannot write " + path);
    }
  }
  ~Output() {
    if (f_) std::fclose(f_);
  }
  void Line(const std::string& s) {
    std::lock_guard<std::mutex> l(m_);
    FILE* o = f_ ? f_ : stdout;
    std::fputs(s.c_str(), o);
    std::fputc('\n', o);
    std::fflush(o);
  }

 private:
  FILE* f_ = nullptr;
  std::mutex m_;
};

class Publisher : public Member {
 public:
  Publisher(Agora* a, const Options& o, Output* out)
      : Member(a, o.rate > 0 ? std::max(1, static_cast<int>(1000.0 / o.rate)) : 0), o_(o), out_(out) {}
  void do_your_job(int) override {
    if (!go) {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
      return;
    }
    if (sent_ >= o_.count) {
      if (!done_) out_->Line("published " + std::to_string(sent_));
      done_ = true;
      terminate();
      return;
    }
    // As fast as possible: a burst per job.
    const int burst = o_.rate > 0 ? 1 : 256;
    for (int b = 0; b < burst && sent_ < o_.count; ++b) {
      Msg* m = create_msg(o_.publish_type, o_.warranty);
      if (!o_.xml_payloads.empty()) {
        m->set_payload(o_.xml_payloads[static_cast<size_t>(sent_) % o_.xml_payloads.size()]);
      } else {
        std::string t = o_.text;
        for (size_t p; (p = t.find("{i}")) != std::string::npos;) t.replace(p, 3, std::to_string(sent_));
        m->set_payload(t);
      }
      if (!share_msg(m)) ++refused;  // a full mailbox or link refused a guaranteed message
      ++sent_;
    }
  }

  std::atomic<bool> go{false};
  std::atomic<uint64_t> refused{0};

 private:
  const Options& o_;
  Output* out_;
  long sent_ = 0;
  bool done_ = false;
};

class Subscriber : public Member {
 public:
  Subscriber(Agora* a, const Options& o, Output* out) : Member(a), o_(o), out_(out) {}
  void init() override {
    for (auto& [type, scope] : o_.subs) subscribe_msg_type(type, scope);
  }
  void do_your_job(int) override {
    while (const Msg* m = receive_msg()) {
      const auto& h = m->header();
      std::ostringstream s;
      s << "recv type=" << h.type << " agora=" << h.agora_id << " member=" << h.member_id << " seq=" << h.seq
        << " hops=" << int(h.hops) << " scope=" << (h.remote ? "remote" : "local") << " warranty=" << int(h.warranty)
        << " len=" << m->payload_len() << " payload=" << Escape(m->payload_string());
      out_->Line(s.str());
      ++received;
      remove_curr_msg();
    }
  }
  std::atomic<long> received{0};

 private:
  const Options& o_;
  Output* out_;
};

RequestType ParseScope(const std::string& s) {
  if (s == "local") return DCDT_LOCAL_MSG;
  if (s == "remote") return DCDT_REMOTE_MSG;
  if (s == "all") return DCDT_ALL_MSG;
  throw std::invalid_argument("scope must be local, remote or all: " + s);
}

int ParseType(const std::string& s) {
  int t = msg_type_from_name(s.c_str());
  if (t < 0) throw std::invalid_argument("unknown message type: " + s);
  return t;
}

// Handles the options that answer at once (--check-xml, --check-config):
// returns their exit code.
int answer_at_once(const std::string& a, const std::string& value) {
  if (a == "--check-xml") {
    std::string err = validate_xml(ReadFile(value));
    if (!err.empty()) {
      std::cerr << value << ": " << err << "\n";
      return 2;
    }
    std::cout << value << ": valid MRT message\n";
    return 0;
  }
  // --check-config
  try {
    std::cout << format_agora_config(load_agora_config(value));
  } catch (const mrt::common::ParseError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
  return 0;
}

// The options into the CLI11 parser; the values needing conversion go to `raw`.
struct RawOptions {
  std::string config, publish, warranty = "guaranteed", check_xml, check_config;
  std::vector<std::string> xml_files, subs;
};

void add_options(CLI::App& app, Options& o, RawOptions& r) {
  app.add_option("--config", r.config, "NETWORK Agora configured by FILE (manual 3.3.1); default STANDALONE");
  app.add_option("--inner-dir", o.agora.inner_dir,
                 "inner-link directory (default $DCDT_INNER_DIR or /tmp/dcdt-<uid>)");
  app.add_flag("--no-inner{false}", o.agora.inner_links, "do not talk to the other Agoras of this machine");
  app.add_flag("--no-finder{false}", o.agora.finder, "NETWORK: no multicast discovery");
  app.add_option("--id", o.agora.agora_id, "Agora id (default random)");
  app.add_option("--publish", r.publish, "message type to publish (legacy name or number)");
  app.add_option("--warranty", r.warranty, "none | retransmit | guaranteed (default guaranteed)")
      ->check(CLI::IsMember({"none", "retransmit", "guaranteed"}));
  app.add_option("--text", o.text, "payload text; \"{i}\" is replaced by the message index (default \"message {i}\")");
  app.add_option("--xml", r.xml_files, "payload from an XML message file, validated (repeatable, cycled)");
  app.add_option("--count", o.count, "messages to publish (default 1)");
  app.add_option("--rate", o.rate, "publishing rate (Hz, default 10; 0 = as fast as possible)");
  app.add_option("--wait-peers", o.wait_peers,
                 "before publishing wait (at most 10 s) for N peers (inner peers + connected channels)");
  app.add_option("--subscribe", r.subs, "TYPE[:SCOPE]: subscribe (SCOPE local|remote|all, default all); repeatable");
  app.add_option("--expect", o.expect, "exit 0 once N messages were received (1 if not within --duration)");
  app.add_option("--linger", o.linger_ms, "after --expect is met, keep receiving MS milliseconds (default 0)");
  app.add_option("--duration", o.duration, "run at most S seconds (default 10)");
  app.add_option("--out", o.out, "write received messages and status lines to FILE (default stdout)");
  app.add_option("--check-xml", r.check_xml, "validate an XML message file and exit (0 valid, 2 invalid)");
  app.add_option("--check-config", r.check_config, "parse a configuration file, print it normalised, exit (0 / 2)");
  app.footer(kFooter);
}

// Parses the command line into o: returns -1 to go on, else the exit code.
int parse_args(int argc, char** argv, Options& o) {
  // roslaunch appends __name:= and __log:= arguments, which CLI11 cannot be
  // told to skip: they are dropped here.
  std::vector<char*> args;
  for (int i = 0; i < argc; ++i)
    if (i == 0 || std::string(argv[i]).rfind("__", 0) != 0) args.push_back(argv[i]);
  CLI::App app{"A legacy-style Agora built only on the DCDT library: publishes and subscribes test\n"
               "messages from the command line or from XML files.",
               "dcdt_agora"};
  RawOptions r;
  add_options(app, o, r);
  if (const int rc = mrt::cli::parse_cli(app, static_cast<int>(args.size()), args.data()); rc >= 0) return rc;
  if (!r.check_xml.empty()) return answer_at_once("--check-xml", r.check_xml);
  if (!r.check_config.empty()) return answer_at_once("--check-config", r.check_config);
  if (!r.publish.empty()) o.publish_type = ParseType(r.publish);
  o.warranty = r.warranty == "none" ? DCDT_DW_NONE : r.warranty == "retransmit" ? DCDT_DW_RETRANSMIT : DCDT_DW_GUARANTEED;
  for (const std::string& f : r.xml_files) {
    std::string x = ReadFile(f), err = validate_xml(x);
    if (!err.empty()) {
      std::cerr << f << ": " << err << "\n";
      return 2;
    }
    o.xml_payloads.push_back(x);
  }
  for (const std::string& s : r.subs) {
    auto c = s.find(':');
    o.subs.emplace_back(ParseType(s.substr(0, c)), c == std::string::npos ? DCDT_ALL_MSG : ParseScope(s.substr(c + 1)));
  }
  if (!r.config.empty()) {
    o.agora.network = true;
    o.agora.config = load_agora_config(r.config);
  }
  return -1;
}

using Clock = std::chrono::steady_clock;

// Inner peers plus connected channels.
int peer_count(Agora& agora) {
  auto s = agora.stats();
  int n = s.inner_peers;
  for (auto& c : s.channels) n += c.connected ? 1 : 0;
  return n;
}

// Starts publishing once the peers are there, ends at --expect, at the end of
// publishing or at --duration. Returns whether --expect was met (true
// without --expect) and whether publishing started.
bool run_until_done(const Options& o, Agora& agora, Subscriber& sub, Publisher& pub, bool will_publish,
                    bool* publishing) {
  const auto t_start = Clock::now();
  const auto t_end = t_start + std::chrono::milliseconds(static_cast<long>(o.duration * 1000));
  bool ok = o.expect < 0;
  while (!g_signal && Clock::now() < t_end) {
    if (!*publishing && will_publish &&
        (peer_count(agora) >= o.wait_peers || Clock::now() > t_start + std::chrono::seconds(10))) {
      *publishing = true;
      pub.go = true;
    }
    if (o.expect >= 0 && sub.received >= o.expect) {
      ok = true;
      // Late or duplicate messages would show up during the linger.
      std::this_thread::sleep_for(std::chrono::milliseconds(o.linger_ms));
      break;
    }
    // Without --expect and without subscriptions: done when publishing is.
    if (o.expect < 0 && o.subs.empty() && (!will_publish || pub.state() == MemberState::TERMINATED)) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return ok;
}

// Guaranteed messages may still be queued or unacknowledged: waits (at most
// 5 s) until every channel has delivered them.
void wait_for_channels(Agora& agora) {
  for (int i = 0; i < 1000 && !g_signal; ++i) {
    uint64_t pending = 0;
    for (auto& c : agora.stats().channels) pending += c.pending;
    if (pending == 0) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(50));  // inner-link datagrams
}

std::string stats_line(Agora& agora, const Subscriber& sub, uint64_t refused) {
  auto s = agora.stats();
  std::ostringstream st;
  st << "stats routed=" << s.routed << " duplicates=" << s.duplicates << " inner_peers=" << s.inner_peers
     << " received=" << sub.received << " share_refused=" << refused;
  for (auto& c : s.channels)
    st << " [" << c.name << " sent=" << c.sent << " received=" << c.received << " resent=" << c.resent
       << " dropped=" << c.dropped << " refused=" << c.refused << " reconnects=" << c.reconnects << "]";
  return st.str();
}

int run(int argc, char** argv) {
  Options o;
  if (int rc = parse_args(argc, argv, o); rc >= 0) return rc;
  std::signal(SIGINT, OnSignal);
  std::signal(SIGTERM, OnSignal);
  std::signal(SIGPIPE, SIG_IGN);

  Output out(o.out);
  Agora agora(o.agora);
  Subscriber sub(&agora, o, &out);
  Publisher pub(&agora, o, &out);
  if (!o.subs.empty()) {
    agora.add_member(&sub);
    agora.activate_member(&sub);
  }
  const bool will_publish = o.publish_type >= 0 && o.count > 0;
  if (will_publish) {
    agora.add_member(&pub);
    agora.activate_member(&pub);
  }
  std::thread work([&] { agora.lets_work(); });
  // "ready" once the subscriptions exist (init ran), so tests can sequence processes.
  for (int i = 0; i < 1000 && !o.subs.empty() && sub.state() != MemberState::RUNNING; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  out.Line("ready agora=" + std::to_string(agora.agora_id()));
  bool publishing = false;
  const bool ok = run_until_done(o, agora, sub, pub, will_publish, &publishing);
  if (publishing) wait_for_channels(agora);
  agora.shutdown();
  work.join();
  out.Line(stats_line(agora, sub, pub.refused));
  return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const mrt::common::ParseError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "dcdt_agora: " << e.what() << "\n";
    return 2;
  }
}
