// airboard_frame: encodes AIRBoard frames to hex, or decodes a hex/binary
// capture of the serial line into readable frames.
//
//   airboard_frame encode set_speed SEQ W1 [W2 ..]     (rad/s)
//   airboard_frame encode set_pwm SEQ D1 [D2 ..]       (duty in [-1, 1])
//   airboard_frame encode set_gains SEQ MOTOR KP KI    (MOTOR 255 = all)
//   airboard_frame encode set_stream SEQ PERIOD_MS [FORMAT]   (FORMAT 0 = STATE, 1 = compact)
//   airboard_frame encode get_state|heartbeat|get_info SEQ
//   airboard_frame decode [--binary] [FILE]            (hex bytes, whitespace separated; '-' or none = stdin)
//
// Exit codes: 0 ok, 2 usage or input error.
#include <CLI/CLI.hpp>

#include <cctype>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "mrt_airboard/protocol.h"
#include "mrt_common/cli.h"

using namespace mrt::airboard;

namespace {

int usage() {
  std::cerr << "airboard_frame: wrong number of arguments for this frame type\n"
               "Run with --help for more information.\n";
  return 2;
}

double num(const std::string& s) {
  std::size_t used = 0;
  const double v = std::stod(s, &used);
  if (used != s.size()) throw std::invalid_argument("expected a number, got '" + s + "'");
  return v;
}

std::string type_name(uint8_t t) {
  switch (t) {
    case proto::kSetSpeed: return "SET_SPEED";
    case proto::kSetPwm: return "SET_PWM";
    case proto::kSetGains: return "SET_GAINS";
    case proto::kGetState: return "GET_STATE";
    case proto::kHeartbeat: return "HEARTBEAT";
    case proto::kSetStream: return "SET_STREAM";
    case proto::kGetInfo: return "GET_INFO";
    case proto::kState: return "STATE";
    case proto::kInfo: return "INFO";
    case proto::kNack: return "NACK";
    case proto::kShortState: return "SHORT_STATE";
    case proto::kCounters: return "COUNTERS";
    default: return "UNKNOWN";
  }
}

void print(const Frame& f) {
  std::cout << type_name(f.type) << " seq=" << int(f.seq);
  std::vector<double> v;
  Gains g;
  uint16_t p;
  uint8_t format;
  BoardState s;
  ShortState ss;
  BoardCounters c;
  BoardInfo i;
  uint8_t a, b;
  if (parse_set_speed(f, &v) || parse_set_pwm(f, &v)) {
    for (double x : v) std::cout << ' ' << x;
  } else if (parse_set_gains(f, &g)) {
    std::cout << " motor=" << int(g.motor) << " kp=" << g.kp << " ki=" << g.ki;
  } else if (parse_set_stream(f, &p, &format)) {
    std::cout << " period_ms=" << p;
    if (f.payload.size() == 3) std::cout << " format=" << int(format);
  } else if (parse_short_state(f, &ss)) {
    std::cout << " time_ms=" << ss.time_ms << " status=0x" << std::hex << int(ss.status) << std::dec;
    for (std::size_t k = 0; k < ss.ticks.size(); ++k)
      std::cout << " [ticks=" << ss.ticks[k] << " setpoint=" << ss.setpoints[k] << ']';
  } else if (parse_counters(f, &c)) {
    std::cout << " since_cmd_ms=" << c.since_cmd_ms << " frames_bad=" << c.frames_bad
              << " watchdog_trips=" << c.watchdog_trips;
  } else if (parse_state(f, &s)) {
    std::cout << " time_ms=" << s.time_ms << " status=0x" << std::hex << int(s.status) << std::dec
              << " last_seq=" << int(s.last_seq) << " since_cmd_ms=" << s.since_cmd_ms
              << " frames_bad=" << s.frames_bad << " watchdog_trips=" << s.watchdog_trips;
    for (const auto& m : s.motors)
      std::cout << " [ticks=" << m.ticks << " speed=" << m.speed << " setpoint=" << m.setpoint
                << " duty=" << m.duty << " status=0x" << std::hex << int(m.status) << std::dec << ']';
  } else if (parse_info(f, &i)) {
    std::cout << " fw=" << int(i.fw_major) << '.' << int(i.fw_minor) << " motors=" << int(i.motors)
              << " cpr=" << i.counts_per_rev << " control_hz=" << i.control_hz << " pwm_hz=" << i.pwm_hz
              << " max_speed=" << i.max_speed << " watchdog_ms=" << i.watchdog_ms;
  } else if (parse_nack(f, &a, &b)) {
    std::cout << " type=0x" << std::hex << int(a) << std::dec << " reason=" << int(b);
  } else if (!f.payload.empty()) {
    std::cout << " (malformed payload of " << f.payload.size() << " bytes)";
  }
  std::cout << '\n';
}

int encode(const std::string& t, int seq_number, const std::vector<std::string>& args) {
  const auto seq = static_cast<uint8_t>(seq_number);
  std::vector<double> v;
  for (const std::string& a : args) v.push_back(num(a));
  Frame f;
  if (t == "set_speed") f = make_set_speed(seq, v);
  else if (t == "set_pwm") f = make_set_pwm(seq, v);
  else if (t == "set_gains" && v.size() == 3) f = make_set_gains(seq, Gains{static_cast<uint8_t>(v[0]), v[1], v[2]});
  else if (t == "set_stream" && v.size() == 1) f = make_set_stream(seq, static_cast<uint16_t>(v[0]));
  else if (t == "set_stream" && v.size() == 2)
    f = make_set_stream(seq, static_cast<uint16_t>(v[0]), static_cast<uint8_t>(v[1]));
  else if (t == "get_state" && v.empty()) f = make_simple(proto::kGetState, seq);
  else if (t == "heartbeat" && v.empty()) f = make_simple(proto::kHeartbeat, seq);
  else if (t == "get_info" && v.empty()) f = make_simple(proto::kGetInfo, seq);
  else return usage();
  const auto bytes = encode_frame(f);
  for (std::size_t i = 0; i < bytes.size(); ++i)
    std::cout << (i ? " " : "") << std::uppercase << std::hex << std::setw(2) << std::setfill('0') << int(bytes[i]);
  std::cout << '\n';
  return 0;
}

int decode(bool binary, const std::string& name) {
  std::ifstream file;
  std::istream* in = &std::cin;
  if (name != "-") {
    file.open(name, std::ios::binary);
    if (!file) {
      std::cerr << name << ": cannot open file\n";
      return 2;
    }
    in = &file;
  }
  std::vector<uint8_t> bytes;
  if (binary) {
    bytes.assign(std::istreambuf_iterator<char>(*in), std::istreambuf_iterator<char>());
  } else {
    std::string line;
    int n = 0;
    while (std::getline(*in, line)) {
      ++n;
      std::istringstream ls(line);
      std::string tok;
      while (ls >> tok) {
        if (tok[0] == '#') break;
        if (tok.size() != 2 || !std::isxdigit(tok[0]) || !std::isxdigit(tok[1])) {
          std::cerr << name << ':' << n << ':' << (line.find(tok) + 1) << ": expected a hex byte, got '" << tok << "'\n";
          return 2;
        }
        bytes.push_back(static_cast<uint8_t>(std::stoi(tok, nullptr, 16)));
      }
    }
  }
  FrameDecoder dec;
  dec.feed(bytes.data(), bytes.size(), print);
  const auto& s = dec.stats();
  std::cout << "# " << s.frames_ok << " frames, " << s.crc_errors << " bad CRC, " << s.length_errors
            << " bad length, " << s.bytes_skipped << " bytes skipped\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Encodes AIRBoard frames to hex, or decodes a capture of the serial line into\n"
               "readable frames. Exit 0 ok, 2 on usage or input errors.",
               "airboard_frame"};
  app.require_subcommand(1);
  std::string type, file = "-";
  int seq = 0;
  bool binary = false;
  std::vector<std::string> args;
  CLI::App* enc = app.add_subcommand("encode", "print one frame as hex bytes");
  enc->add_option("type", type,
                  "set_speed W1 [W2 ..] (rad/s) | set_pwm D1 [D2 ..] (duty in [-1, 1]) |\n"
                  "set_gains MOTOR KP KI (MOTOR 255 = all) | set_stream PERIOD_MS [FORMAT]\n"
                  "(ms; FORMAT 0 = STATE, 1 = compact) | get_state | heartbeat | get_info")
      ->required()
      ->check(CLI::IsMember({"set_speed", "set_pwm", "set_gains", "set_stream", "get_state", "heartbeat", "get_info"}));
  enc->add_option("seq", seq, "sequence number (0..255)")->required()->check(CLI::Range(0, 255));
  enc->add_option("args", args, "the numbers of the frame type, see above");
  CLI::App* dec = app.add_subcommand("decode", "print the frames of a capture and the decoder's counters");
  dec->add_flag("--binary", binary, "FILE holds raw bytes (default: hex bytes, whitespace separated, # comments)");
  dec->add_option("file", file, "capture file; '-' or none = stdin");
  if (const int rc = mrt::cli::parse_cli(app, argc, argv); rc >= 0) return rc;
  try {
    if (enc->parsed()) return encode(type, seq, args);
    return decode(binary, file);
  } catch (const std::exception& e) {
    std::cerr << "airboard_frame: " << e.what() << '\n';
    return 2;
  }
}
