#include "polar/authoring/bounds_gen.h"

#include <algorithm>

#include "authoring/radial_field.h"

namespace polar {

FitQuality measureFit(const PixelSet& pixels, const Bound& bound, bool container) {
    RadialField field(pixels, bound.centre(), container);
    FitQuality q;
    q.pixels = pixels.count();
    double slackSum = 0.0;
    q.worstSlack = -kInf;
    for (int k = 0; k < FitQuality::kSlackDirections; ++k) {
        double degrees = k * 360.0 / FitQuality::kSlackDirections;
        double phi = degToRad(degrees);
        double limit = field.rayLimit(direction(phi));
        double r = bound.radius(phi);
        double slack = container ? limit - r : r - limit;
        slackSum += slack;
        if (slack > q.worstSlack) q.worstSlack = slack, q.worstSlackDegrees = degrees;
        q.worstMiss = std::max(q.worstMiss, -slack);
    }
    q.meanSlack = slackSum / FitQuality::kSlackDirections;
    for (const RadialField::Corner& c : field.corners()) {
        double r = bound.radius(c.angle);
        q.worstMiss = std::max(q.worstMiss, container ? r - c.dist : c.dist - r);
    }
    for (const RadiusSample& s : bound.samples()) {
        double limit = field.rayLimit(direction(s.angle));
        q.worstMiss = std::max(q.worstMiss, container ? s.radius - limit : limit - s.radius);
    }
    return q;
}

}  // namespace polar
