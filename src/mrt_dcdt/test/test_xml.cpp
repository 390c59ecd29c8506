// XML payloads: golden document, round trips, DTD violations, hostile input.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "mrt_dcdt/xml_message.h"

using namespace mrt::dcdt;

namespace {

std::string ReadFile(const std::string& p) {
  std::ifstream f(p);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}
std::string Data(const char* name) { return ReadFile(std::string(DCDT_TEST_DATA) + "/" + name); }

void ExpectEqual(const XmlMessage& a, const XmlMessage& b) {
  EXPECT_EQ(a.sec, b.sec);
  EXPECT_EQ(a.nsec, b.nsec);
  EXPECT_EQ(a.sensor, b.sensor);
  EXPECT_EQ(a.robot, b.robot);
  EXPECT_EQ(a.frame, b.frame);
  ASSERT_EQ(a.objects.size(), b.objects.size());
  for (size_t i = 0; i < a.objects.size(); ++i) {
    EXPECT_EQ(a.objects[i].name, b.objects[i].name);
    EXPECT_EQ(a.objects[i].membership_class, b.objects[i].membership_class);
    ASSERT_EQ(a.objects[i].attributes.size(), b.objects[i].attributes.size());
    for (size_t j = 0; j < a.objects[i].attributes.size(); ++j) {
      const auto &x = a.objects[i].attributes[j], &y = b.objects[i].attributes[j];
      EXPECT_EQ(x.name, y.name);
      EXPECT_EQ(x.value, y.value);  // bit-exact
      EXPECT_EQ(x.symbol, y.symbol);
      EXPECT_EQ(x.variability, y.variability);
      EXPECT_EQ(x.reliability, y.reliability);
    }
  }
}

TEST(Xml, ShippedDtdIsTheEmbeddedOne) {
  EXPECT_EQ(ReadFile(std::string(DCDT_SHARE_DIR) + "/mrt_message.dtd"), std::string(kMrtMessageDtd));
}

TEST(Xml, GoldenDocumentDecodes) {
  XmlMessage m = decode_xml(Data("percept_ball.xml"));
  EXPECT_EQ(m.sec, 1700000000);
  EXPECT_EQ(m.nsec, 250000000u);
  EXPECT_EQ(m.sensor, "omnivision");
  EXPECT_EQ(m.robot, "ianus3");
  EXPECT_EQ(m.frame, "base_link");
  ASSERT_EQ(m.objects.size(), 3u);
  EXPECT_EQ(m.objects[0].name, "ball");
  EXPECT_EQ(m.objects[0].membership_class, "Ball");
  ASSERT_EQ(m.objects[0].attributes.size(), 3u);
  EXPECT_EQ(m.objects[0].attributes[0].name, "distance");
  EXPECT_DOUBLE_EQ(m.objects[0].attributes[0].value, 2.4);
  EXPECT_DOUBLE_EQ(m.objects[0].attributes[0].variability, 0.1);
  EXPECT_DOUBLE_EQ(m.objects[0].attributes[0].reliability, 0.9);
  EXPECT_EQ(m.objects[0].attributes[2].symbol, "orange");
  // Defaults of the DTD when variability/reliability are absent.
  EXPECT_EQ(m.objects[1].attributes[0].variability, 0.0);
  EXPECT_EQ(m.objects[1].attributes[0].reliability, 1.0);
  EXPECT_TRUE(m.objects[2].attributes.empty());
}

TEST(Xml, GoldenEncoding) {
  XmlMessage m;
  m.sec = 12;
  m.nsec = 5;
  m.sensor = "sonar";
  m.objects.push_back({"w", "Wall", {{"distance", 0.5, "", 0.25, 1.0}}});
  EXPECT_EQ(encode_xml(m),
            "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
            "<message time=\"12.000000005\" sensor=\"sonar\">\n"
            "  <object name=\"w\" class=\"Wall\">\n"
            "    <attribute name=\"distance\" value=\"0.5\" variability=\"0.25\" reliability=\"1\"/>\n"
            "  </object>\n"
            "</message>\n");
}

TEST(Xml, RoundTripIsLossless) {
  XmlMessage m;
  m.sec = 1763776000;
  m.nsec = 999999999;
  m.sensor = "omni <vision> & \"friends\"";
  m.robot = "r\tone\nline";
  m.frame = "robot1/base_link";
  m.objects.push_back({"ball", "Ball", {{"x", 0.1 + 0.2, "", 1e-300, 0.3333333333333333}, {"team", 0, "cyan", 0, 0}}});
  m.objects.push_back({"ünïcode", "Person", {{"v", -std::numeric_limits<double>::max(), "", 0, 1}}});
  m.objects.push_back({"empty", "Obstacle", {}});
  // The smallest subnormal (5e-324) and the largest finite value survive too.
  m.objects.push_back({"tiny", "Obstacle", {{"d", std::numeric_limits<double>::denorm_min(), "", 0, 1},
                                            {"h", std::numeric_limits<double>::max(), "", 0, 1}}});
  ExpectEqual(decode_xml(encode_xml(m)), m);
  ExpectEqual(decode_xml(encode_xml(decode_xml(Data("percept_ball.xml")))), decode_xml(Data("percept_ball.xml")));
}

TEST(Xml, DtdViolationsAreRejectedWithAClearMessage) {
  struct Case {
    std::string file, expect;
  } cases[] = {
      {"invalid_unknown_element.xml", "does not match mrt_message.dtd"},
      {"invalid_missing_class.xml", "class"},
  };
  for (const auto& c : cases) {
    try {
      decode_xml(Data(c.file.c_str()));
      ADD_FAILURE() << c.file << " accepted";
    } catch (const XmlError& e) {
      EXPECT_NE(std::string(e.what()).find(c.expect), std::string::npos) << c.file << ": " << e.what();
      EXPECT_GT(e.line(), 0) << e.what();
    }
  }
}

TEST(Xml, SemanticErrors) {
  auto err = [](const std::string& body) { return validate_xml("<message time=\"1\">" + body + "</message>"); };
  EXPECT_NE(err("<object name='a' class='B'><attribute name='x'/></object>").find("exactly one of"), std::string::npos);
  EXPECT_NE(err("<object name='a' class='B'><attribute name='x' value='1' symbol='s'/></object>").find("exactly one"),
            std::string::npos);
  EXPECT_NE(err("<object name='a' class='B'><attribute name='x' value='abc'/></object>").find("not a finite number"),
            std::string::npos);
  EXPECT_NE(err("<object name='a' class='B'><attribute name='x' value='nan'/></object>").find("finite"),
            std::string::npos);
  EXPECT_NE(err("<object name='a' class='B'><attribute name='x' value='1e999'/></object>").find("finite"),
            std::string::npos);  // overflows to infinity
  EXPECT_NE(err("<object name='a' class='B'><attribute name='x' value='1' reliability='1.5'/></object>")
                .find("reliability"),
            std::string::npos);
  EXPECT_NE(validate_xml("<message time='soon'/>").find("time"), std::string::npos);
  EXPECT_NE(validate_xml("<message time='1.0123456789'/>").find("time"), std::string::npos);
  EXPECT_NE(validate_xml("<percept time='1'/>").find("mrt_message.dtd"), std::string::npos);
  EXPECT_NE(validate_xml("<message time='1'>").find("not well-formed"), std::string::npos);
  EXPECT_EQ(validate_xml("<message time='1'/>"), "");
}

TEST(Xml, HostileInputIsRejected) {
  EXPECT_NE(validate_xml(Data("invalid_entity.xml")).find("entity"), std::string::npos);
  EXPECT_NE(validate_xml("<!DOCTYPE message [<!ELEMENT message ANY>]><message time='1'/>").find("internal DTD"),
            std::string::npos);
  // External entities / DTDs are never fetched.
  EXPECT_EQ(validate_xml("<!DOCTYPE message SYSTEM \"http://127.0.0.1:1/x.dtd\"><message time='1'/>"), "");
  std::string huge = "<message time='1'>" + std::string(kMaxXmlBytes, ' ') + "</message>";
  EXPECT_NE(validate_xml(huge).find("larger than"), std::string::npos);
  EXPECT_NE(validate_xml("").find("not well-formed"), std::string::npos);
}

TEST(Xml, EncoderRefusesWhatXmlCannotCarry) {
  XmlMessage m;
  m.sensor = std::string("a\x01", 2);
  EXPECT_THROW(encode_xml(m), XmlError);
  XmlMessage n;
  n.objects.push_back({"a", "B", {{"x", std::nan(""), "", 0, 1}}});
  EXPECT_THROW(encode_xml(n), XmlError);
}

TEST(Xml, EncoderRefusesWhatEveryDecoderRejects) {
  // reliability must be in [0, 1] and variability >= 0 (README, DTD section).
  auto with = [](double variability, double reliability) {
    XmlMessage m;
    m.objects.push_back({"ball", "Ball", {{"distance", 2.0, "", variability, reliability}}});
    return m;
  };
  EXPECT_THROW(encode_xml(with(0, 1.5)), XmlError);
  EXPECT_THROW(encode_xml(with(0, -0.25)), XmlError);
  EXPECT_THROW(encode_xml(with(0, std::nan(""))), XmlError);
  EXPECT_THROW(encode_xml(with(-1e-9, 1)), XmlError);
  EXPECT_THROW(encode_xml(with(std::nan(""), 1)), XmlError);
  try {
    encode_xml(with(0, 1.5));
  } catch (const XmlError& e) {
    EXPECT_NE(std::string(e.what()).find("reliability must be in [0, 1]"), std::string::npos) << e.what();
  }
  // The bounds themselves are fine, and a symbolic attribute is checked too.
  EXPECT_NO_THROW(decode_xml(encode_xml(with(0, 0))));
  EXPECT_NO_THROW(decode_xml(encode_xml(with(0, 1))));
  XmlMessage sym;
  sym.objects.push_back({"ball", "Ball", {{"colour", 0, "orange", 0, 2}}});
  EXPECT_THROW(encode_xml(sym), XmlError);
}

}  // namespace
