#include "mrt_dcdt/msg.h"

#include <algorithm>
#include <chrono>
#include <cstring>

namespace mrt::dcdt {

DCDT_TIME now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

namespace {
struct TypeName {
  int type;
  const char* name;
};
constexpr TypeName kTypes[] = {
    {MSG_FROM_VISION, "MSG_FROM_VISION"},
    {MSG_FROM_VISION_OMNIDIR, "MSG_FROM_VISION_OMNIDIR"},
    {MSG_FROM_VISION_FRONTAL, "MSG_FROM_VISION_FRONTAL"},
    {MSG_FROM_MOTION, "MSG_FROM_MOTION"},
    {MSG_FROM_MONITOR, "MSG_FROM_MONITOR"},
    {MSG_FROM_MAP, "MSG_FROM_MAP"},
    {MSG_FROM_SCARE, "MSG_FROM_SCARE"},
    {MSG_FROM_BRIAN, "MSG_FROM_BRIAN"},
    {MSG_FROM_ANCHORER, "MSG_FROM_ANCHORER"},
    {MSG_FROM_REFBOX, "MSG_FROM_REFBOX"},
    {MSG_TO_BRIAN, "MSG_TO_BRIAN"},
    {MSG_TO_MOTION, "MSG_TO_MOTION"},
    {MSG_TO_ANCHORER, "MSG_TO_ANCHORER"},
    {MSG_FROM_JOYPAD_BRIEF, "MSG_FROM_JOYPAD_BRIEF"},
    {MSG_FROM_SONAR_QUALITY, "MSG_FROM_SONAR_QUALITY"},
};
}  // namespace

const char* msg_type_name(int type) {
  for (const auto& t : kTypes)
    if (t.type == type) return t.name;
  return "";
}

int msg_type_from_name(const char* name) {
  if (!name || !*name) return -1;
  for (const auto& t : kTypes)
    if (std::strcmp(t.name, name) == 0) return t.type;
  char* end = nullptr;
  long v = std::strtol(name, &end, 10);
  if (*end != '\0' || v < 0 || v > 0x7fffffff) return -1;
  return static_cast<int>(v);
}

Msg::Msg(int type, int member_id, int agora_id, int warranty) {
  header_.type = type;
  header_.member_id = member_id;
  header_.agora_id = agora_id;
  header_.warranty = static_cast<uint8_t>(std::clamp(warranty, 0, 2));
  header_.creation_time = now_ns();
}

void Msg::set_payload(const void* data, int len) {
  len = std::clamp(len, 0, static_cast<int>(kMaxPayload));
  if (len == 0 || !data) {
    payload_.clear();
    return;
  }
  payload_.assign(static_cast<const char*>(data), static_cast<size_t>(len));
}

void* Msg::alloc_payload(int len) {
  len = std::clamp(len, 0, static_cast<int>(kMaxPayload));
  payload_.assign(static_cast<size_t>(len), '\0');
  return payload_.data();
}

}  // namespace mrt::dcdt
