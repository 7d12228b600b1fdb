#include "polar/math.h"

#include <cmath>

namespace polar {

double reduceDegrees(double degrees) {
    double r = std::fmod(degrees, 360.0);
    if (r < 0) r += 360.0;
    // fmod(-1e-20, 360) + 360 rounds to 360: keep the half-open range.
    return r >= 360.0 ? 0.0 : r;
}

double reduceRadians(double radians) {
    double r = std::fmod(radians, kTwoPi);
    if (r < 0) r += kTwoPi;
    return r >= kTwoPi ? 0.0 : r;
}

namespace trig {
namespace {

// π/2 split into three parts (fdlibm's values) so that x − q·π/2 is exact for |q| < 2²⁰.
constexpr double kPio2Hi = 1.57079632673412561417e+00;
constexpr double kPio2Mid = 6.07710050630396597660e-11;
constexpr double kPio2Lo = 2.02226624871116645580e-21;
constexpr double kTwoOverPi = 6.36619772367581382433e-01;

// Taylor series on |r| ≤ π/4: the first omitted term is below 5e-17.
double sinPoly(double r) {
    double z = r * r;
    double p = -1.0 / 1307674368000.0;  // −1/15!
    p = p * z + 1.0 / 6227020800.0;     // 1/13!
    p = p * z - 1.0 / 39916800.0;       // −1/11!
    p = p * z + 1.0 / 362880.0;         // 1/9!
    p = p * z - 1.0 / 5040.0;           // −1/7!
    p = p * z + 1.0 / 120.0;            // 1/5!
    p = p * z - 1.0 / 6.0;              // −1/3!
    return r + r * z * p;
}

double cosPoly(double r) {
    double z = r * r;
    double p = 1.0 / 20922789888000.0;  // 1/16!
    p = p * z - 1.0 / 87178291200.0;    // −1/14!
    p = p * z + 1.0 / 479001600.0;      // 1/12!
    p = p * z - 1.0 / 3628800.0;        // −1/10!
    p = p * z + 1.0 / 40320.0;          // 1/8!
    p = p * z - 1.0 / 720.0;            // −1/6!
    p = p * z + 1.0 / 24.0;             // 1/4!
    return 1.0 - 0.5 * z + z * z * p;
}

// atan on |t| ≤ 0.1: Taylor series t − t³/3 + t⁵/5 − …; the first omitted term is below 1e-20.
double atanSmall(double t) {
    double z = t * t;
    double p = 1.0 / 19.0;
    p = -p * z + 1.0 / 17.0;
    p = -p * z + 1.0 / 15.0;
    p = -p * z + 1.0 / 13.0;
    p = -p * z + 1.0 / 11.0;
    p = -p * z + 1.0 / 9.0;
    p = -p * z + 1.0 / 7.0;
    p = -p * z + 1.0 / 5.0;
    p = -p * z + 1.0 / 3.0;
    return t - t * z * p;
}

// atan on [0, 1].
double atanUnit(double t) {
    constexpr double kTanPiOver8 = 0.41421356237309504880;
    constexpr double kQuarterPi = 0.78539816339744830962;
    double base = 0.0;
    if (t > kTanPiOver8) {  // atan t = π/4 + atan((t − 1)/(t + 1)), now |t| ≤ tan(π/8)
        base = kQuarterPi;
        t = (t - 1.0) / (t + 1.0);
    }
    // Halve the angle twice: atan t = 2·atan(t / (1 + √(1 + t²))), so |t| ≤ 0.099.
    t = t / (1.0 + std::sqrt(1.0 + t * t));
    t = t / (1.0 + std::sqrt(1.0 + t * t));
    return base + 4.0 * atanSmall(t);
}

}  // namespace

void sincos(double x, double& s, double& c) {
    if (!std::isfinite(x)) {
        s = c = x - x;  // NaN, as libm gives
        return;
    }
    // x = q·π/2 + r with |r| ≤ π/4 (a little more for huge |x|, where precision is lost anyway).
    double q = std::floor(x * kTwoOverPi + 0.5);
    double r = ((x - q * kPio2Hi) - q * kPio2Mid) - q * kPio2Lo;
    double sr = sinPoly(r);
    double cr = cosPoly(r);
    long quadrant = static_cast<long>(std::fmod(q, 4.0));
    if (quadrant < 0) quadrant += 4;
    switch (quadrant) {
        case 0:
            s = sr;
            c = cr;
            break;
        case 1:
            s = cr;
            c = -sr;
            break;
        case 2:
            s = -sr;
            c = -cr;
            break;
        default:
            s = -cr;
            c = sr;
            break;
    }
}

double sin(double x) {
    double s, c;
    sincos(x, s, c);
    return s;
}

double cos(double x) {
    double s, c;
    sincos(x, s, c);
    return c;
}

double atan2(double y, double x) {
    if (std::isnan(x) || std::isnan(y)) return x + y;
    double ax = std::fabs(x), ay = std::fabs(y);
    if (ax == 0.0 && ay == 0.0) return 0.0;
    double a;
    if (std::isinf(ax) || std::isinf(ay)) {
        a = (std::isinf(ax) && std::isinf(ay)) ? kPi / 4 : (std::isinf(ay) ? kHalfPi : 0.0);
    } else if (ay <= ax) {
        a = atanUnit(ay / ax);
    } else {
        a = kHalfPi - atanUnit(ax / ay);
    }
    if (x < 0) a = kPi - a;
    return y < 0 ? -a : a;
}

}  // namespace trig

Mat2 rotationMatrix(double radians) {
    double s, c;
    trig::sincos(radians, s, c);
    Mat2 r;
    r << c, -s, s, c;
    return r;
}

}  // namespace polar
