// The Agora configuration file of manual §3.3.1: the manual's example,
// every line kind, and errors naming file:line:column.
#include <gtest/gtest.h>

#include "mrt_common/parse_error.h"
#include "mrt_dcdt/config.h"

using namespace mrt::dcdt;
using mrt::common::ParseError;

namespace {

TEST(Config, ManualExample) {
  // Verbatim from manual §3.3.1.
  auto c = parse_agora_config("192.168.0.1 225.0.0.1 2003\nPostOffice: SLWB\nip link 0 192.168.0.1 3000 192.168.1.1 3000\n",
                            "dcdt.cfg");
  EXPECT_EQ(c.local_addr, "192.168.0.1");
  EXPECT_EQ(c.multicast_addr, "225.0.0.1");
  EXPECT_EQ(c.port, 2003);
  EXPECT_EQ(c.policy, PostOfficePolicy::SLWB);
  ASSERT_EQ(c.channels.size(), 1u);
  const auto& ch = c.channels[0];
  EXPECT_EQ(ch.kind, ChannelConfig::IP);
  EXPECT_EQ(ch.mode, ChannelMode::LINK);
  EXPECT_EQ(ch.level, 0);
  EXPECT_EQ(ch.local_addr, "192.168.0.1");
  EXPECT_EQ(ch.local_port, 3000);
  EXPECT_EQ(ch.remote_addr, "192.168.1.1");
  EXPECT_EQ(ch.remote_port, 3000);
  EXPECT_EQ(ch.line, 3);
}

TEST(Config, AllLineKindsCommentsAndRoundTrip) {
  const std::string text =
      "# an Agora with every kind of channel\n"
      "\n"
      "127.0.0.1 239.255.0.1 5000   # network line\n"
      "PostOffice: SLWDWCV\n"
      "ip bridge 2 127.0.0.1 3001 127.0.0.1 3002\n"
      "ser link 0 /dev/ttyS0\r\n";
  auto c = parse_agora_config(text, "x.cfg");
  EXPECT_EQ(c.policy, PostOfficePolicy::SLWDWCV);
  ASSERT_EQ(c.channels.size(), 2u);
  EXPECT_EQ(c.channels[0].mode, ChannelMode::BRIDGE);
  EXPECT_EQ(c.channels[0].level, 2);
  EXPECT_EQ(c.channels[1].kind, ChannelConfig::SERIAL);
  EXPECT_EQ(c.channels[1].device, "/dev/ttyS0");
  auto again = parse_agora_config(format_agora_config(c), "y.cfg");
  EXPECT_EQ(format_agora_config(again), format_agora_config(c));
}

struct Bad {
  const char* text;
  int line;
  int column;
  const char* expect;
};

TEST(Config, ErrorsNameFileLineAndColumn) {
  const Bad cases[] = {
      {"", 1, 0, "expected '<local IP addr> <multicast addr> <port>'"},
      {"127.0.0.1\n", 1, 10, "expected <multicast addr>"},
      {"127.0.0.1 239.255.0.1\n", 1, 22, "<port>"},
      {"localhost 239.255.0.1 2000\n", 1, 1, "dotted IPv4"},
      {"127.0.0.1 10.0.0.1 2000\n", 1, 11, "expected a multicast address"},
      {"127.0.0.1 239.255.0.1 70000\n", 1, 23, "out of range"},
      {"127.0.0.1 239.255.0.1 2000\nPostOffice: FAST\n", 2, 13, "expected SLWB, SLWDWCV or SLWSM"},
      {"127.0.0.1 239.255.0.1 2000\n", 1, 0, "expected a 'PostOffice: <type>' line"},
      {"127.0.0.1 239.255.0.1 2000\nPostOffice: SLWB\nip tunnel 0 127.0.0.1 1 127.0.0.1 2\n", 3, 4,
       "expected 'link' or 'bridge'"},
      {"127.0.0.1 239.255.0.1 2000\nPostOffice: SLWB\nip link x 127.0.0.1 1 127.0.0.1 2\n", 3, 9, "<level>"},
      {"127.0.0.1 239.255.0.1 2000\nPostOffice: SLWB\nip link 99 127.0.0.1 1 127.0.0.1 2\n", 3, 9, "out of range"},
      {"127.0.0.1 239.255.0.1 2000\nPostOffice: SLWB\nip link 0 127.0.0.1 1 127.0.0.1\n", 3, 32,
       "expected <remote port>"},
      {"127.0.0.1 239.255.0.1 2000\nPostOffice: SLWB\nip link 0 127.0.0.1 1 127.0.0.1 2 extra\n", 3, 35,
       "unexpected 'extra'"},
      {"127.0.0.1 239.255.0.1 2000\nPostOffice: SLWB\nser bridge 1\n", 3, 13, "expected <device>"},
      {"127.0.0.1 239.255.0.1 2000\nPostOffice: SLWB\nudp link 0\n", 3, 1, "expected 'PostOffice:', 'ip' or 'ser'"},
      {"127.0.0.1 239.255.0.1 2000\nPostOffice: SLWB\nPostOffice: SLWB\n", 3, 1, "PostOffice given twice"},
  };
  for (const auto& b : cases) {
    try {
      parse_agora_config(b.text, "agora.cfg");
      ADD_FAILURE() << "accepted: " << b.text;
    } catch (const ParseError& e) {
      EXPECT_EQ(e.file(), "agora.cfg");
      EXPECT_EQ(e.line(), b.line) << e.what();
      if (b.column) {
        EXPECT_EQ(e.column(), b.column) << e.what();
      }
      EXPECT_NE(std::string(e.what()).find(b.expect), std::string::npos) << e.what();
    }
  }
}

TEST(Config, MissingFileIsAParseError) {
  EXPECT_THROW(load_agora_config("/nonexistent/dcdt.cfg"), ParseError);
}

TEST(Config, ShippedExampleConfigurationsParse) {
  for (const char* f : {"agora_standalone_net.cfg", "agora_link.cfg"}) {
    EXPECT_NO_THROW(load_agora_config(std::string(DCDT_TEST_DATA) + "/" + f)) << f;
  }
}

}  // namespace
