#pragma once
#include "polar/math.h"

namespace polar {

// A 2D placement: the homogeneous 3×3 matrix M = T(position) · R(θ) · S(sx, sy).
//
// Why keep it as its factors? A transform is changed by giving only the change (translate, rotate,
// scale), and each change acts on its own factor: rotation and scale act about the object's own
// position, never on the translation. Keeping the factors makes that true by construction, and it
// keeps the rotation a rotation forever: θ is one wrapped number, R(θ) is rebuilt from it with the
// engine's own trigonometry, so a million small turns cannot drift into a shear. Because each change
// touches only its own factor, the changes of one update may come in any order (rotation, then
// scale, then translation, or any other) and give the same matrix.
class Transform {
  public:
    Transform() = default;
    Transform(const Vec2& position, double rotation, const Vec2& scale);

    // Adds (dx, dy) to the position.
    void translate(double dx, double dy);
    void translate(const Vec2& delta) { translate(delta.x(), delta.y()); }
    // Pre-multiplies the rotation by R(dθ): R ← R(dθ)·R. Counter-clockwise for dθ > 0.
    void rotate(double dTheta);
    // Adds f to both scale factors, or fx and fy to each. A negative factor mirrors.
    void scale(double f) { scale(f, f); }
    void scale(double fx, double fy);

    void setPosition(const Vec2& position) { position_ = position; }
    void setRotation(double radians);
    void setScale(const Vec2& scale) { scale_ = scale; }

    const Vec2& position() const { return position_; }
    // θ in radians, in [−π, π].
    double rotation() const { return angle_; }
    const Vec2& scaleFactors() const { return scale_; }

    // R(θ).
    Mat2 rotationMatrix() const;
    // The linear part L = R(θ)·S(sx, sy).
    Mat2 linear() const;
    // The full homogeneous matrix T·R·S.
    Mat3 matrix() const;
    // world(q) = p + R(θ)·diag(sx, sy)·q.
    Vec2 apply(const Vec2& q) const { return position_ + linear() * q; }

  private:
    friend struct TransformFactors;  // the numbers as stored, kept to the bit (engine/src/math/)

    Vec2 position_ = Vec2::Zero();
    double angle_ = 0.0;
    double cos_ = 1.0;
    double sin_ = 0.0;
    Vec2 scale_ = Vec2::Ones();
};

}  // namespace polar
