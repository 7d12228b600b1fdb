#include "polar/transform.h"

#include <gtest/gtest.h>
#include <Eigen/LU>

#include <cmath>

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

// The largest difference between two matrices.
double maxDiff(const Mat2& a, const Mat2& b) {
    return (a - b).cwiseAbs().maxCoeff();
}

TEST(Transform, DefaultIsIdentity) {
    Transform t;
    EXPECT_EQ(t.matrix(), Mat3::Identity());
    EXPECT_EQ(t.apply(Vec2(3, -7)), Vec2(3, -7));
}

TEST(Transform, TranslateTakesAVectorToo) {
    Transform t(Vec2(1, 2), 0.3, Vec2(2, 2));
    t.translate(Vec2(-0.5, 4));
    EXPECT_EQ(t.position(), Vec2(0.5, 6));
    EXPECT_EQ(t.rotation(), 0.3);  // translation touches nothing else
    EXPECT_EQ(t.scaleFactors(), Vec2(2, 2));
}

TEST(Transform, UniformScaleAddsToBothFactors) {
    Transform t(Vec2::Zero(), 0.0, Vec2(1, 3));
    t.scale(0.25);
    EXPECT_EQ(t.scaleFactors(), Vec2(1.25, 3.25));
    t.scale(-1.25);
    EXPECT_EQ(t.scaleFactors(), Vec2(0, 2));
}

TEST(Transform, RotatePreMultipliesTheRotation) {
    Transform t(Vec2(0, 0), 0.4, Vec2(1, 1));
    Mat2 before = t.rotationMatrix();
    t.rotate(0.9);
    // R ← R(dθ)·R.
    EXPECT_LT(maxDiff(t.rotationMatrix(), rotationMatrix(0.9) * before), 1e-15);
    EXPECT_NEAR(t.rotation(), 1.3, 1e-15);
    // Counter-clockwise: +x turns toward +y.
    Transform q;
    q.rotate(kHalfPi);
    Vec2 x = q.apply(Vec2(1, 0));
    EXPECT_NEAR(x.x(), 0.0, 1e-16);
    EXPECT_NEAR(x.y(), 1.0, 1e-16);
    // The angle stays wrapped to [−π, π].
    Transform w;
    for (int i = 0; i < 7; ++i) w.rotate(1.0);
    EXPECT_LE(std::fabs(w.rotation()), kPi);
    EXPECT_NEAR(w.rotation(), 7.0 - kTwoPi, 1e-14);
}

TEST(Transform, RotationAndScaleActAboutTheObjectsOwnPosition) {
    Transform t;
    t.translate(100, -50);
    t.rotate(1.2);
    t.scale(2.0, 0.5);
    // The translation is untouched; the object's own origin stays where it is.
    EXPECT_EQ(t.position(), Vec2(100, -50));
    EXPECT_EQ(t.apply(Vec2::Zero()), Vec2(100, -50));
    EXPECT_EQ(t.matrix()(0, 2), 100.0);
    EXPECT_EQ(t.matrix()(1, 2), -50.0);
    // A point keeps its distance to the position under rotation: it turns about the position.
    Transform r(Vec2(100, -50), 0.0, Vec2(1, 1));
    Vec2 before = r.apply(Vec2(3, 4));
    r.rotate(2.0);
    Vec2 after = r.apply(Vec2(3, 4));
    EXPECT_NEAR((after - Vec2(100, -50)).norm(), 5.0, 1e-12);
    EXPECT_NEAR((before - Vec2(100, -50)).norm(), 5.0, 1e-12);
}

TEST(Transform, MatrixIsTRSFromItsFactorsForManyPlacements) {
    for (double angle : {-3.0, -1.0, 0.0, 0.5, 2.9}) {
        for (Vec2 s : {Vec2(1, 1), Vec2(2, 0.5), Vec2(-1, 1), Vec2(1e-3, 1e3)}) {
            Vec2 p(-12.5, 1e6);
            Transform t(p, angle, s);
            Mat3 T = Mat3::Identity(), R = Mat3::Identity(), S = Mat3::Identity();
            T(0, 2) = p.x();
            T(1, 2) = p.y();
            R(0, 0) = std::cos(angle), R(0, 1) = -std::sin(angle);
            R(1, 0) = std::sin(angle), R(1, 1) = std::cos(angle);
            S(0, 0) = s.x(), S(1, 1) = s.y();
            Mat3 expected = T * R * S;
            EXPECT_LT((t.matrix() - expected).cwiseAbs().maxCoeff(),
                      1e-12 * std::max(1.0, s.cwiseAbs().maxCoeff()));
            EXPECT_LT(maxDiff(t.linear(), expected.topLeftCorner<2, 2>()),
                      1e-12 * std::max(1.0, s.cwiseAbs().maxCoeff()));
            Vec2 q(3, -4);
            Vec2 viaMatrix = (t.matrix() * Eigen::Vector3d(q.x(), q.y(), 1)).head<2>();
            EXPECT_LT((t.apply(q) - viaMatrix).norm(), 1e-9);
        }
    }
}

TEST(Transform, UpdateOrderDoesNotChangeTheResult) {
    // The seed applies rotation, then scale, then translation; each acts on its own factor, so any
    // order of the same changes gives the same matrix.
    Transform a(Vec2(3, 4), 0.2, Vec2(1.5, 0.7)), b = a, c = a;
    a.rotate(0.6), a.scale(0.5, -0.2), a.translate(7, -1);
    b.translate(7, -1), b.scale(0.5, -0.2), b.rotate(0.6);
    c.scale(0.5, -0.2), c.translate(7, -1), c.rotate(0.6);
    EXPECT_EQ(a.matrix(), b.matrix());
    EXPECT_EQ(a.matrix(), c.matrix());
}

TEST(Transform, NegativeScaleMirrors) {
    Transform t(Vec2(10, 0), 0.0, Vec2(-1, 1));
    EXPECT_EQ(t.apply(Vec2(2, 3)), Vec2(8, 3));  // x flips about the object's position
    EXPECT_LT(t.linear().determinant(), 0.0);
    // Orientation reverses: a counter-clockwise pair of directions comes out clockwise.
    Vec2 ex = t.linear() * Vec2(1, 0), ey = t.linear() * Vec2(0, 1);
    EXPECT_LT(cross(ex, ey), 0.0);
    // Mirroring then turning keeps it mirrored, and turning does not undo it.
    t.rotate(1.0);
    EXPECT_LT(t.linear().determinant(), 0.0);
    // Scale −1 on both axes is a half turn, not a mirror.
    Transform h(Vec2::Zero(), 0.0, Vec2(-1, -1));
    EXPECT_GT(h.linear().determinant(), 0.0);
    Transform s;
    s.scale(-2.0);  // 1 + (−2) = −1 on both axes
    EXPECT_EQ(s.scaleFactors(), Vec2(-1, -1));
}

TEST(Transform, NonUniformlyScaledSpriteKeepsItsShapeWhileItTurns) {
    // A 2:0.5 stretched sprite: its world outline at angle θ is the outline at 0 turned by θ about
    // the position. With the wrong order (S·R) it would shear instead.
    const Vec2 p(40, -20);
    const std::vector<Vec2> corners = {Vec2(10, 10), Vec2(-10, 10), Vec2(-10, -10), Vec2(10, -10),
                                       Vec2(3, 7)};
    Transform flat(p, 0.0, Vec2(2, 0.5));
    for (double angle : {0.3, 1.0, kHalfPi, 2.5, -2.0}) {
        Transform turned = flat;
        turned.rotate(angle);
        Mat2 r = rotationMatrix(angle);
        for (std::size_t i = 0; i < corners.size(); ++i) {
            Vec2 expected = p + r * (flat.apply(corners[i]) - p);
            EXPECT_LT((turned.apply(corners[i]) - expected).norm(), 1e-12) << "angle " << angle;
            for (std::size_t j = 0; j < i; ++j) {
                double lengthFlat = (flat.apply(corners[i]) - flat.apply(corners[j])).norm();
                double lengthTurned = (turned.apply(corners[i]) - turned.apply(corners[j])).norm();
                EXPECT_NEAR(lengthTurned, lengthFlat, 1e-12);
            }
        }
        // The sprite's own axes stay perpendicular: no shear.
        EXPECT_NEAR(turned.linear().col(0).dot(turned.linear().col(1)), 0.0, 1e-15);
    }
}

TEST(Transform, MillionSmallRotationsMatchTheExactRotation) {
    Transform t(Vec2::Zero(), 0.0, Vec2(3, -0.25));
    for (int i = 0; i < 1000000; ++i) t.rotate(0.001);
    // 10⁶ · 0.001 = 1000 radians; compare with a rotation built independently by libm.
    Mat2 r;
    r << std::cos(1000.0), -std::sin(1000.0), std::sin(1000.0), std::cos(1000.0);
    EXPECT_LT(maxDiff(t.linear(), r * Vec2(3, -0.25).asDiagonal()), 1e-5);
    EXPECT_NEAR(t.linear().determinant(), -0.75, 1e-12);
}

TEST(Transform, RotateThenRotateBackRestores) {
    for (double theta : {1e-9, 0.001, 0.5, 3.0, -2.2, 10.0, 1e4}) {
        Transform t(Vec2(1, 2), 1.0, Vec2(2, 0.5));
        Mat3 before = t.matrix();
        t.rotate(theta);
        t.rotate(-theta);
        // Adding and removing θ rounds once each at the size of θ: a few ulps of 1 + |θ|.
        double tolerance = 4e-16 * (1 + std::fabs(theta)) * 4;
        EXPECT_NEAR(t.rotation(), 1.0, tolerance) << theta;
        EXPECT_LT((t.matrix() - before).cwiseAbs().maxCoeff(), 2 * tolerance) << theta;
        EXPECT_EQ(t.position(), Vec2(1, 2));
    }
}

TEST(Transform, SetRotationWrapsAndRebuildsTheMatrix) {
    Transform t;
    t.setRotation(kTwoPi * 3 + 0.25);
    EXPECT_NEAR(t.rotation(), 0.25, 1e-14);
    EXPECT_NEAR(t.rotationMatrix()(1, 0), std::sin(0.25), 1e-14);
    t.setScale(Vec2(4, 5));
    t.setPosition(Vec2(-1, -1));
    EXPECT_EQ(t.scaleFactors(), Vec2(4, 5));
    EXPECT_EQ(t.position(), Vec2(-1, -1));
}

}  // namespace
}  // namespace polar
