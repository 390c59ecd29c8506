// The benchmark's goals as a test: a reduced UMBmark (2 squares clockwise,
// 2 counter-clockwise instead of 5 + 5) with the systematic errors of
// bench/umbmark_bench.cpp, the staggered placement of the README (the one
// the README claims the slip figure for). Goals of issue 5: E_max,syst
// after calibration <= 20 mm, >= 95 % of the injected slips detected, and
// no false alarm on a clean sample.
#include <gtest/gtest.h>

#include <vector>

#include "umbmark.h"

using namespace mrt::mice;
using namespace mrt::mice::umbmark;

TEST(UMBmark, CalibratedErrorAndSlipDetectionMeetTheGoals) {
  const sim::SimMice mice = as_built(0.003);
  const CalibrationResult calib = calibrate_as_operator(mice, 99, nominal());
  MiceOdometry before(nominal()), after(calib.params);
  std::vector<Pose2D> cw_b, ccw_b, cw_a, ccw_a;
  for (int run = 0; run < 4; ++run) {
    const bool clockwise = run < 2;
    const auto e = run_square(1000 + run, clockwise, mice, {&after, &before}, nullptr);
    (clockwise ? cw_a : ccw_a).push_back(e[0]);
    (clockwise ? cw_b : ccw_b).push_back(e[1]);
  }
  const double ea = e_max_syst(cw_a, ccw_a), eb = e_max_syst(cw_b, ccw_b);
  RecordProperty("e_max_syst_after_mm", std::to_string(ea * 1000.0));
  EXPECT_LE(ea, 0.020) << "E_max,syst after calibration, m";
  // The calibration must matter: with the drawing's parameters the 5 degree
  // relative mount error alone turns the heading ~0.09 rad per 4 m side.
  EXPECT_GT(eb, 0.5) << "E_max,syst before calibration, m";

  Slips slips;
  slips.rate = 0.05;
  for (int run = 0; run < 2; ++run) {
    MiceOdometry o(calib.params);
    run_square(2000 + run, run % 2 == 0, mice, {&o}, &slips);
  }
  ASSERT_GT(slips.injected, 50);
  const double detected = static_cast<double>(slips.detected) / slips.injected;
  RecordProperty("slips_detected_fraction", std::to_string(detected));
  EXPECT_GE(detected, 0.95) << slips.detected << " of " << slips.injected;
  ASSERT_GT(slips.clean, 1000);
  EXPECT_EQ(slips.false_alarms, 0) << "of " << slips.clean << " clean samples";
}
