// recvision_calibrate --out LUT.png [--calib FILE] [--grow N] --sample CLASS:IMAGE:MASK...
// Builds (or extends) RecVision's colour look-up table from marked images:
// every pixel of IMAGE where MASK is not black is a sample of CLASS. Each
// RGB bin gets the class most of its samples have; bins without samples
// next to a labelled bin (up to N bins away) take its class; with --calib
// the result is laid over that file's table (its ranges and lut). Prints
// per class the samples, the bins and the bins disputed with another class.
// Reference the table from the calibration file with `lut: LUT.png`.
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <array>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "mrt_common/cli.h"
#include "mrt_common/parse_error.h"
#include "mrt_recvision/calibration.h"

using namespace mrt::recvision;

namespace {

struct Sample {
  ColorClass cls;
  cv::Mat rgb, mask;
};

Sample read_sample(const std::string& spec) {
  const auto a = spec.find(':'), b = spec.find(':', a == std::string::npos ? a : a + 1);
  if (a == std::string::npos || b == std::string::npos)
    throw std::invalid_argument("--sample '" + spec + "': expected CLASS:IMAGE:MASK");
  Sample s;
  if (!parse_color(spec.substr(0, a), s.cls))
    throw std::invalid_argument("--sample '" + spec + "': unknown colour class '" + spec.substr(0, a) + "'");
  const std::string img = spec.substr(a + 1, b - a - 1), mask = spec.substr(b + 1);
  const cv::Mat bgr = cv::imread(img, cv::IMREAD_COLOR);
  if (bgr.empty()) throw std::runtime_error(img + ": cannot read image");
  cv::cvtColor(bgr, s.rgb, cv::COLOR_BGR2RGB);
  s.mask = cv::imread(mask, cv::IMREAD_GRAYSCALE);
  if (s.mask.empty()) throw std::runtime_error(mask + ": cannot read mask");
  if (s.mask.size() != s.rgb.size()) throw std::runtime_error(mask + ": mask and image differ in size");
  return s;
}

// Spreads every labelled bin to unlabelled neighbours, `grow` times.
void grow(ColorTable& t, int times) {
  for (int k = 0; k < times; ++k) {
    ColorTable next = t;
    for (int i = 0; i < ColorTable::kBins; ++i) {
      if (t.data()[i] == 0) continue;
      const int r = i >> 10, g = (i >> 5) & 31, b = i & 31;
      for (int dr = -1; dr <= 1; ++dr)
        for (int dg = -1; dg <= 1; ++dg)
          for (int db = -1; db <= 1; ++db) {
            const int rr = r + dr, gg = g + dg, bb = b + db;
            if (rr < 0 || gg < 0 || bb < 0 || rr > 31 || gg > 31 || bb > 31) continue;
            const int j = (rr << 10) | (gg << 5) | bb;
            if (t.data()[j] == 0 && next.data()[j] == 0)
              next.set(std::uint8_t(rr << 3), std::uint8_t(gg << 3), std::uint8_t(bb << 3),
                       static_cast<ColorClass>(t.data()[i]));
          }
    }
    t = next;
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Builds RecVision's colour look-up table from images with masks", "recvision_calibrate"};
  std::string out, calib;
  std::vector<std::string> specs;
  int grow_bins = 1;
  app.add_option("--out", out, "colour table to write (PNG)")->required();
  app.add_option("--calib", calib, "calibration file whose table is extended");
  app.add_option("--grow", grow_bins, "spread labels to unlabelled bins this many bins away")->check(CLI::Range(0, 8));
  app.add_option("--sample", specs, "CLASS:IMAGE:MASK, repeatable")->required();
  if (const int rc = mrt::cli::parse_cli(app, argc, argv); rc >= 0) return rc;
  try {
    std::vector<std::array<int, kColorClasses>> counts(ColorTable::kBins, std::array<int, kColorClasses>{});
    std::array<long, kColorClasses> pixels{};
    for (const std::string& spec : specs) {
      const Sample s = read_sample(spec);
      for (int v = 0; v < s.rgb.rows; ++v)
        for (int u = 0; u < s.rgb.cols; ++u) {
          if (!s.mask.at<std::uint8_t>(v, u)) continue;
          const cv::Vec3b& p = s.rgb.at<cv::Vec3b>(v, u);
          ++counts[ColorTable::index(p[0], p[1], p[2])][int(s.cls)];
          ++pixels[int(s.cls)];
        }
    }
    ColorTable learned;
    std::array<int, kColorClasses> disputed{};
    for (int i = 0; i < ColorTable::kBins; ++i) {
      int best = 0, labels = 0;
      for (int c = 1; c < kColorClasses; ++c) {
        labels += counts[i][c] > 0;
        if (counts[i][c] > counts[i][best]) best = c;
      }
      if (best == 0) continue;
      if (labels > 1) ++disputed[best];
      learned.set(std::uint8_t((i >> 10) << 3), std::uint8_t(((i >> 5) & 31) << 3), std::uint8_t((i & 31) << 3),
                  static_cast<ColorClass>(best));
    }
    grow(learned, grow_bins);
    ColorTable table = calib.empty() ? ColorTable() : load_calibration(calib).colors;
    table.overlay(learned);
    table.save(out);
    std::printf("class,samples,learned_bins,disputed_bins,table_bins\n");
    for (int c = 1; c < kColorClasses; ++c)
      std::printf("%s,%ld,%d,%d,%d\n", color_name(ColorClass(c)), pixels[c], learned.count(ColorClass(c)),
                  disputed[c], table.count(ColorClass(c)));
  } catch (const mrt::common::ParseError& e) {
    std::cerr << "recvision_calibrate: " << e.what() << "\n";
    return 2;
  } catch (const std::invalid_argument& e) {
    std::cerr << "recvision_calibrate: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "recvision_calibrate: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
