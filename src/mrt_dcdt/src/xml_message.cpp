#include "mrt_dcdt/xml_message.h"

#include <libxml/parser.h>
#include <libxml/tree.h>
#include <libxml/valid.h>
#include <libxml/xmlerror.h>

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <mutex>

namespace mrt::dcdt {

namespace {

void append_escaped(std::string& out, const std::string& s) {
  for (unsigned char ch : s) {
    switch (ch) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\t': out += "&#9;"; break;
      case '\n': out += "&#10;"; break;
      case '\r': out += "&#13;"; break;
      default:
        if (ch < 0x20) throw XmlError(0, "control character 0x" + std::to_string(ch) + " cannot be written in XML");
        out += static_cast<char>(ch);
    }
  }
}

std::string num(double v) {
  if (!std::isfinite(v)) throw XmlError(0, "non-finite number cannot be written");
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  // Prefer the shortest representation that reads back exactly.
  for (int p = 1; p <= 17; ++p) {
    char b2[40];
    std::snprintf(b2, sizeof b2, "%.*g", p, v);
    if (std::strtod(b2, nullptr) == v) return b2;
  }
  return buf;
}

void attr(std::string& out, const char* name, const std::string& v) {
  out += ' ';
  out += name;
  out += "=\"";
  append_escaped(out, v);
  out += '"';
}

// The DTD parsed once; validation is serialised (libxml2 validation contexts
// are per call, the DTD is shared read-only, the mutex keeps it simple).
std::mutex g_dtd_mutex;
xmlDtdPtr shared_dtd() {
  static xmlDtdPtr dtd = [] {
    xmlInitParser();
    xmlParserInputBufferPtr buf =
        xmlParserInputBufferCreateMem(kMrtMessageDtd, static_cast<int>(std::strlen(kMrtMessageDtd)), XML_CHAR_ENCODING_UTF8);
    return xmlIOParseDTD(nullptr, buf, XML_CHAR_ENCODING_UTF8);  // takes ownership of buf
  }();
  return dtd;
}

struct ValidationErrors {
  std::string first;
};

void on_validity_error(void* ctx, const char* fmt, ...) {
  auto* e = static_cast<ValidationErrors*>(ctx);
  if (!e->first.empty()) return;
  char buf[512];
  va_list ap;
  va_start(ap, fmt);
  std::vsnprintf(buf, sizeof buf, fmt, ap);
  va_end(ap);
  e->first = buf;
  while (!e->first.empty() && (e->first.back() == '\n' || e->first.back() == ' ')) e->first.pop_back();
}
void ignore(void*, const char*, ...) {}
void ignore_structured(void*, xmlErrorPtr) {}

struct DocDeleter {
  void operator()(xmlDoc* d) const { xmlFreeDoc(d); }
};
using DocPtr = std::unique_ptr<xmlDoc, DocDeleter>;

std::string prop(xmlNodePtr n, const char* name, bool* present = nullptr) {
  xmlChar* v = xmlGetProp(n, reinterpret_cast<const xmlChar*>(name));
  if (present) *present = v != nullptr;
  if (!v) return "";
  std::string s(reinterpret_cast<const char*>(v));
  xmlFree(v);
  return s;
}

double parse_number(xmlNodePtr n, const char* attr, const std::string& s) {
  char* end = nullptr;
  // strtod flags both overflow (+-HUGE_VAL, not finite) and underflow
  // (a subnormal such as 5e-324, which encode_xml writes) with ERANGE:
  // only the overflow is an error.
  double v = std::strtod(s.c_str(), &end);
  if (s.empty() || *end != '\0' || !std::isfinite(v))
    throw XmlError(xmlGetLineNo(n), std::string("attribute '") + attr + "' is not a finite number: '" + s + "'");
  return v;
}

void parse_time(xmlNodePtr n, const std::string& s, XmlMessage* m) {
  const char* bad = "attribute 'time' must be seconds since the epoch with at most 9 decimals, got '";
  size_t i = 0;
  bool neg = false;
  if (i < s.size() && s[i] == '-') {
    neg = true;
    ++i;
  }
  int64_t sec = 0;
  size_t digits = 0;
  while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) {
    if (digits++ > 15) throw XmlError(xmlGetLineNo(n), bad + s + "'");
    sec = sec * 10 + (s[i++] - '0');
  }
  if (digits == 0) throw XmlError(xmlGetLineNo(n), bad + s + "'");
  uint32_t nsec = 0;
  if (i < s.size() && s[i] == '.') {
    ++i;
    int k = 0;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) {
      if (k >= 9) throw XmlError(xmlGetLineNo(n), bad + s + "'");
      nsec = nsec * 10 + static_cast<uint32_t>(s[i++] - '0');
      ++k;
    }
    if (k == 0) throw XmlError(xmlGetLineNo(n), bad + s + "'");
    for (; k < 9; ++k) nsec *= 10;
  }
  if (i != s.size() || (neg && nsec != 0)) throw XmlError(xmlGetLineNo(n), bad + s + "'");
  m->sec = neg ? -sec : sec;
  m->nsec = nsec;
}

DocPtr parse_and_validate(const std::string& text) {
  if (text.size() > kMaxXmlBytes) throw XmlError(0, "document larger than 1 MiB");
  if (text.find("<!ENTITY") != std::string::npos)
    throw XmlError(0, "entity declarations are not accepted (untrusted input)");
  xmlInitParser();
  xmlParserCtxtPtr ctxt = xmlNewParserCtxt();
  if (!ctxt) throw XmlError(0, "out of memory");
  xmlSetStructuredErrorFunc(nullptr, ignore_structured);
  // No XML_PARSE_NOENT (entities stay unexpanded), no DTDLOAD, no network.
  const int opts = XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING | XML_PARSE_NOCDATA;
  xmlDocPtr raw = xmlCtxtReadMemory(ctxt, text.data(), static_cast<int>(text.size()), "message.xml", nullptr, opts);
  if (!raw) {
    xmlErrorPtr e = xmlCtxtGetLastError(ctxt);
    std::string msg = e && e->message ? e->message : "not well-formed XML";
    int line = e ? e->line : 0;
    xmlFreeParserCtxt(ctxt);
    while (!msg.empty() && msg.back() == '\n') msg.pop_back();
    throw XmlError(line, "not well-formed: " + msg);
  }
  xmlFreeParserCtxt(ctxt);
  DocPtr doc(raw);
  if (xmlDtdPtr in = xmlGetIntSubset(doc.get()); in && in->children)
    throw XmlError(0, "internal DTD subsets are not accepted; the shipped DTD is used");
  std::lock_guard<std::mutex> l(g_dtd_mutex);
  xmlDtdPtr dtd = shared_dtd();
  if (!dtd) throw XmlError(0, "internal error: the embedded DTD does not parse");
  xmlValidCtxtPtr v = xmlNewValidCtxt();
  ValidationErrors errs;
  v->userData = &errs;
  v->error = on_validity_error;
  v->warning = ignore;
  xmlResetLastError();
  const int ok = xmlValidateDtd(v, doc.get(), dtd);
  xmlFreeValidCtxt(v);
  if (!ok) {
    xmlErrorPtr e = xmlGetLastError();
    std::string why = errs.first;
    if (why.empty() && e && e->message) why = e->message;
    while (!why.empty() && (why.back() == '\n' || why.back() == ' ')) why.pop_back();
    throw XmlError(e ? e->line : 0, "does not match mrt_message.dtd: " + (why.empty() ? "invalid" : why));
  }
  return doc;
}

}  // namespace

std::string encode_xml(const XmlMessage& m) {
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<message";
  if (m.nsec >= 1000000000u) throw XmlError(0, "nsec must be < 1e9");
  char t[48];
  if (m.sec < 0 && m.nsec != 0) throw XmlError(0, "negative time stamps with a fraction are not representable");
  std::snprintf(t, sizeof t, "%lld.%09u", static_cast<long long>(m.sec), m.nsec);
  attr(out, "time", t);
  if (!m.sensor.empty()) attr(out, "sensor", m.sensor);
  if (!m.robot.empty()) attr(out, "robot", m.robot);
  if (!m.frame.empty()) attr(out, "frame", m.frame);
  out += ">\n";
  for (const auto& o : m.objects) {
    out += "  <object";
    attr(out, "name", o.name);
    attr(out, "class", o.membership_class);
    if (o.attributes.empty()) {
      out += "/>\n";
      continue;
    }
    out += ">\n";
    for (const auto& a : o.attributes) {
      // The decoder's rules: refuse to write what no decoder would read.
      if (!(a.variability >= 0))
        throw XmlError(0, "object '" + o.name + "' attribute '" + a.name + "': variability must be >= 0, got " +
                              std::to_string(a.variability));
      if (!(a.reliability >= 0 && a.reliability <= 1))
        throw XmlError(0, "object '" + o.name + "' attribute '" + a.name + "': reliability must be in [0, 1], got " +
                              std::to_string(a.reliability));
      out += "    <attribute";
      attr(out, "name", a.name);
      if (a.symbol.empty()) attr(out, "value", num(a.value));
      else attr(out, "symbol", a.symbol);
      attr(out, "variability", num(a.variability));
      attr(out, "reliability", num(a.reliability));
      out += "/>\n";
    }
    out += "  </object>\n";
  }
  out += "</message>\n";
  return out;
}

XmlMessage decode_xml(const std::string& text) {
  DocPtr doc = parse_and_validate(text);
  XmlMessage m;
  xmlNodePtr root = xmlDocGetRootElement(doc.get());
  parse_time(root, prop(root, "time"), &m);
  m.sensor = prop(root, "sensor");
  m.robot = prop(root, "robot");
  m.frame = prop(root, "frame");
  for (xmlNodePtr o = root->children; o; o = o->next) {
    if (o->type != XML_ELEMENT_NODE) continue;
    XmlObject obj;
    obj.name = prop(o, "name");
    obj.membership_class = prop(o, "class");
    for (xmlNodePtr a = o->children; a; a = a->next) {
      if (a->type != XML_ELEMENT_NODE) continue;
      XmlAttribute at;
      at.name = prop(a, "name");
      bool has_value = false, has_symbol = false;
      std::string value = prop(a, "value", &has_value);
      at.symbol = prop(a, "symbol", &has_symbol);
      if (has_value == has_symbol)
        throw XmlError(xmlGetLineNo(a), "attribute '" + at.name + "' needs exactly one of 'value' and 'symbol'");
      if (has_symbol && at.symbol.empty())
        throw XmlError(xmlGetLineNo(a), "attribute '" + at.name + "' has an empty symbol");
      if (has_value) at.value = parse_number(a, "value", value);
      bool has_var = false, has_rel = false;  // absent: the DTD defaults 0 and 1
      std::string var = prop(a, "variability", &has_var), rel = prop(a, "reliability", &has_rel);
      at.variability = has_var ? parse_number(a, "variability", var) : 0.0;
      at.reliability = has_rel ? parse_number(a, "reliability", rel) : 1.0;
      if (at.variability < 0) throw XmlError(xmlGetLineNo(a), "variability must be >= 0");
      if (at.reliability < 0 || at.reliability > 1) throw XmlError(xmlGetLineNo(a), "reliability must be in [0, 1]");
      obj.attributes.push_back(std::move(at));
    }
    m.objects.push_back(std::move(obj));
  }
  return m;
}

std::string validate_xml(const std::string& text) {
  try {
    decode_xml(text);
    return "";
  } catch (const XmlError& e) {
    return e.what();
  }
}

}  // namespace mrt::dcdt
