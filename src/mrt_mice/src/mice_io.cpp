#include "mrt_mice/mice_io.h"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <map>

#include "mrt_common/angle.h"
#include "mrt_common/csv.h"
#include "mrt_common/yaml_reader.h"

namespace mrt::mice {

using mrt::common::CsvReader;
using mrt::common::ParseError;
using mrt::common::YamlReader;

namespace {

double number(const YamlReader& r, const YAML::Node& parent, const std::string& key, bool required,
              double fallback) {
  const YAML::Node n = parent[key];
  if (!n) {
    if (required) r.fail(parent, "expected a key '" + key + "'");
    return fallback;
  }
  if (!n.IsScalar()) r.fail(n, "expected a number for '" + key + "'");
  double v;
  if (!YamlReader::decode(n, v)) r.fail(n, "expected a number for '" + key + "', got '" + n.Scalar() + "'");
  if (!std::isfinite(v)) r.fail(n, "expected a finite number for '" + key + "'");
  return v;
}

MouseParams mouse(const YamlReader& r, const YAML::Node& root, const std::string& key) {
  const YAML::Node n = root[key];
  if (!n) r.fail(root, "expected a key '" + key + "' (the " + key + " mouse)");
  if (!n.IsMap()) r.fail(n, "expected a map {x, y, yaw, counts_per_m} for '" + key + "'");
  for (const auto& kv : n) {
    const std::string k = kv.first.Scalar();
    if (k != "x" && k != "y" && k != "yaw" && k != "counts_per_m")
      r.fail(kv.first, "unknown key '" + k + "' in '" + key + "' (expected x, y, yaw, counts_per_m)");
  }
  MouseParams m;
  m.mount = Pose2D(number(r, n, "x", true, 0), number(r, n, "y", true, 0), number(r, n, "yaw", false, 0.0));
  m.counts_per_m = number(r, n, "counts_per_m", true, 0);
  if (!(m.counts_per_m > 0.0)) r.fail(n["counts_per_m"], "expected counts_per_m > 0");
  return m;
}

}  // namespace

MiceParams parse_params(const std::string& text, const std::string& file) {
  const YamlReader r(file);
  const YAML::Node root = r.load(text);
  if (!root.IsMap()) throw ParseError(file, 1, 1, "expected a map with keys 'left' and 'right'");
  // A misspelt optional key would otherwise silently keep its default.
  r.map(root, "the parameter file",
        {"left", "right", "detection_factor", "detection_relative", "derived", "calibration"});
  MiceParams p;
  p.left = mouse(r, root, "left");
  p.right = mouse(r, root, "right");
  p.detection_factor = number(r, root, "detection_factor", false, p.detection_factor);
  p.detection_relative = number(r, root, "detection_relative", false, p.detection_relative);
  try {
    p.validate();
  } catch (const std::invalid_argument& e) {
    throw ParseError(file, 0, 0, e.what());
  }
  return p;
}

MiceParams load_params(const std::string& path) {
  return parse_params(mrt::common::read_file(path), path);
}

void write_params(std::ostream& out, const MiceParams& p, const CalibrationResult* calib) {
  using mrt::common::rad_to_deg;
  YAML::Emitter e;
  e.SetDoublePrecision(10);
  auto mouse_map = [&](const char* key, const MouseParams& m) {
    e << YAML::Key << key << YAML::Value << YAML::Flow << YAML::BeginMap;
    e << YAML::Key << "x" << YAML::Value << m.mount.x;
    e << YAML::Key << "y" << YAML::Value << m.mount.y;
    e << YAML::Key << "yaw" << YAML::Value << m.mount.theta;
    e << YAML::Key << "counts_per_m" << YAML::Value << m.counts_per_m;
    e << YAML::EndMap;
  };
  const ManualGeometry g = manual_geometry(p);
  e << YAML::Comment("mrt_mice parameters: mount pose of each mouse in base_link (m, rad), resolution (counts/m)");
  e << YAML::BeginMap;
  mouse_map("left", p.left);
  mouse_map("right", p.right);
  e << YAML::Key << "detection_factor" << YAML::Value << p.detection_factor;
  e << YAML::Key << "detection_relative" << YAML::Value << p.detection_relative;
  e << YAML::Key << "derived" << YAML::Value << YAML::BeginMap;
  e << YAML::Key << "D_m" << YAML::Value << g.D;
  e << YAML::Key << "sigma_l_deg" << YAML::Value << rad_to_deg(g.sigma_l);
  e << YAML::Key << "sigma_r_deg" << YAML::Value << rad_to_deg(g.sigma_r);
  e << YAML::Key << "delta_deg" << YAML::Value << rad_to_deg(g.delta);
  e << YAML::EndMap;
  if (calib) {
    e << YAML::Key << "calibration" << YAML::Value << YAML::BeginMap;
    e << YAML::Key << "pushes" << YAML::Value << calib->pushes;
    e << YAML::Key << "turns" << YAML::Value << calib->turns;
    e << YAML::Key << "rms_residual_counts" << YAML::Value << calib->rms_residual;
    e << YAML::Key << "runs" << YAML::Value << YAML::BeginSeq;
    for (const auto& r : calib->residuals) {
      e << YAML::Flow << YAML::BeginMap;
      e << YAML::Key << "source" << YAML::Value << r.source;
      e << YAML::Key << "kind" << YAML::Value
        << (r.kind == CalibrationRun::Kind::kPush ? "push" : "turn");
      e << YAML::Key << "left_counts" << YAML::Value << r.left;
      e << YAML::Key << "right_counts" << YAML::Value << r.right;
      e << YAML::EndMap;
    }
    e << YAML::EndSeq << YAML::EndMap;
  }
  e << YAML::EndMap;
  out << e.c_str() << '\n';
}

std::vector<ReadingRow> parse_readings_csv(std::istream& in, const std::string& file) {
  CsvReader csv(in, file);
  csv.require_header({"t", "left_dx", "left_dy", "right_dx", "right_dy"});
  std::vector<ReadingRow> out;
  out.reserve(csv.rows().size());
  for (const auto& row : csv.rows()) {
    ReadingRow r;
    r.line = row.line;
    r.t = csv.number(row, 0);
    if (!out.empty() && r.t < out.back().t)
      throw ParseError(file, row.line, row.columns[0],
                       "expected t >= " + std::to_string(out.back().t) + " (time must not decrease)");
    r.counts.left_dx = csv.integer(row, 1);
    r.counts.left_dy = csv.integer(row, 2);
    r.counts.right_dx = csv.integer(row, 3);
    r.counts.right_dy = csv.integer(row, 4);
    out.push_back(r);
  }
  return out;
}

std::vector<ReadingRow> read_readings_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ParseError(path, 0, 0, "cannot open file");
  return parse_readings_csv(in, path);
}

std::vector<CalibrationRun> parse_calibration_csv(std::istream& in, const std::string& file) {
  CsvReader csv(in, file);
  csv.require_header({"run", "kind", "amount", "left_dx", "left_dy", "right_dx", "right_dy"});
  std::vector<CalibrationRun> runs;
  std::map<long long, std::size_t> index;
  for (const auto& row : csv.rows()) {
    const long long id = csv.integer(row, 0);
    const std::string& kind_s = row.fields[1];
    CalibrationRun::Kind kind;
    if (kind_s == "push")
      kind = CalibrationRun::Kind::kPush;
    else if (kind_s == "turn")
      kind = CalibrationRun::Kind::kTurn;
    else
      throw ParseError(file, row.line, row.columns[1], "expected 'push' or 'turn', got '" + kind_s + "'");
    const double amount = csv.number(row, 2);
    if (amount == 0.0) throw ParseError(file, row.line, row.columns[2], "expected a non-zero amount");
    auto it = index.find(id);
    if (it == index.end()) {
      CalibrationRun r;
      r.kind = kind;
      r.amount = amount;
      r.source = file + ":" + std::to_string(row.line);
      index[id] = runs.size();
      runs.push_back(r);
      it = index.find(id);
    }
    CalibrationRun& r = runs[it->second];
    if (r.kind != kind || r.amount != amount)
      throw ParseError(file, row.line, row.columns[1],
                       "expected kind and amount of run " + std::to_string(id) + " as on " + r.source);
    r.counts.left_dx += csv.integer(row, 3);
    r.counts.left_dy += csv.integer(row, 4);
    r.counts.right_dx += csv.integer(row, 5);
    r.counts.right_dy += csv.integer(row, 6);
  }
  if (runs.empty()) throw ParseError(file, 0, 0, "expected at least one run");
  return runs;
}

std::vector<CalibrationRun> read_calibration_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ParseError(path, 0, 0, "cannot open file");
  return parse_calibration_csv(in, path);
}

}  // namespace mrt::mice
