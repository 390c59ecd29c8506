#include "mrt_recvision/color_table.h"

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <stdexcept>

namespace mrt::recvision {

namespace {
constexpr std::array<const char*, kColorClasses> kNames = {
    "none", "green", "white", "orange", "yellow", "blue", "black", "cyan", "magenta", "red",
    "purple", "beige", "grey", "bronze"};

// Centre colour of every bin, and its HSV (H degrees, S and V in [0, 1])
// computed once by OpenCV.
struct BinColors {
  cv::Mat rgb, hsv;  // kBins x 1, CV_32FC3
  BinColors() : rgb(ColorTable::kBins, 1, CV_32FC3) {
    for (int i = 0; i < ColorTable::kBins; ++i) {
      rgb.at<cv::Vec3f>(i) = cv::Vec3f(((i >> 10) << 3) + 4.f, (((i >> 5) & 31) << 3) + 4.f, ((i & 31) << 3) + 4.f);
    }
    cv::cvtColor(rgb / 255.0, hsv, cv::COLOR_RGB2HSV);
  }
};
const BinColors& bins() {
  static const BinColors b;
  return b;
}
}  // namespace

const char* color_name(ColorClass c) {
  const auto i = static_cast<std::size_t>(c);
  return i < kNames.size() ? kNames[i] : "none";
}

bool parse_color(const std::string& name, ColorClass& out) {
  for (std::size_t i = 1; i < kNames.size(); ++i) {
    if (name == kNames[i]) {
      out = static_cast<ColorClass>(i);
      return true;
    }
  }
  return false;
}

std::string color_class_list() {
  std::string out;
  for (std::size_t i = 1; i < kNames.size(); ++i) out += (i > 1 ? ", " : "") + std::string(kNames[i]);
  return out;
}

bool HsvRange::contains(double h, double s, double v) const {
  const bool hue = h_min <= h_max ? (h >= h_min && h <= h_max) : (h >= h_min || h <= h_max);
  return hue && s >= s_min && s <= s_max && v >= v_min && v <= v_max;
}

bool RgbRange::contains(int r, int g, int b) const {
  return r >= r_min && r <= r_max && g >= g_min && g <= g_max && b >= b_min && b <= b_max;
}

void ColorTable::add_range(const HsvRange& range, ColorClass c) {
  const BinColors& b = bins();
  for (int i = 0; i < kBins; ++i) {
    if (table_[i] != 0) continue;
    const cv::Vec3f& hsv = b.hsv.at<cv::Vec3f>(i);
    if (range.contains(hsv[0], hsv[1], hsv[2])) table_[i] = static_cast<std::uint8_t>(c);
  }
}

void ColorTable::add_range(const RgbRange& range, ColorClass c) {
  const BinColors& b = bins();
  for (int i = 0; i < kBins; ++i) {
    if (table_[i] != 0) continue;
    const cv::Vec3f& rgb = b.rgb.at<cv::Vec3f>(i);
    if (range.contains(static_cast<int>(rgb[0]), static_cast<int>(rgb[1]), static_cast<int>(rgb[2])))
      table_[i] = static_cast<std::uint8_t>(c);
  }
}

void ColorTable::overlay(const ColorTable& other) {
  for (int i = 0; i < kBins; ++i)
    if (other.table_[i] != 0) table_[i] = other.table_[i];
}

int ColorTable::count(ColorClass c) const {
  return static_cast<int>(std::count(table_.begin(), table_.end(), static_cast<std::uint8_t>(c)));
}

void ColorTable::save(const std::string& path) const {
  const cv::Mat img(128, 256, CV_8UC1, const_cast<std::uint8_t*>(table_.data()));
  if (!cv::imwrite(path, img)) throw std::runtime_error(path + ": cannot write colour table");
}

ColorTable ColorTable::load(const std::string& path) {
  const cv::Mat img = cv::imread(path, cv::IMREAD_UNCHANGED);
  if (img.empty()) throw std::runtime_error(path + ": cannot read colour table image");
  if (img.rows != 128 || img.cols != 256 || img.type() != CV_8UC1)
    throw std::runtime_error(path + ": expected a 256x128 8-bit grey colour table, got " + std::to_string(img.cols) +
                             "x" + std::to_string(img.rows) + " with " + std::to_string(img.channels()) + " channel(s)");
  ColorTable t;
  for (int i = 0; i < kBins; ++i) {
    const std::uint8_t v = img.at<std::uint8_t>(i / 256, i % 256);
    if (v >= kColorClasses)
      throw std::runtime_error(path + ": bin " + std::to_string(i) + " holds unknown class " + std::to_string(v));
    t.table_[i] = v;
  }
  return t;
}

}  // namespace mrt::recvision
