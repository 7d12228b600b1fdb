#include "polar/transform.h"

#include <gtest/gtest.h>

namespace polar {
namespace {

TEST(Transform, TranslateAddsToPosition) {
    Transform t;
    t.translate(3, -4);
    t.translate(1, 1);
    EXPECT_EQ(t.position(), Vec2(4, -3));
}

TEST(Transform, ScaleAddsToFactors) {
    Transform t;
    t.scale(0.5);
    t.scale(1.0, -3.0);
    EXPECT_EQ(t.scaleFactors(), Vec2(2.5, -1.5));
}

TEST(Transform, WorldMatrixIsTranslationRotationScale) {
    Transform t(Vec2(10, 20), kHalfPi, Vec2(2, 3));
    // world(q) = p + R(θ)·diag(sx, sy)·q: (1, 0) → scale → (2, 0) → rotate 90° → (0, 2) → + p.
    Vec2 w = t.apply(Vec2(1, 0));
    EXPECT_NEAR(w.x(), 10, 1e-12);
    EXPECT_NEAR(w.y(), 22, 1e-12);
    Eigen::Vector3d h = t.matrix() * Eigen::Vector3d(0, 1, 1);  // (0, 3) → (−3, 0) → + p
    EXPECT_NEAR(h.x(), 7, 1e-12);
    EXPECT_NEAR(h.y(), 20, 1e-12);
}

TEST(Transform, MillionSmallRotationsDoNotDrift) {
    Transform t(Vec2(5, 5), 0.0, Vec2(2, 0.5));
    for (int i = 0; i < 1000000; ++i) t.rotate(0.001);
    Mat2 expected = rotationMatrix(t.rotation()) * Vec2(2, 0.5).asDiagonal();
    EXPECT_LT((t.linear() - expected).cwiseAbs().maxCoeff(), 1e-5);
    // The linear part is a rotation times the scale: its columns are orthogonal with lengths 2, 0.5.
    EXPECT_NEAR(t.linear().col(0).dot(t.linear().col(1)), 0.0, 1e-12);
    EXPECT_NEAR(t.linear().col(0).norm(), 2.0, 1e-12);
    EXPECT_NEAR(std::remainder(t.rotation() - 1000.0, kTwoPi), 0.0, 1e-8);
    EXPECT_EQ(t.position(), Vec2(5, 5));
}

}  // namespace
}  // namespace polar
