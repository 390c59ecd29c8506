// Calibration from synthetic pushes and turns (quantised exact readings).
#include <gtest/gtest.h>

#include <cmath>

#include "mrt_common/angle.h"
#include "mrt_mice/calibrator.h"
#include "test_util.h"

using namespace mrt::mice;

namespace {

std::vector<CalibrationRun> protocol(const MiceParams& truth, double push = 0.5) {
  std::vector<CalibrationRun> runs;
  for (int i = 0; i < 10; ++i) {
    test::QuantisedMice mice(truth);
    CalibrationRun r;
    r.kind = CalibrationRun::Kind::kPush;
    r.amount = push;
    r.counts = mice.step(push, 0.0, 0.0, 1.0);
    r.source = "push" + std::to_string(i);
    runs.push_back(r);
  }
  for (int i = 0; i < 5; ++i) {
    test::QuantisedMice mice(truth);
    CalibrationRun r;
    r.kind = CalibrationRun::Kind::kTurn;
    r.amount = 2 * M_PI;
    r.counts = mice.step(0.0, 0.0, 2 * M_PI, 1.0);
    r.source = "turn" + std::to_string(i);
    runs.push_back(r);
  }
  return runs;
}

TEST(Calibrator, RecoversGeneralPlacement) {
  const MiceParams truth = test::general_placement();
  const CalibrationResult res = calibrate(protocol(truth));
  EXPECT_EQ(res.pushes, 10);
  EXPECT_EQ(res.turns, 5);
  const auto& p = res.params;
  EXPECT_NEAR(p.left.counts_per_m, truth.left.counts_per_m, 1e-4 * truth.left.counts_per_m);
  EXPECT_NEAR(p.right.counts_per_m, truth.right.counts_per_m, 1e-4 * truth.right.counts_per_m);
  EXPECT_NEAR(p.left.mount.theta, truth.left.mount.theta, 1e-3);
  EXPECT_NEAR(p.right.mount.theta, truth.right.mount.theta, 1e-3);
  EXPECT_NEAR(p.left.mount.x, truth.left.mount.x, 1e-4);
  EXPECT_NEAR(p.left.mount.y, truth.left.mount.y, 1e-4);
  EXPECT_NEAR(p.right.mount.x, truth.right.mount.x, 1e-4);
  EXPECT_NEAR(p.right.mount.y, truth.right.mount.y, 1e-4);
  const ManualGeometry g = manual_geometry(truth), e = res.geometry;
  EXPECT_NEAR(e.D, g.D, 1e-3 * g.D);
  EXPECT_NEAR(e.delta, g.delta, 1e-3);
  EXPECT_LT(res.rms_residual, 1.0);  // counts: only quantisation is left
  EXPECT_EQ(res.residuals.size(), 15u);
}

TEST(Calibrator, ManualPlacementAndDerivedParameters) {
  const MiceParams truth = manual_placement(0.25, 15748.0);
  const CalibrationResult res = calibrate(protocol(truth));
  EXPECT_NEAR(res.geometry.D, 0.25, 1e-4);
  EXPECT_NEAR(res.geometry.delta, 0.0, 1e-3);
  EXPECT_NEAR(res.geometry.sigma_l, -M_PI / 2, 1e-3);
  EXPECT_NEAR(res.geometry.sigma_r, -M_PI / 2, 1e-3);
}

TEST(Calibrator, RejectsIncompleteProtocols) {
  auto runs = protocol(test::general_placement());
  std::vector<CalibrationRun> pushes(runs.begin(), runs.begin() + 10);
  std::vector<CalibrationRun> turns(runs.begin() + 10, runs.end());
  EXPECT_THROW(calibrate(pushes), std::invalid_argument);
  EXPECT_THROW(calibrate(turns), std::invalid_argument);
  runs[0].amount = 0.0;
  EXPECT_THROW(calibrate(runs), std::invalid_argument);
}

TEST(Calibrator, ResidualsShowABadRun) {
  auto runs = protocol(test::general_placement());
  runs[3].counts.left_dx -= 500;  // a slip in one push
  const CalibrationResult res = calibrate(runs);
  double worst = 0.0;
  std::string where;
  for (const auto& r : res.residuals)
    if (r.left > worst) {
      worst = r.left;
      where = r.source;
    }
  EXPECT_EQ(where, "push3");
  EXPECT_GT(worst, 400.0);
}

}  // namespace
