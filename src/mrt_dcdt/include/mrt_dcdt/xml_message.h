// The MRT XML message (manual §3.2): a time stamp and a list of objects, each
// with a name, a class and attributes (name, value or symbol, variability,
// reliability). Documents are checked against the shipped DTD
// (share/mrt_message.dtd, embedded as kMrtMessageDtd) with libxml2: no entity
// expansion, no network, no external DTD loading, size capped.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "mrt_common/percept.h"

namespace mrt::dcdt {

/// An object of the message and its attributes are the stack's percept
/// types (mrt_common/percept.h): name, class (the XML `class` attribute),
/// attributes (name, value or a non-empty symbol, variability, reliability).
using XmlAttribute = mrt::common::Attribute;
using XmlObject = mrt::common::PerceptObject;

struct XmlMessage {
  int64_t sec = 0;     ///< time stamp, seconds since the Unix epoch
  uint32_t nsec = 0;   ///< and nanoseconds (< 1e9)
  std::string sensor, robot, frame;
  std::vector<XmlObject> objects;
};

/// A document that is not a valid MRT message; what() names line and cause.
class XmlError : public std::runtime_error {
 public:
  XmlError(int line, const std::string& msg)
      : std::runtime_error(line > 0 ? "line " + std::to_string(line) + ": " + msg : msg), line_(line) {}
  int line() const { return line_; }

 private:
  int line_;
};

extern const char* const kMrtMessageDtd;
constexpr size_t kMaxXmlBytes = 1u << 20;

/// Serialises (always valid against the DTD; numbers round-trip exactly).
/// Throws XmlError for strings XML 1.0 cannot carry (control characters),
/// non-finite numbers, variability < 0 and reliability outside [0, 1].
std::string encode_xml(const XmlMessage& m);
/// Parses and validates; throws XmlError.
XmlMessage decode_xml(const std::string& text);
/// Validates only; returns "" when valid, else the error message.
std::string validate_xml(const std::string& text);

}  // namespace mrt::dcdt
