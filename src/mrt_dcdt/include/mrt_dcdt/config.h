// The Agora configuration file (manual §3.3.1):
//   <local IP addr> <multicast addr> <port>
//   PostOffice: SLWB | SLWDWCV | SLWSM
//   ip  <link|bridge> <level> <local addr> <local port> <remote addr> <remote port>   (any number)
//   ser <link|bridge> <level> <device>                                               (any number)
// '#' starts a comment; blank lines are ignored. Errors throw
// mrt::common::ParseError naming file:line:column.
#pragma once

#include <string>
#include <vector>

#include "mrt_dcdt/post_office.h"

namespace mrt::dcdt {

enum class ChannelMode { LINK, BRIDGE };

struct ChannelConfig {
  enum Kind { IP, SERIAL } kind = IP;
  ChannelMode mode = ChannelMode::LINK;
  /// Forward a message on this channel only if it has travelled at most
  /// `level` network channels already (0..kMaxHops). See doc/communities.md.
  int level = 0;
  std::string local_addr;
  int local_port = 0;
  std::string remote_addr;
  int remote_port = 0;
  std::string device;  // SERIAL
  int line = 0;        // where it was declared (for messages)
};

struct AgoraConfig {
  std::string local_addr = "127.0.0.1";
  std::string multicast_addr = "239.255.0.1";
  int port = 0;  ///< multicast (Finder) port
  PostOfficePolicy policy = PostOfficePolicy::SLWB;
  std::vector<ChannelConfig> channels;
};

/// Parses the text of a configuration file; `file` is used in errors.
AgoraConfig parse_agora_config(const std::string& text, const std::string& file);
/// Reads and parses a file (ParseError with line 0 when it cannot be read).
AgoraConfig load_agora_config(const std::string& path);
/// The configuration in the file format (parses back to the same struct).
std::string format_agora_config(const AgoraConfig& c);

}  // namespace mrt::dcdt
