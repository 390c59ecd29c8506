#include "mrt_dcdt/config.h"

#include <arpa/inet.h>

#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "mrt_common/parse_error.h"

namespace mrt::dcdt {

using mrt::common::ParseError;

namespace {

struct Token {
  std::string text;
  int column;  // 1-based
};

std::vector<Token> tokenize(const std::string& line) {
  std::vector<Token> out;
  size_t i = 0;
  while (i < line.size()) {
    if (line[i] == '#') break;
    if (std::isspace(static_cast<unsigned char>(line[i]))) {
      ++i;
      continue;
    }
    size_t j = i;
    while (j < line.size() && !std::isspace(static_cast<unsigned char>(line[j])) && line[j] != '#') ++j;
    out.push_back({line.substr(i, j - i), static_cast<int>(i) + 1});
    i = j;
  }
  return out;
}

class LineParser {
 public:
  LineParser(const std::string& file, int line, std::vector<Token> toks, int end_col)
      : file_(file), line_(line), toks_(std::move(toks)), end_col_(end_col) {}

  [[noreturn]] void Fail(size_t i, const std::string& msg) const {
    throw ParseError(file_, line_, i < toks_.size() ? toks_[i].column : end_col_, msg);
  }
  const std::string& At(size_t i, const char* what) const {
    if (i >= toks_.size()) Fail(i, std::string("expected ") + what);
    return toks_[i].text;
  }
  std::string Ipv4(size_t i, const char* what, bool multicast = false) const {
    const std::string& s = At(i, what);
    in_addr a{};
    if (inet_pton(AF_INET, s.c_str(), &a) != 1) Fail(i, std::string("expected ") + what + " (dotted IPv4), got '" + s + "'");
    if (multicast && !IN_MULTICAST(ntohl(a.s_addr)))
      Fail(i, "expected a multicast address (224.0.0.0/4), got '" + s + "'");
    return s;
  }
  int Int(size_t i, const char* what, int lo, int hi) const {
    const std::string& s = At(i, what);
    errno = 0;
    char* end = nullptr;
    long v = std::strtol(s.c_str(), &end, 10);
    if (*end != '\0' || errno != 0 || s.empty())
      Fail(i, std::string("expected ") + what + " (an integer), got '" + s + "'");
    if (v < lo || v > hi)
      Fail(i, std::string(what) + " out of range [" + std::to_string(lo) + ", " + std::to_string(hi) + "]: " + s);
    return static_cast<int>(v);
  }
  void End(size_t n) const {
    if (toks_.size() > n) Fail(n, "unexpected '" + toks_[n].text + "' at end of line");
  }
  size_t size() const { return toks_.size(); }

 private:
  const std::string& file_;
  int line_;
  std::vector<Token> toks_;
  int end_col_;
};

}  // namespace

AgoraConfig parse_agora_config(const std::string& text, const std::string& file) {
  AgoraConfig c;
  bool have_net = false, have_po = false;
  std::istringstream in(text);
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    auto toks = tokenize(line);
    if (toks.empty()) continue;
    LineParser p(file, n, toks, static_cast<int>(line.size()) + 1);
    const std::string& first = toks[0].text;
    if (!have_net) {
      c.local_addr = p.Ipv4(0, "<local IP addr> as the first line");
      c.multicast_addr = p.Ipv4(1, "<multicast addr>", true);
      c.port = p.Int(2, "<port>", 1, 65535);
      p.End(3);
      have_net = true;
    } else if (first == "PostOffice:" || first == "PostOffice") {
      if (have_po) p.Fail(0, "PostOffice given twice");
      const std::string& pol = p.At(1, "a PostOffice policy (SLWB, SLWDWCV or SLWSM)");
      if (!parse_policy(pol, &c.policy)) p.Fail(1, "expected SLWB, SLWDWCV or SLWSM, got '" + pol + "'");
      p.End(2);
      have_po = true;
    } else if (first == "ip" || first == "ser") {
      ChannelConfig ch;
      ch.line = n;
      ch.kind = first == "ip" ? ChannelConfig::IP : ChannelConfig::SERIAL;
      const std::string& mode = p.At(1, "'link' or 'bridge'");
      if (mode == "link") ch.mode = ChannelMode::LINK;
      else if (mode == "bridge") ch.mode = ChannelMode::BRIDGE;
      else p.Fail(1, "expected 'link' or 'bridge', got '" + mode + "'");
      ch.level = p.Int(2, "<level>", 0, kMaxHops);
      if (ch.kind == ChannelConfig::IP) {
        ch.local_addr = p.Ipv4(3, "<local addr>");
        ch.local_port = p.Int(4, "<local port>", 1, 65535);
        ch.remote_addr = p.Ipv4(5, "<remote addr>");
        ch.remote_port = p.Int(6, "<remote port>", 1, 65535);
        p.End(7);
        if (ch.local_addr == ch.remote_addr && ch.local_port == ch.remote_port)
          p.Fail(6, "local and remote end points are the same");
      } else {
        ch.device = p.At(3, "<device>");
        p.End(4);
      }
      c.channels.push_back(ch);
    } else {
      p.Fail(0, "expected 'PostOffice:', 'ip' or 'ser', got '" + first + "'");
    }
  }
  if (!have_net) throw ParseError(file, n > 0 ? n : 1, 0, "expected '<local IP addr> <multicast addr> <port>'");
  if (!have_po) throw ParseError(file, n, 0, "expected a 'PostOffice: <type>' line");
  return c;
}

AgoraConfig load_agora_config(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw ParseError(path, 0, 0, "cannot read the Agora configuration file");
  std::ostringstream ss;
  ss << f.rdbuf();
  if (ss.str().size() > (1u << 20)) throw ParseError(path, 0, 0, "configuration file larger than 1 MiB");
  return parse_agora_config(ss.str(), path);
}

std::string format_agora_config(const AgoraConfig& c) {
  std::ostringstream o;
  o << c.local_addr << ' ' << c.multicast_addr << ' ' << c.port << '\n';
  o << "PostOffice: " << policy_name(c.policy) << '\n';
  for (const auto& ch : c.channels) {
    const char* mode = ch.mode == ChannelMode::LINK ? "link" : "bridge";
    if (ch.kind == ChannelConfig::IP)
      o << "ip " << mode << ' ' << ch.level << ' ' << ch.local_addr << ' ' << ch.local_port << ' '
        << ch.remote_addr << ' ' << ch.remote_port << '\n';
    else
      o << "ser " << mode << ' ' << ch.level << ' ' << ch.device << '\n';
  }
  return o.str();
}

}  // namespace mrt::dcdt
