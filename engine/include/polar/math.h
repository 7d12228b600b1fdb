#pragma once
// Polarcade's math conventions, stated once for the whole engine:
//   - World units are arbitrary (the demo uses screen pixels); bound space is sprite pixels with the
//     origin at the sprite's centre.
//   - x points right, y points up, angles run counter-clockwise from +x.
//   - Degrees in files, radians in code.
//   - A world matrix is M = T(position) · R(rotation) · S(sx, sy).
//   - World positions are doubles, so a scene 10⁶ units from the origin behaves like one at it.
#include <Eigen/Core>

namespace polar {

using Vec2 = Eigen::Vector2d;
using Mat2 = Eigen::Matrix2d;
using Mat3 = Eigen::Matrix3d;

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kTwoPi = 6.28318530717958647692;
inline constexpr double kHalfPi = 1.57079632679489661923;

constexpr double degToRad(double degrees) {
    return degrees * (kPi / 180.0);
}
constexpr double radToDeg(double radians) {
    return radians * (180.0 / kPi);
}

// An angle in degrees reduced to [0, 360). Exact: fmod does not round.
double reduceDegrees(double degrees);
// An angle in radians reduced to [0, 2π).
double reduceRadians(double radians);

// 2D cross product (the z of the 3D one): positive when b is counter-clockwise from a.
inline double cross(const Vec2& a, const Vec2& b) {
    return a.x() * b.y() - a.y() * b.x();
}

// The engine's own trigonometry. It uses only +, −, ×, ÷ and sqrt, which IEEE 754 rounds the same
// everywhere, so its results are bit-identical across compilers and C libraries (libm's are not).
// Everything that feeds the simulation uses these, never std::sin and friends.
namespace trig {
double sin(double x);
double cos(double x);
void sincos(double x, double& s, double& c);
// The angle of (x, y) in (−π, π]; atan2(0, 0) is 0.
double atan2(double y, double x);
}  // namespace trig

// Rotation matrix R(θ) built with the engine's own trigonometry.
Mat2 rotationMatrix(double radians);

}  // namespace polar
