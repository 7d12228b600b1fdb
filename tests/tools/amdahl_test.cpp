// The benchmarks' Amdahl fit (tools/bench/amdahl.h): the serial fraction a measured speed-up gives,
// the gains it allows, clamping when noise puts the speed-up outside [1, N], and phases composed.
#include "amdahl.h"

#include <gtest/gtest.h>

#include <vector>

namespace polar::bench {
namespace {

TEST(Amdahl, TheSerialFractionGivesBackTheMeasuredSpeedUp) {
    // 10 ms → 5.5 ms on 2 threads: S = 1.818…, s = (2/S − 1)/(2 − 1) = 0.1.
    const AmdahlFit fit = fitAmdahl(10.0, 5.5, 2.0);
    EXPECT_NEAR(fit.speedUp, 10.0 / 5.5, 1e-12);
    EXPECT_NEAR(fit.serialFraction, 0.1, 1e-12);
    EXPECT_FALSE(fit.clamped);
    EXPECT_NEAR(fit.gainAt(2.0), 10.0 / 5.5, 1e-12);
    EXPECT_NEAR(fit.gainAt(16.0), 1.0 / (0.1 + 0.9 / 16.0), 1e-12);  // 6.4
    EXPECT_NEAR(fit.gainAt(64.0), 1.0 / (0.1 + 0.9 / 64.0), 1e-12);
    // 4 threads: 10 → 3.25 ms is s = 0.1 too.
    EXPECT_NEAR(fitAmdahl(10.0, 3.25, 4.0).serialFraction, 0.1, 1e-12);
}

TEST(Amdahl, SpeedUpsOutsideOneToNAreClamped) {
    const AmdahlFit slower = fitAmdahl(10.0, 12.0, 2.0);  // slower on 2 threads: all serial
    EXPECT_EQ(slower.serialFraction, 1.0);
    EXPECT_TRUE(slower.clamped);
    EXPECT_EQ(slower.gainAt(16.0), 1.0);
    const AmdahlFit superlinear = fitAmdahl(10.0, 4.0, 2.0);  // 2.5× on 2 threads: none serial
    EXPECT_EQ(superlinear.serialFraction, 0.0);
    EXPECT_TRUE(superlinear.clamped);
    EXPECT_EQ(superlinear.gainAt(16.0), 16.0);
    EXPECT_FALSE(fitAmdahl(10.0, 5.0, 2.0).clamped);
    EXPECT_EQ(fitAmdahl(0.0, 1.0, 2.0).serialFraction, 0.0);  // too short to time: parallel
}

TEST(Amdahl, PhasesComposeByTheirOwnFits) {
    // A serial phase (10 → 10 ms) and a parallel one (10 → 5 ms) on 2 threads: at 16 threads
    // 10 + 10/16 ms of the 20.
    const std::vector<PhaseTime> phases{{"serial", 10.0, 10.0}, {"parallel", 10.0, 5.0}};
    EXPECT_NEAR(projectedGain(phases, 2.0, 16.0), 20.0 / (10.0 + 10.0 / 16.0), 1e-12);
    EXPECT_NEAR(projectedGain(phases, 2.0, 2.0), 20.0 / 15.0, 1e-12);
}

}  // namespace
}  // namespace polar::bench
