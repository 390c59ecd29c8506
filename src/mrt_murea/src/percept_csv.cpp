#include "mrt_murea/percept_csv.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>

#include "mrt_common/parse_error.h"
#include "mrt_common/percept_csv.h"

namespace mrt::murea {

using mrt::common::ParseError;

std::vector<PerceptFrame> read_percept_csv(std::istream& in, const std::string& file) {
  std::vector<PerceptFrame> frames;
  for (const mrt::common::PerceptCsvFrame& f : mrt::common::read_percept_csv(in, file)) {
    PerceptFrame out{f.id, f.line, {}, {}};
    for (const mrt::common::PerceptObject& o : f.objects) {
      const double distance = *o.number("distance"), bearing = *o.number("bearing");
      const double reliability = o.find("distance")->reliability;
      const auto cls = parse_feature_class(o.membership_class);
      if (!cls) {
        ++out.dropped.unknown_class;
      } else if (!std::isfinite(distance) || !std::isfinite(bearing) || !std::isfinite(reliability)) {
        ++out.dropped.non_finite;
      } else if (distance < 0.0 || !(reliability > 0.0) || reliability > 1.0) {
        ++out.dropped.out_of_range;
      } else {
        out.percepts.push_back({*cls, o.symbol("color"), distance, bearing, reliability});
      }
    }
    frames.push_back(std::move(out));
  }
  return frames;
}

std::vector<PerceptFrame> load_percept_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ParseError(path, 0, 0, "cannot open file");
  return read_percept_csv(in, path);
}

void write_result_header(std::ostream& out) {
  out << "frame,x,y,theta,evidence,ambiguous,alt_x,alt_y,alt_theta,alt_evidence,time_ms\n";
}

void write_result_row(std::ostream& out, const std::string& frame, const Result& r) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(4) << frame << ',' << r.estimate.mean.x << ',' << r.estimate.mean.y << ','
    << std::setprecision(5) << r.estimate.mean.theta << ',' << std::setprecision(4) << r.best.evidence << ','
    << (r.ambiguous ? 1 : 0) << ',';
  if (r.alternative)
    s << r.alternative->pose.x << ',' << r.alternative->pose.y << ',' << std::setprecision(5)
      << r.alternative->pose.theta << ',' << std::setprecision(4) << r.alternative->evidence;
  else
    s << ",,,";
  s << ',' << std::setprecision(3) << r.time_ms << '\n';
  out << s.str();
}

}  // namespace mrt::murea
