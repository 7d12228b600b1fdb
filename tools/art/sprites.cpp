#include "sprites.h"

#include <algorithm>
#include <cmath>

namespace polar::art {
namespace {

// The centre of pixel (x, y) in math coordinates: origin at the image centre, y up.
Vec2 centreOf(int x, int y, int w, int h) {
    return Vec2(x + 0.5 - w * 0.5, h * 0.5 - y - 0.5);
}

double angleOf(const Vec2& p) {
    return reduceRadians(trig::atan2(p.y(), p.x()));
}

// Whether the segment from the origin to p passes through the square [lo, lo + 1]² shrunk by `inset`
// on every side (Liang–Barsky clipping: what is left of t ∈ [0, 1] has positive length).
bool segmentCrossesSquare(const Vec2& p, const Vec2& lo, double inset) {
    double t0 = 0.0, t1 = 1.0;
    for (int axis = 0; axis < 2; ++axis) {
        double a = lo[axis] + inset, b = lo[axis] + 1.0 - inset;
        if (p[axis] == 0.0) {
            if (0.0 <= a || 0.0 >= b) return false;
            continue;
        }
        double ta = a / p[axis], tb = b / p[axis];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta), t1 = std::min(t1, tb);
    }
    return t1 - t0 > 0.0;
}

// The signed circular difference a − b in (−π, π].
double angleDiff(double a, double b) {
    double d = reduceRadians(a - b);
    return d > kPi ? d - kTwoPi : d;
}

Ramp ramp(std::initializer_list<std::uint32_t> rgb) {
    Ramp r;
    for (std::uint32_t c : rgb) r.colours.push_back(Colour::hex(c));
    return r;
}

// Light from the upper left, slightly in front: the same for every sprite.
const Vec2 kLight2(-0.6, 0.8);
struct Light3 {
    double x = -0.50, y = 0.60, z = 0.62;
};

double lightDot(double nx, double ny, double nz) {
    Light3 l;
    double ln = std::sqrt(l.x * l.x + l.y * l.y + l.z * l.z);
    double nn = std::sqrt(nx * nx + ny * ny + nz * nz);
    return (nx * l.x + ny * l.y + nz * l.z) / (ln * nn);
}

// ---------------------------------------------------------------------------------------------- rocks

// A boulder's outline as a radius per direction from its centre: a union of discs that each contain
// the centre (so the union is star-shaped from it), chipped by a few flat facets, with a little
// wobble, scaled so that its largest radius is `maxR`.
struct Boulder {
    struct Disc {
        Vec2 centre;
        double radius;
    };
    struct Facet {
        double angle, distance;  // the cut keeps points p with p·u(angle) ≤ distance
    };
    std::vector<Disc> discs;
    std::vector<Facet> facets;
    struct Bite {
        double angle, depth, width;  // a radial notch: r is reduced by up to depth·r
    };
    std::vector<Bite> bites;
    std::vector<double> amplitude, phase;  // wobble harmonics k = 5, 6, ...
    double scale = 1.0;

    double radius(double theta) const {
        Vec2 u(trig::cos(theta), trig::sin(theta));
        double r = 0.0;
        for (const Disc& d : discs) {
            // The ray's exit from the disc: t = c·u + sqrt(ρ² − |c|² + (c·u)²).
            double cu = d.centre.dot(u);
            r = std::max(r, cu + std::sqrt(d.radius * d.radius - d.centre.squaredNorm() + cu * cu));
        }
        for (const Facet& f : facets) {
            double c = trig::cos(theta - f.angle);
            if (c > 1e-6) r = std::min(r, f.distance / c);
        }
        double wobble = 1.0;
        for (std::size_t k = 0; k < amplitude.size(); ++k)
            wobble += amplitude[k] * trig::cos((k + 5) * theta + phase[k]);
        for (const Bite& b : bites) {
            double t = angleDiff(theta, b.angle) / b.width;
            if (t > -1.0 && t < 1.0) wobble -= b.depth * (1.0 - t * t) * (1.0 - t * t);
        }
        return scale * r * wobble;
    }
};

Boulder makeBoulder(Random& random, int discs, int facets, int bites, double wobble, double maxR) {
    Boulder b;
    b.discs.push_back({Vec2::Zero(), 1.0});
    for (int k = 0; k < discs; ++k) {
        double angle = random.uniform(0.0, kTwoPi), along = random.uniform(0.25, 0.5);
        b.discs.push_back(
            {Vec2(along * trig::cos(angle), along * trig::sin(angle)), random.uniform(0.55, 0.8)});
    }
    for (int k = 0; k < facets; ++k)
        b.facets.push_back({random.uniform(0.0, kTwoPi), random.uniform(0.8, 1.05)});
    for (int k = 0; k < bites; ++k)
        b.bites.push_back(
            {random.uniform(0.0, kTwoPi), random.uniform(0.15, 0.24), random.uniform(0.35, 0.6)});
    for (int k = 0; k < 4; ++k) {
        b.amplitude.push_back(random.uniform(0.3, 1.0) * wobble / (1.0 + 0.5 * k));
        b.phase.push_back(random.uniform(0.0, kTwoPi));
    }
    double most = 0.0;
    for (int k = 0; k < 720; ++k) most = std::max(most, b.radius(k * kTwoPi / 720));
    b.scale = maxR / most;
    return b;
}

struct Crater {
    Vec2 centre;
    double radius;
    double depth;
};

}  // namespace

Canvas drawRock(int size, int variant, std::uint64_t seed) {
    static const Ramp kPalettes[3] = {
        ramp({0x1c1420, 0x33263a, 0x54404c, 0x7a5e5c, 0xa0806c, 0xc4a585, 0xe6cfa6}),
        ramp({0x12141d, 0x252a3a, 0x3c4555, 0x596471, 0x7b8791, 0xa1adb1, 0xcbd4d2}),
        ramp({0x1e1218, 0x3a1f27, 0x5c2f33, 0x834640, 0xa86550, 0xcb8c68, 0xecbc8f}),
    };
    const Ramp& palette = kPalettes[(variant - 1) % 3];
    Random random(seed * 1000003u + static_cast<std::uint64_t>(size) * 31u +
                  static_cast<std::uint64_t>(variant));
    const double maxR = size * 0.5 - 1.0;
    const bool large = size >= 40, small = size < 24;
    Boulder lumps =
        makeBoulder(random, large ? 4 : 3, large ? 3 : 2, small ? 0 : 1, small ? 0.02 : 0.035, maxR);

    std::vector<Crater> craters;
    int craterCount = large ? 5 : small ? 1 : 3;
    for (int attempt = 0; attempt < 200 && static_cast<int>(craters.size()) < craterCount; ++attempt) {
        double theta = random.uniform(0.0, kTwoPi);
        double along = random.uniform(0.0, 0.62) * lumps.radius(theta);
        Vec2 c(along * trig::cos(theta), along * trig::sin(theta));
        double radius = std::max(small ? 1.8 : 2.4, random.uniform(0.11, 0.22) * maxR);
        // Spread them out: no crater overlaps another.
        bool apart = true;
        for (const Crater& o : craters) apart = apart && (o.centre - c).norm() > (o.radius + radius) * 1.1;
        if (apart) craters.push_back({c, radius, random.uniform(0.08, 0.12)});
    }
    const std::uint64_t noiseSeed = random.next();

    // Height above the silhouette's base plane: a dome over the lumpy outline, with craters (a bowl
    // and a raised rim) and a little surface noise.
    auto height = [&](const Vec2& p) {
        double r = lumps.radius(angleOf(p));
        double u = p.norm() / r;
        if (u >= 1.0) return 0.0;
        double h = std::sqrt(1.0 - u * u);
        for (const Crater& c : craters) {
            double e = (p - c.centre).norm() / c.radius;
            if (e < 1.0) h -= c.depth * (1.0 - e * e) * 1.6;
            double rim = (e - 1.0) / 0.45;
            if (rim > -1.0 && rim < 1.0) h += c.depth * 0.45 * (1.0 - rim * rim) * (1.0 - rim * rim);
        }
        h += 0.07 * (fbm(p.x() / 3.5, p.y() / 3.5, noiseSeed, 3) - 0.5);
        return h;
    };

    Canvas canvas(size, size);
    Mask inside(size, size);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            Vec2 p = centreOf(x, y, size, size);
            if (p.norm() <= lumps.radius(angleOf(p))) inside.set(x, y);
        }
    const double dither = large ? 0.2 : 0.0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            if (!inside.at(x, y)) continue;
            Vec2 p = centreOf(x, y, size, size);
            const double e = 0.5;
            double gx = (height(p + Vec2(e, 0)) - height(p - Vec2(e, 0))) / (2 * e);
            double gy = (height(p + Vec2(0, e)) - height(p - Vec2(0, e))) / (2 * e);
            double diffuse = std::max(0.0, lightDot(-gx * maxR, -gy * maxR, 1.0));
            double albedo = 0.86 + 0.28 * fbm(p.x() / 5.0 + 11.0, p.y() / 5.0, noiseSeed + 1, 3);
            double inCrater = 0.0;
            for (const Crater& c : craters) {
                double t = (p - c.centre).norm() / c.radius;
                if (t < 0.85) inCrater = std::max(inCrater, 1.0 - t / 0.85);
            }
            double shade = (0.2 + 0.8 * diffuse) * albedo - 0.1 * inCrater;
            // Shade 0 is kept for the outline: the fill uses palette entries 1..n−1.
            Ramp fill{std::vector<Colour>(palette.colours.begin() + 1, palette.colours.end())};
            Colour c = fill.pick(shade, x, y, dither);
            if (inside.isEdge(x, y)) {
                // A selective outline: darkest in shadow, one step up where the light grazes it.
                c = diffuse > 0.45  ? palette.colours[2]
                    : diffuse > 0.2 ? palette.colours[1]
                                    : palette.colours[0];
            }
            canvas.set(x, y, c);
        }
    return canvas;
}

// ----------------------------------------------------------------------------------------------- ship

Canvas drawShip() {
    const int n = kShipSize;
    // Swept delta wings on a long fuselage, symmetric about the x axis.
    const std::vector<Vec2> upper = {{9.4, 0.0},  {5.0, 1.7},  {1.0, 2.6}, {-6.0, 8.8},
                                     {-8.4, 8.8}, {-6.6, 3.0}, {-8.8, 2.4}};
    std::vector<Vec2> hull = upper;
    for (auto it = upper.rbegin(); it != upper.rend(); ++it)
        if (it->y() != 0.0) hull.push_back(Vec2(it->x(), -it->y()));
    const Ramp body = ramp({0x1b1d33, 0x3b4261, 0x5f6a8a, 0x8e9bb5, 0xc5cedd, 0xf2f5fa});
    const Colour accent = Colour::hex(0xe2483b), accentLight = Colour::hex(0xff8a5c);
    const Colour glassDark = Colour::hex(0x163e5c), glass = Colour::hex(0x2f86b3),
                 glassLight = Colour::hex(0x9beeff);
    const Colour nozzle = Colour::hex(0x2a2740), flame = Colour::hex(0xffb347),
                 flameHot = Colour::hex(0xfff1b0);

    Mask mask(n, n);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            Vec2 p = centreOf(x, y, n, n);
            if (insidePolygon(hull, p.x(), p.y())) mask.set(x, y);
        }
    Canvas canvas(n, n);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            Vec2 p = centreOf(x, y, n, n);
            if (!mask.at(x, y)) {
                if (mask.touches(x, y, false)) canvas.set(x, y, body.colours[0]);
                continue;
            }
            // Light from above: the upper half of the hull is brighter, edges facing up are highlit and
            // edges facing down are shaded.
            int level = p.y() > 0.5 ? 4 : p.y() > -0.5 ? 3 : 2;
            if (std::fabs(p.y()) > 3.0) level -= 1;  // the wings sit lower than the fuselage
            if (!mask.at(x, y - 1)) level += 1;
            if (!mask.at(x, y + 1)) level -= 1;
            Colour c = body.colours[static_cast<std::size_t>(std::clamp(level, 1, 5))];
            // A stripe along each wing's leading edge.
            double wing = std::fabs(p.y());
            double leading = 2.6 + (1.0 - p.x()) * (6.2 / 7.0);  // the leading edge's |y| at this x
            if (p.x() < 0.0 && wing > 3.2 && leading - wing < 1.6) c = p.y() > 0 ? accentLight : accent;
            // Cockpit: an ellipse on the fuselage, dark glass with a bright glint at its upper front.
            double ex = (p.x() - 2.6) / 2.4, ey = p.y() / 1.2;
            if (ex * ex + ey * ey < 1.0) c = p.y() > 0 ? glass : glassDark;
            if (std::fabs(p.x() - 3.5) < 0.6 && std::fabs(p.y() - 0.5) < 0.6) c = glassLight;
            if (p.x() < -7.5 && std::fabs(p.y()) < 1.5) c = nozzle;
            canvas.set(x, y, c);
        }
    // Engine glow behind the nozzle.
    for (int y = 0; y < n; ++y) {
        Vec2 p = centreOf(0, y, n, n);
        if (std::fabs(p.y()) < 1.0)
            canvas.set(0, y, flameHot);
        else if (std::fabs(p.y()) < 2.0)
            canvas.set(0, y, flame.withAlpha(0.75));
    }
    return canvas;
}

// -------------------------------------------------------------------------------------- bullet, pickups

Canvas drawBullet() {
    const int n = kBulletSize;
    Canvas canvas(n, n);
    const Colour core = Colour::hex(0xfffff0), hot = Colour::hex(0xffe27a), warm = Colour::hex(0xffa040);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            double d = centreOf(x, y, n, n).norm();
            if (d < 0.5)
                canvas.set(x, y, core);
            else if (d < 1.2)
                canvas.set(x, y, hot);
            else if (d < 1.6)
                canvas.set(x, y, warm.withAlpha(0.8));
            else if (d < 2.3)
                canvas.set(x, y, warm.withAlpha(0.4));
        }
    return canvas;
}

namespace {

// A glowing ring pickup with an emblem given as rows of '#' (fill), '+' (highlight) and '=' (shade).
Canvas drawPickup(const Ramp& ring, const Colour& inner, const std::vector<const char*>& emblem,
                  const Colour& emblemFill, const Colour& emblemLight, const Colour& emblemShade) {
    const int n = kPickupSize;
    Canvas canvas(n, n);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            Vec2 p = centreOf(x, y, n, n);
            double d = p.norm();
            if (d > 6.9) continue;
            if (d > 5.3) {
                // The ring: lit from the upper left.
                double lit = (p.normalized().dot(kLight2) + 1.0) * 0.5;
                int level = 1 + static_cast<int>(lit * 3.0 + 0.5);
                if (d > 6.2) level = std::max(0, level - 1);
                canvas.set(x, y, ring.colours[static_cast<std::size_t>(std::clamp(level, 0, 4))]);
            } else {
                canvas.set(x, y, inner);
            }
        }
    int rows = static_cast<int>(emblem.size());
    int cols = static_cast<int>(std::string(emblem[0]).size());
    int x0 = (n - cols) / 2, y0 = (n - rows) / 2;
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) {
            char ch = emblem[static_cast<std::size_t>(r)][c];
            if (ch == '#') canvas.set(x0 + c, y0 + r, emblemFill);
            if (ch == '+') canvas.set(x0 + c, y0 + r, emblemLight);
            if (ch == '=') canvas.set(x0 + c, y0 + r, emblemShade);
        }
    return canvas;
}

}  // namespace

Canvas drawPickupShield() {
    return drawPickup(ramp({0x0d2240, 0x1d5a8c, 0x2f9bd0, 0x6fd6f5, 0xc8f6ff}), Colour::hex(0x0b1a33, 0.8),
                      {"+++#===", "+++#===", "+++#===", ".++#==.", "..+#=..", "...#..."},
                      Colour::hex(0x8fe2ff), Colour::hex(0xe6fbff), Colour::hex(0x3b9fd8));
}

Canvas drawPickupLife() {
    return drawPickup(ramp({0x3a0f1e, 0x8c2040, 0xd0455e, 0xf5869a, 0xffd2da}), Colour::hex(0x2a0a18, 0.8),
                      {".##.##.", "#+###=#", "#####=#", ".###==.", "..#==..", "...=..."},
                      Colour::hex(0xff4f6d), Colour::hex(0xffe0e6), Colour::hex(0xc22848));
}

Canvas drawPickupSpread() {
    return drawPickup(ramp({0x3a2a08, 0x8c6a14, 0xd0a22a, 0xf5d46a, 0xfff4c8}), Colour::hex(0x2a1f06, 0.8),
                      {"#..#..#", ".#.#.#.", "..###..", "...#...", "...#...", "..+#=.."},
                      Colour::hex(0xffd24a), Colour::hex(0xfff4c0), Colour::hex(0xc08a1a));
}

Canvas drawPickupRapid() {
    return drawPickup(ramp({0x0e3a14, 0x1f8c30, 0x36d04e, 0x7af58a, 0xd0ffd8}), Colour::hex(0x0a2a0e, 0.8),
                      {"...+#.", "..+#=.", ".+####", "####=.", ".+#=..", ".#=..."}, Colour::hex(0x5cff74),
                      Colour::hex(0xe0ffe4), Colour::hex(0x20a83a));
}

Canvas drawPickupBarrier() {
    return drawPickup(ramp({0x2a0e3a, 0x6a208c, 0xa645d0, 0xd486f5, 0xf4d8ff}), Colour::hex(0x1e0a2a, 0.8),
                      {".+###=.", "+#...#=", "#..+..=", "#.+#=.=", "=#...#=", ".===== "},
                      Colour::hex(0xd070ff), Colour::hex(0xf8e4ff), Colour::hex(0x8a2ab8));
}

// ------------------------------------------------------------------------------------------------ foes

namespace {

// A flying saucer seen from the side, `n` pixels wide: a lit dome over a rim with lights, its
// colours from `hull` (dark to light) and `glow`.
Canvas drawSaucerShape(int n, const Ramp& hull, const Colour& dome, const Colour& glow) {
    Canvas canvas(n, n);
    const double a = n * 0.5 - 0.5, b = n * 0.17;  // the rim: an ellipse a × b
    const double domeR = n * 0.22;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            Vec2 p = centreOf(x, y, n, n);
            const double rim = (p.x() * p.x()) / (a * a) + (p.y() * p.y()) / (b * b);
            const Vec2 d = p - Vec2(0, b * 0.6);
            if (d.norm() < domeR && p.y() > 0) {
                const double lit = (d.normalized().dot(kLight2) + 1.0) * 0.5;
                canvas.set(x, y, lit > 0.75 ? Colour::hex(0xffffff, 0.95) : dome.withAlpha(0.9));
            } else if (rim <= 1.0) {
                const double lit = p.y() / b * 0.5 + 0.5 - std::fabs(p.x()) / a * 0.25;
                canvas.set(x, y, hull.pick(std::clamp(lit, 0.0, 1.0), x, y, 0.2));
                if (std::fabs(p.y()) < 0.9 && static_cast<int>(std::floor(p.x() + a)) % 4 == 1)
                    canvas.set(x, y, glow);
            }
        }
    return canvas;
}

}  // namespace

Canvas drawSaucer() {
    return drawSaucerShape(kSaucerSize, ramp({0x1a1d2a, 0x3a4258, 0x6a7690, 0xa8b4c8, 0xe2e8f0}),
                           Colour::hex(0x66e0ff), Colour::hex(0xff5a8a));
}

Canvas drawSmallSaucer() {
    return drawSaucerShape(kSmallSaucerSize, ramp({0x2a1010, 0x5c2222, 0x9a3a30, 0xd8704a, 0xffc08a}),
                           Colour::hex(0xffe066), Colour::hex(0x66ffd0));
}

Canvas drawMine() {
    const int n = kMineSize;
    Canvas canvas(n, n);
    const Ramp shell = ramp({0x1a0a0a, 0x401414, 0x702020, 0xa83232, 0xe06050});
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            Vec2 p = centreOf(x, y, n, n);
            const double d = p.norm();
            const double angle = angleOf(p);
            // A ball with eight spikes: the outline swells toward each spike's direction.
            const double spike = std::pow(std::fabs(trig::cos(4.0 * angle)), 6.0);
            const double edge = n * 0.3 + spike * (n * 0.5 - 0.5 - n * 0.3);
            if (d > edge) continue;
            if (d < 1.6) {
                canvas.set(x, y, Colour::hex(0xfff080));  // the fuse light
            } else if (d < n * 0.3) {
                const double lit = d > 0 ? (p.normalized().dot(kLight2) + 1.0) * 0.5 : 1.0;
                canvas.set(x, y, shell.pick(0.2 + 0.7 * lit * (1.0 - d / (n * 0.45)), x, y, 0.25));
            } else {
                canvas.set(x, y, Colour::hex(0xc8b8b0));
            }
        }
    return canvas;
}

Canvas drawMineShard() {
    const int n = kShardSize;
    Canvas canvas(n, n);
    // A dart pointing toward +x.
    const std::vector<Vec2> dart{
        {n * 0.5 - 0.5, 0}, {-n * 0.4, n * 0.35}, {-n * 0.15, 0}, {-n * 0.4, -n * 0.35}};
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            Vec2 p = centreOf(x, y, n, n);
            if (!insidePolygon(dart, p.x(), p.y())) continue;
            canvas.set(x, y, p.y() > 0 ? Colour::hex(0xff9a6a) : Colour::hex(0xc83a2a));
        }
    return canvas;
}

Canvas drawHunter() {
    const int n = kHunterSize;
    Canvas canvas(n, n);
    const Ramp armour = ramp({0x0c1a10, 0x1c3a22, 0x2e6a3a, 0x4aa05a, 0x9ae0a0});
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            Vec2 p = centreOf(x, y, n, n);
            // A crab-like turret facing +x: a hexagonal body and a barrel.
            const bool barrel = p.x() > 0 && p.x() < n * 0.5 - 0.5 && std::fabs(p.y()) < 1.3;
            const double hex =
                std::max(std::fabs(p.y()) * 1.15, std::fabs(p.x()) * 0.85 + std::fabs(p.y()) * 0.5);
            if (barrel && hex >= n * 0.3) {
                canvas.set(x, y, Colour::hex(0xd0f0d0));
            } else if (hex < n * 0.3) {
                const double lit = (p.dot(kLight2) / (n * 0.3) + 1.0) * 0.5;
                canvas.set(x, y, armour.pick(std::clamp(lit, 0.0, 1.0), x, y, 0.2));
                if (p.norm() < 2.0) canvas.set(x, y, Colour::hex(0xff4040));  // its eye
            } else if (hex < n * 0.42 && std::fabs(p.x()) < n * 0.25 && std::fabs(p.y()) > n * 0.2) {
                canvas.set(x, y, Colour::hex(0x2e6a3a));  // legs
            }
        }
    return canvas;
}

Canvas drawFoeShot() {
    const int n = kBulletSize;
    Canvas canvas(n, n);
    const Colour core = Colour::hex(0xfff0ff), hot = Colour::hex(0xff70d0), edge = Colour::hex(0xc020a0);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            double d = centreOf(x, y, n, n).norm();
            if (d < 0.8)
                canvas.set(x, y, core);
            else if (d < 1.6)
                canvas.set(x, y, hot);
            else if (d < 2.4)
                canvas.set(x, y, edge.withAlpha(0.6));
        }
    return canvas;
}

// ----------------------------------------------------------------------------------------------- comet

Canvas drawComet(std::uint64_t seed) {
    const int n = kCometSize;
    Canvas canvas(n, n);
    const Vec2 head(6.0, 0.0);
    const double headR = 3.2, length = 18.0;
    const Ramp tail = ramp({0x2a1a5e, 0x3340a8, 0x3a86dc, 0x86d8f7, 0xe0faff});
    Random random(seed * 31 + 7);
    // Streaks fan out behind the head: each has a spread (|y| grows with t) and a brightness.
    struct Streak {
        double spread, bright;
    };
    const std::vector<Streak> streaks = {{0.0, 1.0}, {0.7, 0.8}, {-0.75, 0.75}, {1.4, 0.5}, {-1.45, 0.45}};
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            Vec2 p = centreOf(x, y, n, n);
            Vec2 q = p - head;
            double d = q.norm();
            if (d < headR) {
                Colour c = d < 1.3   ? Colour::hex(0xffffff)
                           : d < 2.3 ? Colour::hex(0xc6f4ff)
                                     : Colour::hex(0x66c2ee);
                // A darker crescent away from the light gives the head some roundness.
                if (d >= 2.3 && q.dot(kLight2) < -1.0) c = Colour::hex(0x3f86c8);
                canvas.set(x, y, c);
                continue;
            }
            if (q.x() > -0.5) continue;
            double t = -q.x() / length;  // 0 at the head, 1 at the tail's end
            if (t > 1.0) continue;
            double fade = (1.0 - t) * (1.0 - t);
            // A soft body that narrows to the head, plus the streaks' bright lines.
            double halfWidth = headR * (0.9 + 1.1 * t);
            double across = std::fabs(q.y()) / halfWidth;
            double intensity = across < 1.0 ? 0.5 * fade * (1.0 - across * across) : 0.0;
            for (const Streak& s : streaks) {
                double off = std::fabs(q.y() - s.spread * headR * t * 1.6);
                double along = (1.0 - t) * std::sqrt(1.0 - t);
                if (off < 0.75) intensity = std::max(intensity, s.bright * along * (1.0 - off / 0.75 * 0.6));
            }
            if (intensity < 0.1) continue;
            Colour c = tail.pick(std::min(1.0, intensity * 1.35), x, y, 0.0);
            double alpha = intensity > 0.45 ? 1.0 : intensity > 0.28 ? 0.8 : intensity > 0.17 ? 0.55 : 0.3;
            canvas.set(x, y, c.withAlpha(alpha));
        }
    // A few sparkles trailing the tail.
    for (int k = 0; k < 5; ++k) {
        int x = 1 + random.below(8), y = n / 2 - 4 + random.below(9);
        if (canvas.at(x, y).a < 0.5) canvas.set(x, y, Colour::hex(0x9fdcff, 0.45));
    }
    return canvas;
}

// ------------------------------------------------------------------------------------------------ cave

Canvas drawCave(std::uint64_t seed) {
    const int w = kCaveWidth, h = kCaveHeight;
    Random random(seed * 7919 + 17);
    // The interior: an ellipse made irregular by harmonics and outcrops, as a radius per direction
    // from the centre, which makes it star-shaped from the centre by construction.
    const double a = 292.0, b = 150.0;
    std::vector<double> amp, phase;
    for (int k = 2; k <= 17; ++k) {
        amp.push_back(random.uniform(0.3, 1.0) * 0.07 / (0.6 + 0.25 * k));
        phase.push_back(random.uniform(0.0, kTwoPi));
    }
    struct Outcrop {
        double angle, depth, width;
    };
    std::vector<Outcrop> outcrops;
    for (int k = 0; k < 9; ++k)
        outcrops.push_back(
            {random.uniform(0.0, kTwoPi), random.uniform(8.0, 26.0), random.uniform(0.05, 0.16)});
    auto interiorRadius = [&](double theta) {
        double c = trig::cos(theta), s = trig::sin(theta);
        double r = a * b / std::sqrt((b * c) * (b * c) + (a * s) * (a * s));
        double wobble = 1.0;
        for (std::size_t k = 0; k < amp.size(); ++k) wobble += amp[k] * trig::cos((k + 2) * theta + phase[k]);
        r *= wobble;
        for (const Outcrop& o : outcrops) {
            double t = angleDiff(theta, o.angle) / o.width;
            if (t > -1.0 && t < 1.0) r -= o.depth * (1.0 - t * t) * (1.0 - t * t);
        }
        // Walls at least 12 px thick at the image's edges.
        double limit = std::min(std::fabs(s) > 1e-9 ? (h * 0.5 - 12.0) / std::fabs(s) : 1e9,
                                std::fabs(c) > 1e-9 ? (w * 0.5 - 12.0) / std::fabs(c) : 1e9);
        return std::min(r, limit);
    };

    Mask open(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            Vec2 p = centreOf(x, y, w, h);
            if (p.norm() < interiorRadius(angleOf(p))) open.set(x, y);
        }
    // The outline is star-shaped, but its pixels may not quite be: a pixel just behind an outcrop's
    // corner can be hidden from the centre. Such pixels become rock, until the segment from the
    // centre to every open pixel's centre crosses no rock square's interior (shrunk by 1e-6 px, so
    // that touching a corner does not count). Steps of ½ px with exact tests against the 3×3
    // neighbourhood of each step meet every square the segment enters.
    auto crossesRock = [&](const Vec2& p) {
        int steps = static_cast<int>(p.norm() * 2.0) + 1;
        for (int k = 0; k <= steps; ++k) {
            Vec2 q = p * (static_cast<double>(k) / steps);
            int cx = static_cast<int>(std::floor(q.x() + w * 0.5)),
                cy = static_cast<int>(std::floor(h * 0.5 - q.y()));
            for (int y = cy - 1; y <= cy + 1; ++y)
                for (int x = cx - 1; x <= cx + 1; ++x)
                    if (!open.at(x, y) && segmentCrossesSquare(p, Vec2(x - w * 0.5, h * 0.5 - y - 1.0), 1e-6))
                        return true;
        }
        return false;
    };
    for (bool changed = true; changed;) {
        changed = false;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                if (!open.at(x, y)) continue;
                bool nearRock = false;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) nearRock = nearRock || !open.at(x + dx, y + dy);
                if (nearRock && crossesRock(centreOf(x, y, w, h))) {
                    open.set(x, y, false);
                    changed = true;
                }
            }
    }

    // Chamfer distance (1, √2) from the open interior into the rock, and its gradient for lighting.
    const double kFar = 1e9;
    std::vector<double> dist(static_cast<std::size_t>(w) * h, kFar);
    auto D = [&](int x, int y) -> double& { return dist[static_cast<std::size_t>(y) * w + x]; };
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (open.at(x, y)) D(x, y) = 0.0;
    const double diag = std::sqrt(2.0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double& d = D(x, y);
            if (x > 0) d = std::min(d, D(x - 1, y) + 1.0);
            if (y > 0) d = std::min(d, D(x, y - 1) + 1.0);
            if (x > 0 && y > 0) d = std::min(d, D(x - 1, y - 1) + diag);
            if (x + 1 < w && y > 0) d = std::min(d, D(x + 1, y - 1) + diag);
        }
    for (int y = h - 1; y >= 0; --y)
        for (int x = w - 1; x >= 0; --x) {
            double& d = D(x, y);
            if (x + 1 < w) d = std::min(d, D(x + 1, y) + 1.0);
            if (y + 1 < h) d = std::min(d, D(x, y + 1) + 1.0);
            if (x + 1 < w && y + 1 < h) d = std::min(d, D(x + 1, y + 1) + diag);
            if (x > 0 && y + 1 < h) d = std::min(d, D(x - 1, y + 1) + diag);
        }

    const Ramp rock = ramp({0x0b0910, 0x16111d, 0x221a2c, 0x30253d, 0x43344f, 0x5a4764, 0x775f7c, 0x9a7f96});
    const std::uint64_t noiseSeed = random.next();
    Canvas canvas(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (open.at(x, y)) continue;
            Vec2 p = centreOf(x, y, w, h);
            double d = D(x, y);
            // Large blocks and fine grain, with strata that follow the cave's curve.
            double blocks = fbm(p.x() / 26.0, p.y() / 18.0, noiseSeed, 4);
            double grain = fbm(p.x() / 4.0, p.y() / 4.0, noiseSeed + 5, 2);
            double strata = 0.5 + 0.5 * trig::sin(d * 0.42 + blocks * 6.0);
            double shade = 0.12 + 0.5 * blocks + 0.12 * grain + 0.1 * strata;
            // Rock near the arena catches its light; deep rock fades into darkness.
            shade += 0.25 * (1.0 - smoothstep(2.0, 36.0, d)) - 0.12 * smoothstep(30.0, 90.0, d);
            // Cracks: thin dark lines where a ridged noise crosses its middle.
            double ridge = std::fabs(fbm(p.x() / 30.0 + 40.0, p.y() / 30.0, noiseSeed + 9, 3) - 0.5);
            if (ridge < 0.012 && d > 3.0) shade -= 0.22;
            if (d <= 5.0) {
                // The wall's face: lit where it faces the upper-left light, dark where it turns away.
                auto at = [&](int xx, int yy) {
                    return D(std::clamp(xx, 0, w - 1), std::clamp(yy, 0, h - 1));
                };
                Vec2 grad(at(x + 1, y) - at(x - 1, y), -(at(x, y + 1) - at(x, y - 1)));
                Vec2 towardArena = grad.norm() > 0 ? Vec2(-grad.normalized()) : Vec2(0, 0);
                double facing = towardArena.dot(kLight2);
                if (d <= 1.5) {
                    shade = facing > 0.35 ? 0.98 : facing > -0.1 ? 0.8 : 0.1;
                } else if (d <= 3.0) {
                    shade += 0.25 * facing;
                }
            }
            canvas.set(x, y, rock.pick(shade, x, y, 0.45));
        }

    // Crystal clusters set into the walls near the arena, glowing cyan or magenta.
    const Ramp cyan = ramp({0x0f4a5c, 0x1f9bb8, 0x62e0f0, 0xd6fbff});
    const Ramp magenta = ramp({0x4a1247, 0x9a2f8c, 0xe066c8, 0xffd6f4});
    for (int k = 0; k < 14; ++k) {
        double theta = random.uniform(0.0, kTwoPi);
        double depth = random.uniform(4.0, 10.0);
        double r = interiorRadius(theta) + depth;
        Vec2 c(r * trig::cos(theta), r * trig::sin(theta));
        const Ramp& crystal = (k % 3 == 0) ? magenta : cyan;
        int shards = 2 + random.below(3);
        for (int s = 0; s < shards; ++s) {
            Vec2 o = c + Vec2(random.uniform(-3.0, 3.0), random.uniform(-3.0, 3.0));
            double size = random.uniform(2.0, 3.6);
            int cx = static_cast<int>(std::floor(o.x() + w * 0.5)),
                cy = static_cast<int>(std::floor(h * 0.5 - o.y()));
            int extent = static_cast<int>(size) + 1;
            for (int dy = -extent - 1; dy <= extent + 1; ++dy)
                for (int dx = -extent; dx <= extent; ++dx) {
                    int x = cx + dx, y = cy + dy;
                    if (x < 0 || y < 0 || x >= w || y >= h || open.at(x, y)) continue;
                    // A diamond taller than wide; its upper-left facets are the bright ones.
                    double m = std::fabs(dx) / size + std::fabs(dy) / (size * 1.5);
                    if (m > 1.0) continue;
                    int level = m > 0.75 ? 0 : (dx <= 0 && dy <= 0) ? 3 : (dx <= 0 || dy <= 0) ? 2 : 1;
                    canvas.set(x, y, crystal.colours[static_cast<std::size_t>(level)]);
                }
        }
    }
    return canvas;
}

std::vector<NamedSprite> drawAll(std::uint64_t seed) {
    std::vector<NamedSprite> out;
    out.push_back({"ship", drawShip()});
    const char* sizeNames[3] = {"large", "medium", "small"};
    for (int s = 0; s < 3; ++s)
        for (int v = 1; v <= 3; ++v)
            out.push_back({std::string("rock-") + sizeNames[s] + "-" + std::to_string(v),
                           drawRock(kRockSizes[s], v, seed)});
    out.push_back({"bullet", drawBullet()});
    out.push_back({"pickup-shield", drawPickupShield()});
    out.push_back({"pickup-life", drawPickupLife()});
    out.push_back({"comet", drawComet(seed)});
    out.push_back({"cave", drawCave(seed)});
    // Rules 3's foes, their shot and the power-ups (last, so every sprite above keeps its bytes).
    out.push_back({"saucer", drawSaucer()});
    out.push_back({"saucer-small", drawSmallSaucer()});
    out.push_back({"mine", drawMine()});
    out.push_back({"mine-shard", drawMineShard()});
    out.push_back({"hunter", drawHunter()});
    out.push_back({"foe-shot", drawFoeShot()});
    out.push_back({"pickup-spread", drawPickupSpread()});
    out.push_back({"pickup-rapid", drawPickupRapid()});
    out.push_back({"pickup-barrier", drawPickupBarrier()});
    return out;
}

}  // namespace polar::art
