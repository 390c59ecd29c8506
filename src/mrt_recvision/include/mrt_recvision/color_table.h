// Colour classification by look-up table (ROS-free): 32 x 32 x 32 bins of
// RGB (the 3 high bits dropped per channel), one colour class per bin, so
// classifying a pixel is one shift-or and one load. The table is built
// from colour classes given as HSV or RGB ranges, labelled RGB samples, and
// (by recvision_calibrate) from pixels marked in images.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace mrt::recvision {

/// The colour classes RecVision knows (the symbols of the percepts'
/// `color` attribute, spelled as mrt_sim's world files spell them). kNone
/// is "unclassified". Purple, beige, grey and bronze are the museum's
/// (FollowMe's visitor badge, floor, walls, an exhibit).
enum class ColorClass : std::uint8_t {
  kNone = 0, kGreen, kWhite, kOrange, kYellow, kBlue, kBlack, kCyan, kMagenta, kRed,
  kPurple, kBeige, kGrey, kBronze
};
constexpr int kColorClasses = 14;

/// "green", "white", ...; "none" for kNone.
const char* color_name(ColorClass c);
/// The class named `name`; false if there is none.
bool parse_color(const std::string& name, ColorClass& out);
/// Every class name but "none", comma-separated (for error messages).
std::string color_class_list();

/// A colour range: hue in degrees [h_min, h_max] (wrapping through 0 when
/// h_min > h_max), saturation and value in [0, 1], all inclusive.
struct HsvRange {
  double h_min = 0, h_max = 360, s_min = 0, s_max = 1, v_min = 0, v_max = 1;
  bool contains(double h, double s, double v) const;
};
/// An RGB box, channels 0..255 inclusive.
struct RgbRange {
  int r_min = 0, r_max = 255, g_min = 0, g_max = 255, b_min = 0, b_max = 255;
  bool contains(int r, int g, int b) const;
};

class ColorTable {
 public:
  static constexpr int kBins = 32 * 32 * 32;

  ColorTable() { table_.fill(0); }

  static int index(std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    return ((r >> 3) << 10) | ((g >> 3) << 5) | (b >> 3);
  }
  ColorClass classify(std::uint8_t r, std::uint8_t g, std::uint8_t b) const {
    return static_cast<ColorClass>(table_[index(r, g, b)]);
  }
  /// Class of a pixel given as a pointer to its R, G, B bytes.
  std::uint8_t lookup(const std::uint8_t* rgb) const { return table_[index(rgb[0], rgb[1], rgb[2])]; }

  /// Every bin whose centre colour lies in the range and is still
  /// unclassified gets `c` (so ranges given first take precedence).
  void add_range(const HsvRange& range, ColorClass c);
  void add_range(const RgbRange& range, ColorClass c);
  /// The bin of one RGB sample gets `c`, whatever it held.
  void set(std::uint8_t r, std::uint8_t g, std::uint8_t b, ColorClass c) { table_[index(r, g, b)] = static_cast<std::uint8_t>(c); }
  /// Bins classified in `other` override this table's.
  void overlay(const ColorTable& other);

  /// Number of bins holding `c`.
  int count(ColorClass c) const;

  const std::array<std::uint8_t, kBins>& data() const { return table_; }

  /// As a 256 x 128 8-bit PNG (bin i at row i / 256, column i % 256, value
  /// = class). load() throws std::runtime_error naming the file if it is
  /// not such an image or holds an unknown class.
  void save(const std::string& path) const;
  static ColorTable load(const std::string& path);

 private:
  std::array<std::uint8_t, kBins> table_;
};

}  // namespace mrt::recvision
