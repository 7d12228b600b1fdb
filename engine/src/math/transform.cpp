#include "polar/transform.h"

#include <cmath>

namespace polar {

Transform::Transform(const Vec2& position, double rotation, const Vec2& scale)
    : position_(position), scale_(scale) {
    setRotation(rotation);
}

void Transform::translate(double dx, double dy) {
    position_.x() += dx;
    position_.y() += dy;
}

void Transform::rotate(double dTheta) {
    setRotation(angle_ + dTheta);
}

void Transform::setRotation(double radians) {
    // remainder is exact (no rounding), so the wrap itself adds no error. Within [−π, π] it returns
    // its argument unchanged (|x/2π| ≤ 1/2 rounds to 0, ties to even), so the library call, a large
    // share of a physics step, is only made outside.
    static_assert(kTwoPi == 2 * kPi);
    angle_ = std::fabs(radians) <= kPi ? radians : std::remainder(radians, kTwoPi);
    trig::sincos(angle_, sin_, cos_);
}

void Transform::scale(double fx, double fy) {
    scale_.x() += fx;
    scale_.y() += fy;
}

Mat2 Transform::rotationMatrix() const {
    Mat2 r;
    r << cos_, -sin_, sin_, cos_;
    return r;
}

Mat2 Transform::linear() const {
    Mat2 l;
    l << cos_ * scale_.x(), -sin_ * scale_.y(), sin_ * scale_.x(), cos_ * scale_.y();
    return l;
}

Mat3 Transform::matrix() const {
    Mat3 m = Mat3::Identity();
    m.topLeftCorner<2, 2>() = linear();
    m(0, 2) = position_.x();
    m(1, 2) = position_.y();
    return m;
}

}  // namespace polar
