#include "polar/authoring/bounds_gen.h"

#include <algorithm>

#include "authoring/radial_field.h"

namespace polar {

FitQuality measureFit(const PixelSet& pixels, const Bound& radii, bool container) {
    RadialField field(pixels, radii.centre(), container);
    FitQuality q;
    q.pixels = pixels.count();
    double slackSum = 0.0;
    q.worstSlack = -kInf;
    for (int k = 0; k < FitQuality::kSlackDirections; ++k) {
        double degrees = k * 360.0 / FitQuality::kSlackDirections;
        double phi = degToRad(degrees);
        double limit = field.rayLimit(direction(phi));
        double r = radii.radius(phi);
        double slack = container ? limit - r : r - limit;
        slackSum += slack;
        if (slack > q.worstSlack) q.worstSlack = slack, q.worstSlackDegrees = degrees;
        q.worstMiss = std::max(q.worstMiss, -slack);
    }
    q.meanSlack = slackSum / FitQuality::kSlackDirections;
    for (const RadialField::Corner& c : field.corners()) {
        double r = radii.radius(c.angle);
        q.worstMiss = std::max(q.worstMiss, container ? r - c.dist : c.dist - r);
    }
    for (const RadiusSample& s : radii.samples()) {
        double limit = field.rayLimit(direction(s.angle));
        q.worstMiss = std::max(q.worstMiss, container ? s.radius - limit : limit - s.radius);
    }
    return q;
}

}  // namespace polar
