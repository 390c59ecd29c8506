# The sources of the mrt_dcdt library, relative to the package directory;
# shared by CMakeLists.txt and the clang++ fuzz sub-build (fuzz/).
set(MRT_DCDT_CORE_SOURCES
  src/agora.cpp
  src/channels.cpp
  src/config.cpp
  src/finder.cpp
  src/frame.cpp
  src/inner_link_manager.cpp
  src/member.cpp
  src/msg.cpp
  src/net_util.cpp
  src/post_office.cpp
  src/stream_link.cpp
  src/udp_link.cpp
  src/xml_message.cpp)
