#include "polar/authoring/bounds_gen.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

namespace polar {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Points this close to a sample's ray (px) count as on it: its ray limit covers them.
constexpr double kOnRay = 1e-9;
// The smallest radius an enclosing outline uses toward directions with no opaque pixel.
constexpr double kMinRadius = 0.25;
// Safety margin before rounding radii to 3 decimals (away from the pixels), so that a pixel corner
// lying exactly on an edge stays on the right side when the engine's trigonometry rounds differently.
constexpr double kMargin = 1e-6;
constexpr double kRadiusScale = 1000.0;  // radii are written with 3 decimals
constexpr int kMaxPasses = 12;

Vec2 direction(double radians) {
    double s, c;
    trig::sincos(radians, s, c);
    return Vec2(c, s);
}

double angleOf(const Vec2& p) {
    return reduceRadians(trig::atan2(p.y(), p.x()));
}

// The pixels as seen from a centre: the squares on the set's boundary (only they can be the first or
// last thing a ray meets, or a corner an edge must clear), their corners sorted by angle, and the
// limit along any ray. For a container, the set is the walls and everything outside the image is
// wall too.
class RadialField {
  public:
    struct Corner {
        double angle;  // [0, 2π)
        Vec2 p;        // relative to the centre
        double dist;
    };

    RadialField(const PixelSet& set, const Vec2& centre, bool container) : container_(container) {
        const int w = set.width, h = set.height;
        auto wall = [&](int x, int y) {
            if (x < 0 || y < 0 || x >= w || y >= h) return container;
            return set.has(x, y);
        };
        // Corner grid points (X, Y) with X ∈ [−1, w + 1], Y ∈ [−1, h + 1], deduplicated.
        const int gw = w + 3, gh = h + 3;
        std::vector<std::uint8_t> seen(static_cast<std::size_t>(gw) * gh, 0);
        const int lo = container ? -1 : 0;
        for (int y = lo; y < h - lo; ++y) {
            for (int x = lo; x < w - lo; ++x) {
                if (!wall(x, y)) continue;
                bool boundary = false;
                const int nx[4] = {x - 1, x + 1, x, x}, ny[4] = {y, y, y - 1, y + 1};
                for (int k = 0; k < 4; ++k)
                    if (!wall(nx[k], ny[k])) boundary = true;
                if (!boundary) continue;
                // Pixel (x, y) is [x − w/2, x + 1 − w/2] × [h/2 − y − 1, h/2 − y].
                Vec2 lowerLeft(x - w * 0.5, h * 0.5 - y - 1.0);
                squares_.push_back(lowerLeft - centre);
                for (int cy = y; cy <= y + 1; ++cy) {
                    for (int cx = x; cx <= x + 1; ++cx) {
                        std::size_t key = static_cast<std::size_t>(cy + 1) * gw + (cx + 1);
                        if (seen[key]) continue;
                        seen[key] = 1;
                        Vec2 p = Vec2(cx - w * 0.5, h * 0.5 - cy) - centre;
                        double dist = p.norm();
                        if (dist > 0.0) corners_.push_back({angleOf(p), p, dist});
                    }
                }
            }
        }
        std::sort(corners_.begin(), corners_.end(), [](const Corner& a, const Corner& b) {
            return a.angle < b.angle || (a.angle == b.angle && a.dist < b.dist);
        });
        for (const Corner& c : corners_) maxCornerDistance_ = std::max(maxCornerDistance_, c.dist);
        fileSquaresByAngle();
    }

    bool container() const { return container_; }
    const std::vector<Corner>& corners() const { return corners_; }
    double maxCornerDistance() const { return maxCornerDistance_; }

    // Enclosing: the distance to the farthest point of a square on the ray along unit u (0 if none).
    // Container: the distance to the nearest point of a wall square on it (∞ if none).
    double rayLimit(const Vec2& u) const {
        double best = container_ ? kInf : 0.0;
        for (std::size_t index : bins_[binOf(angleOf(u))]) {
            const Vec2& s = squares_[index];
            double tEnter = -kInf, tExit = kInf;
            bool hit = true;
            for (int a = 0; a < 2 && hit; ++a) {
                double lo = s[a], hi = s[a] + 1.0;
                if (u[a] == 0.0) {
                    hit = lo <= 0.0 && 0.0 <= hi;
                    continue;
                }
                double t1 = lo / u[a], t2 = hi / u[a];
                if (t1 > t2) std::swap(t1, t2);
                tEnter = std::max(tEnter, t1);
                tExit = std::min(tExit, t2);
            }
            if (!hit || tExit < std::max(tEnter, 0.0)) continue;
            if (container_)
                best = std::min(best, std::max(tEnter, 0.0));
            else
                best = std::max(best, tExit);
        }
        return best;
    }

    // rayLimit, also counting corners within kOnRay of the ray, which rounding may let the slab
    // test miss; the fitter leaves such corners to this limit.
    double rayLimitWithCorners(double angle) const {
        Vec2 u = direction(angle);
        double limit = rayLimit(u);
        forEachCorner(angle - 1e-6, angle + 1e-6, [&](const Corner& c) {
            double along = c.p.dot(u);
            if (along <= 0.0 || std::fabs(cross(u, c.p)) > kOnRay) return;
            limit = container_ ? std::min(limit, along) : std::max(limit, along);
        });
        return limit;
    }

    // The distance from the centre to the nearest square (0 when the centre is on one).
    double nearestSquareDistance() const {
        double best = kInf;
        for (const Vec2& s : squares_) {
            double dx = std::max({s.x(), 0.0, -(s.x() + 1.0)});
            double dy = std::max({s.y(), 0.0, -(s.y() + 1.0)});
            best = std::min(best, std::hypot(dx, dy));
        }
        return best;
    }

    // Calls f for each corner with angle in [a1, a2] (radians, a1 ≤ a2, either may lie outside
    // [0, 2π): the range wraps).
    template <class F>
    void forEachCorner(double a1, double a2, F&& f) const {
        auto range = [&](double lo, double hi) {
            auto first = std::lower_bound(corners_.begin(), corners_.end(), lo,
                                          [](const Corner& c, double v) { return c.angle < v; });
            for (auto it = first; it != corners_.end() && it->angle <= hi; ++it) f(*it);
        };
        if (a2 - a1 >= kTwoPi) {
            range(0.0, kTwoPi);
            return;
        }
        double lo = a1, hi = a2;
        if (lo < 0.0) {
            range(lo + kTwoPi, kTwoPi);
            range(0.0, hi);
        } else if (hi >= kTwoPi) {
            range(lo, kTwoPi);
            range(0.0, hi - kTwoPi);
        } else {
            range(lo, hi);
        }
    }

  private:
    static constexpr int kBins = 2048;
    static std::size_t binOf(double angle) {
        long b = static_cast<long>(std::floor(angle * (kBins / kTwoPi)));
        return static_cast<std::size_t>(((b % kBins) + kBins) % kBins);
    }

    // Files each square under every angular bin it covers as seen from the centre (with a bin to
    // spare on either side), so that a ray only tests the squares it can meet.
    void fileSquaresByAngle() {
        bins_.assign(kBins, {});
        for (std::size_t index = 0; index < squares_.size(); ++index) {
            const Vec2& s = squares_[index];
            if (s.x() <= 0.0 && s.y() <= 0.0 && s.x() + 1.0 >= 0.0 && s.y() + 1.0 >= 0.0) {
                for (auto& bin : bins_) bin.push_back(index);  // the centre is on this square
                continue;
            }
            // The square subtends less than 180°: measure its corners' angles from its first corner.
            double first = angleOf(s), least = 0.0, most = 0.0;
            for (int c = 1; c < 4; ++c) {
                double d = angleOf(s + Vec2(c & 1, c >> 1)) - first;
                if (d > kPi) d -= kTwoPi;
                if (d < -kPi) d += kTwoPi;
                least = std::min(least, d), most = std::max(most, d);
            }
            long from = static_cast<long>(std::floor((first + least) * (kBins / kTwoPi))) - 1;
            long to = static_cast<long>(std::floor((first + most) * (kBins / kTwoPi))) + 1;
            for (long b = from; b <= to; ++b)
                bins_[static_cast<std::size_t>(((b % kBins) + kBins) % kBins)].push_back(index);
        }
    }

    bool container_ = false;
    std::vector<Vec2> squares_;
    std::vector<std::vector<std::size_t>> bins_;
    std::vector<Corner> corners_;
    double maxCornerDistance_ = 0.0;
};

// A corner inside one edge's sector, written as q = λ·u1 + μ·u2 along the sector's two rays.
// The edge from r1·u1 to r2·u2 has q on its inner side iff λ/r1 + μ/r2 ≤ 1, that is
// λ·w1 + μ·w2 ≤ 1 with w = 1/r: linear in the inverse radii, which is what makes fitting tractable.
struct SectorPoint {
    double lambda;
    double mu;
};

struct Sector {
    std::vector<SectorPoint> points;
    double sinDelta = 0.0;  // sin of the angle between the two rays, for the area ½·r1·r2·sin Δ
};
using SectorPtr = std::shared_ptr<const Sector>;

// An outline under construction: sample angles as integer ticks of the angle grid, inverse radii,
// and the sector of each edge (edge k joins vertex k and k + 1, circularly). The ticks run
// counter-clockwise but may start anywhere (a sample moved across 0° stays where it is in the list).
struct Outline {
    std::vector<int> ticks;
    std::vector<double> w;
    std::vector<SectorPtr> sectors;
    double score = 0.0;  // lower is better: the area (enclosing) or minus the area (container)

    std::size_t size() const { return ticks.size(); }
    std::size_t prev(std::size_t i) const { return (i + size() - 1) % size(); }
    std::size_t next(std::size_t i) const { return (i + 1) % size(); }
};

struct Line {
    double m, b;  // y = m·x + b
    double at(double x) const { return m * x + b; }
};

struct Piece {
    double x0, x1;
    Line line;
};

// The lower (min) or upper (max) envelope of lines over [lo, hi] (hi may be ∞), as pieces from left
// to right. Walks from lo: at each step the active line is overtaken first by a line of smaller
// slope (lower) or larger slope (upper), so it ends after at most one step per line.
std::vector<Piece> envelope(const std::vector<Line>& lines, double lo, double hi, bool lower) {
    auto better = [&](const Line& a, const Line& b, double x) {
        double ya = a.at(x), yb = b.at(x);
        if (ya != yb) return lower ? ya < yb : ya > yb;
        return lower ? a.m < b.m : a.m > b.m;
    };
    std::size_t active = 0;
    for (std::size_t k = 1; k < lines.size(); ++k)
        if (better(lines[k], lines[active], lo)) active = k;
    std::vector<Piece> pieces;
    double x = lo;
    while (true) {
        const Line& cur = lines[active];
        double nextX = kInf;
        std::size_t nextLine = active;
        for (std::size_t k = 0; k < lines.size(); ++k) {
            const Line& l = lines[k];
            bool overtakes = lower ? l.m < cur.m : l.m > cur.m;
            if (!overtakes) continue;
            double xk = (l.b - cur.b) / (cur.m - l.m);
            if (!(xk > x)) continue;
            if (xk < nextX || (xk == nextX && (lower ? l.m < lines[nextLine].m : l.m > lines[nextLine].m))) {
                nextX = xk;
                nextLine = k;
            }
        }
        if (nextX >= hi || nextLine == active) {
            pieces.push_back({x, hi, cur});
            return pieces;
        }
        pieces.push_back({x, nextX, cur});
        x = nextX;
        active = nextLine;
    }
}

// Fits sample angles and radii for one RadialField.
//
// Why this way? The outline must be valid (enclose every pixel, or avoid every wall) after every
// step, and the files must be short and reproducible. Angles live on a grid of `ticksPerDegree` ticks
// per degree, so files get short decimal angles. For fixed angles the radii are found in inverse-
// radius space, where each corner in an edge's sector is the linear constraint λ·w1 + μ·w2 ≤ 1 (≥ 1
// for a container) and each sample's own ray bounds its w:
//   - each edge alone: the (w1, w2) on its constraint envelope with the smallest (largest) triangle
//     area ½·sin Δ/(w1·w2); a vertex shared by two edges takes the safer of the two wishes;
//   - descent: move one w as far as its two edges allow (shrinks the area, never breaks an edge);
//   - pivot: grow one radius a little so both neighbours can shrink more, when that pays;
//   - enclosing only, where the problem is convex: an exact barrier solve (solveExactly).
// The objective is the outline's area: the least for enclosing bounds, the most for a container.
// Angles start evenly spread (the best of several rotations), then improve by local search: each
// sample tries the grid angles between its neighbours (coarse, then fine), and an exchange move
// removes the cheapest sample and inserts one where it gains most.
class Fitter {
  public:
    Fitter(const RadialField& field, int ticksPerDegree, int maxGapTicks)
        : field_(field),
          container_(field.container()),
          ticksPerDegree_(ticksPerDegree),
          fullTurn_(360 * ticksPerDegree),
          maxGapTicks_(maxGapTicks),
          dir_(static_cast<std::size_t>(fullTurn_)),
          bound_(static_cast<std::size_t>(fullTurn_), -1.0) {
        for (int t = 0; t < fullTurn_; ++t) dir_[t] = direction(radians(t));
    }

    double degrees(int tick) const { return static_cast<double>(tick) / ticksPerDegree_; }
    // Exactly the radians the engine derives from the degrees written to the file.
    double radians(int tick) const { return degToRad(reduceDegrees(degrees(tick))); }
    int fullTurn() const { return fullTurn_; }

    // n evenly spread samples, the first at `offset` ticks, with their best radii.
    Outline uniform(int n, int offset) {
        Outline o;
        for (int k = 0; k < n; ++k) {
            int t = static_cast<int>((static_cast<long long>(k) * fullTurn_ + n / 2) / n);
            o.ticks.push_back((t + offset) % fullTurn_);
        }
        o.w.assign(o.size(), std::nan(""));
        for (std::size_t k = 0; k < o.size(); ++k)
            o.sectors.push_back(sector(o.ticks[k], o.ticks[o.next(k)]));
        std::vector<std::size_t> all(o.size());
        for (std::size_t k = 0; k < o.size(); ++k) all[k] = k;
        repair(o, all);
        polishUntilStable(o);
        return o;
    }

    // Improves the angles by passes of local search; `report(pass)` is called once per pass. It stops
    // when a pass gains less than kMinPassGain of the slack area still left, which is the outline's
    // area minus `pixelArea` (enclosing) or `pixelArea`, the free area, minus the outline's area
    // (container).
    template <class Report>
    void optimiseAngles(Outline& o, double pixelArea, Report&& report) {
        static constexpr double kMinPassGain = 0.01;
        for (int pass = 0; pass < kMaxPasses; ++pass) {
            report(pass);
            double before = o.score;
            for (std::size_t i = 0; i < o.size(); ++i) bestMove(o, i);
            exchange(o);
            polishUntilStable(o);
            double slackArea = container_ ? pixelArea + o.score : o.score - pixelArea;
            if (!(before - o.score > kMinPassGain * std::max(slackArea, 1e-9))) break;
        }
    }

    double area(const Outline& o) const {
        double sum = 0.0;
        for (std::size_t k = 0; k < o.size(); ++k)
            sum += 0.5 * o.sectors[k]->sinDelta / (o.w[k] * o.w[o.next(k)]);
        return sum;
    }

  private:
    int gap(int t1, int t2) const { return ((t2 - t1) % fullTurn_ + fullTurn_) % fullTurn_; }

    // w's bound from a sample's own ray: at most 1/ρ (enclosing), at least 1/σ (container).
    double bound(int tick) {
        double& b = bound_[tick];
        if (b < 0.0) {
            double limit = field_.rayLimitWithCorners(radians(tick));
            b = container_ ? 1.0 / limit : 1.0 / std::max(limit, kMinRadius);
        }
        return b;
    }

    SectorPtr sector(int t1, int t2) const {
        auto s = std::make_shared<Sector>();
        const Vec2& u1 = dir_[t1];
        const Vec2& u2 = dir_[t2];
        double d = cross(u1, u2);  // sin Δ > 0: gaps stay under 180°
        s->sinDelta = d;
        double a1 = radians(t1);
        double a2 = a1 + degToRad(degrees(gap(t1, t2)));
        field_.forEachCorner(a1 - 1e-9, a2 + 1e-9, [&](const RadialField::Corner& c) {
            double lambda = cross(c.p, u2) / d;
            double mu = cross(u1, c.p) / d;
            if (lambda < -kOnRay || mu < -kOnRay) return;
            s->points.push_back({std::max(lambda, 0.0), std::max(mu, 0.0)});
        });
        // Keep the Pareto front of the binding points. Enclosing (λ·w1 + μ·w2 ≤ 1): a point with both
        // λ and μ no larger than another's is implied by it. Container (≥ 1): one with both no smaller.
        const double sign = container_ ? -1.0 : 1.0;
        std::sort(s->points.begin(), s->points.end(), [sign](const SectorPoint& a, const SectorPoint& b) {
            return sign * a.lambda > sign * b.lambda || (a.lambda == b.lambda && sign * a.mu > sign * b.mu);
        });
        std::vector<SectorPoint> front;
        double best = -kInf;
        for (const SectorPoint& p : s->points)
            if (sign * p.mu > best) front.push_back(p), best = sign * p.mu;
        s->points = std::move(front);
        return s;
    }

    double better(double a, double b) const { return container_ ? std::max(a, b) : std::min(a, b); }

    // The best (w1, w2) for one edge alone, with its rays' bounds b1, b2.
    std::pair<double, double> edgeOptimum(const Sector& s, double b1, double b2) const {
        std::vector<Line> lines{{0.0, b2}};
        double x1 = b1;  // enclosing: the largest w1; container: the smallest
        for (const SectorPoint& p : s.points) {
            if (p.mu <= kOnRay) {
                if (p.lambda > kOnRay) x1 = better(x1, 1.0 / p.lambda);
                continue;
            }
            lines.push_back({-p.lambda / p.mu, 1.0 / p.mu});
        }
        if (!container_) {
            // Maximise x·env(x) over (0, x1] on the lower envelope: per piece a concave quadratic.
            double bestX = x1, bestF = -kInf;
            auto consider = [&](double x, const Line& l) {
                double f = x * l.at(x);
                if (x > 0.0 && l.at(x) > 0.0 && f > bestF) bestF = f, bestX = x;
            };
            for (const Piece& piece : envelope(lines, 0.0, x1, true)) {
                consider(piece.x1, piece.line);
                consider(piece.x0, piece.line);
                if (piece.line.m < 0.0) {
                    double xs = -piece.line.b / (2.0 * piece.line.m);
                    if (xs > piece.x0 && xs < piece.x1) consider(xs, piece.line);
                }
            }
            double y = kInf;
            for (const Line& l : lines) y = std::min(y, l.at(bestX));
            if (!(y > 0.0)) return {x1 * 0.5, b2 * 0.5};  // degenerate; still valid, polished later
            return {bestX, y};
        }
        // Container: minimise x·env(x) over [x1, ∞) on the upper envelope; per piece concave, so
        // the minimum is at a piece's left end.
        double bestX = x1, bestF = kInf;
        for (const Piece& piece : envelope(lines, x1, kInf, false)) {
            double f = piece.x0 * piece.line.at(piece.x0);
            if (f < bestF) bestF = f, bestX = piece.x0;
        }
        double y = -kInf;
        for (const Line& l : lines) y = std::max(y, l.at(bestX));
        return {bestX, y};
    }

    // The w for vertex i that its two edges and its ray allow, given its neighbours.
    double tightest(const Outline& o, std::size_t i) {
        std::size_t p = o.prev(i), n = o.next(i);
        double w = bound(o.ticks[i]);
        for (const SectorPoint& q : o.sectors[p]->points)
            if (q.mu > kOnRay) w = better(w, (1.0 - q.lambda * o.w[p]) / q.mu);
        for (const SectorPoint& q : o.sectors[i]->points)
            if (q.lambda > kOnRay) w = better(w, (1.0 - q.mu * o.w[n]) / q.lambda);
        return w;
    }

    void descend(Outline& o, std::size_t i) {
        double w = tightest(o, i);
        if (w > 0.0 && std::isfinite(w)) o.w[i] = w;
    }

    // Grows radius i a little when its neighbours can then shrink by more.
    void pivot(Outline& o, std::size_t i) {
        static constexpr double kFactors[] = {0.995, 0.98, 0.95, 0.9, 0.8, 0.6};
        std::size_t p = o.prev(i), n = o.next(i);
        auto local = [&](const Outline& x) {
            if (x.size() <= 4) return container_ ? -area(x) : area(x);
            double sum = 0.0;
            for (std::size_t k : {o.prev(p), p, i, n})
                sum += 0.5 * x.sectors[k]->sinDelta / (x.w[k] * x.w[x.next(k)]);
            return container_ ? -sum : sum;
        };
        double bestScore = local(o);
        std::array<double, 3> bestW{o.w[p], o.w[i], o.w[n]};
        std::array<double, 3> saved = bestW;
        for (double f : kFactors) {
            o.w[i] = container_ ? saved[1] / f : saved[1] * f;
            descend(o, p);
            descend(o, n);
            descend(o, i);
            double s = local(o);
            if (s < bestScore - 1e-12 * std::fabs(bestScore)) bestScore = s, bestW = {o.w[p], o.w[i], o.w[n]};
            o.w[p] = saved[0], o.w[i] = saved[1], o.w[n] = saved[2];
        }
        o.w[p] = bestW[0], o.w[i] = bestW[1], o.w[n] = bestW[2];
    }

    void polish(Outline& o, const std::vector<std::size_t>& window, int sweeps) {
        for (int s = 0; s < sweeps; ++s) {
            for (std::size_t i : window) descend(o, i);
            if (o.size() >= 3)
                for (std::size_t i : window) pivot(o, i);
        }
        o.score = container_ ? -area(o) : area(o);
    }

    void polishUntilStable(Outline& o) {
        std::vector<std::size_t> all(o.size());
        for (std::size_t k = 0; k < o.size(); ++k) all[k] = k;
        double last = kInf;
        for (int round = 0; round < 200; ++round) {
            polish(o, all, 1);
            if (!(o.score < last - 1e-11 * std::fabs(o.score))) break;
            last = o.score;
        }
        if (!container_) solveExactly(o);
    }

    // The optimal radii for fixed angles (enclosing only), by a log-barrier Newton method.
    //
    // In w = 1/r the problem is convex: the area Σ s_k/(2·w_k·w_{k+1}) has the Hessian
    // s/(w1·w2)·[1/w1², 1/(2·w1·w2); 1/(2·w1·w2), 1/w2²] per edge, positive definite for w > 0, and
    // every constraint is linear: λ·w_k + μ·w_{k+1} ≤ 1 per corner, w_i ≤ bound_i per ray. So the
    // barrier t·area − Σ log(slacks) has one minimum, and Newton's method finds it; each step solves a
    // cyclic tridiagonal system. This fixes what coordinate moves cannot: radii that must all change
    // together (a regular polygon around a disc, reached from an alternating one).
    void solveExactly(Outline& o) {
        const std::size_t n = o.size();
        std::vector<double> w = o.w;
        for (double& x : w) x *= 1.0 - 1e-4;  // strictly inside every constraint
        std::size_t constraints = 2 * n;
        for (const SectorPtr& s : o.sectors) constraints += s->points.size();

        // The barrier's value, or ∞ outside the feasible set.
        auto value = [&](const std::vector<double>& v, double t) {
            double f = 0.0;
            for (std::size_t k = 0; k < n; ++k) {
                std::size_t j = (k + 1) % n;
                if (!(v[k] > 0.0)) return kInf;
                double slack = bound(o.ticks[k]) - v[k];
                if (!(slack > 0.0)) return kInf;
                f += t * 0.5 * o.sectors[k]->sinDelta / (v[k] * v[j]) - std::log(slack) - std::log(v[k]);
                for (const SectorPoint& p : o.sectors[k]->points) {
                    double g = 1.0 - p.lambda * v[k] - p.mu * v[j];
                    if (!(g > 0.0)) return kInf;
                    f -= std::log(g);
                }
            }
            return f;
        };
        double t = static_cast<double>(constraints) / std::max(area(o), 1e-9);
        for (int outer = 0; outer < 40; ++outer) {
            for (int iter = 0; iter < 80; ++iter) {
                Eigen::VectorXd grad = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(n));
                std::vector<Eigen::Triplet<double>> entries;
                auto add = [&](std::size_t a, std::size_t b, double v) {
                    entries.emplace_back(static_cast<int>(a), static_cast<int>(b), v);
                };
                for (std::size_t k = 0; k < n; ++k) {
                    std::size_t j = (k + 1) % n;
                    double a = w[k], b = w[j], s = o.sectors[k]->sinDelta;
                    // t·s/(2ab): gradient −t·s/(2a²b), −t·s/(2ab²); Hessian t·s/(a³b), t·s/(ab³),
                    // t·s/(2a²b²).
                    grad[k] += -t * s / (2 * a * a * b);
                    grad[j] += -t * s / (2 * a * b * b);
                    add(k, k, t * s / (a * a * a * b));
                    add(j, j, t * s / (a * b * b * b));
                    add(k, j, t * s / (2 * a * a * b * b));
                    add(j, k, t * s / (2 * a * a * b * b));
                    double slack = bound(o.ticks[k]) - a;
                    grad[k] += 1.0 / slack - 1.0 / a;
                    add(k, k, 1.0 / (slack * slack) + 1.0 / (a * a));
                    for (const SectorPoint& p : o.sectors[k]->points) {
                        double g = 1.0 - p.lambda * a - p.mu * b;
                        grad[k] += p.lambda / g;
                        grad[j] += p.mu / g;
                        double g2 = g * g;
                        add(k, k, p.lambda * p.lambda / g2);
                        add(j, j, p.mu * p.mu / g2);
                        add(k, j, p.lambda * p.mu / g2);
                        add(j, k, p.lambda * p.mu / g2);
                    }
                }
                Eigen::SparseMatrix<double> hessian(static_cast<Eigen::Index>(n),
                                                    static_cast<Eigen::Index>(n));
                hessian.setFromTriplets(entries.begin(), entries.end());
                Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(hessian);
                if (solver.info() != Eigen::Success) break;
                Eigen::VectorXd step = -solver.solve(grad);
                double decrement = -grad.dot(step);  // the Newton decrement squared
                if (!(decrement > 1e-12)) break;
                double current = value(w, t), size = 1.0;
                std::vector<double> trial(n);
                for (int halving = 0; halving < 60; ++halving, size *= 0.5) {
                    for (std::size_t k = 0; k < n; ++k)
                        trial[k] = w[k] + size * step[static_cast<Eigen::Index>(k)];
                    if (value(trial, t) <= current - 0.25 * size * decrement) break;
                }
                if (value(trial, t) >= current) break;
                w = trial;
            }
            if (static_cast<double>(constraints) / t < 1e-10 * area(o)) break;
            t *= 20.0;
        }
        Outline solved = o;
        solved.w = w;
        solved.score = area(solved);
        if (solved.score < o.score) o = std::move(solved);
    }

    // Makes the outline valid again after the edges in `changed` got new sectors (their end
    // vertices may hold NaN), then polishes the neighbourhood.
    void repair(Outline& o, const std::vector<std::size_t>& changed) {
        for (std::size_t k : changed) {
            std::size_t a = k, b = o.next(k);
            auto [w1, w2] = edgeOptimum(*o.sectors[k], bound(o.ticks[a]), bound(o.ticks[b]));
            o.w[a] = std::isnan(o.w[a]) ? w1 : better(o.w[a], w1);
            o.w[b] = std::isnan(o.w[b]) ? w2 : better(o.w[b], w2);
        }
        std::vector<std::size_t> window;
        std::size_t n = o.size();
        if (changed.size() >= n || n <= 6) {
            for (std::size_t k = 0; k < n; ++k) window.push_back(k);
        } else {
            for (std::size_t k : changed)
                for (std::size_t d = 0; d < 6; ++d) window.push_back((k + n - 2 + d) % n);
            std::sort(window.begin(), window.end());
            window.erase(std::unique(window.begin(), window.end()), window.end());
        }
        polish(o, window, 1);
    }

    Outline moved(const Outline& o, std::size_t i, int tick) {
        Outline t = o;
        t.ticks[i] = tick;
        t.w[i] = std::nan("");
        std::size_t p = t.prev(i);
        t.sectors[p] = sector(t.ticks[p], tick);
        t.sectors[i] = sector(tick, t.ticks[t.next(i)]);
        repair(t, {p, i});
        return t;
    }

    Outline removed(const Outline& o, std::size_t i) {
        Outline t = o;
        t.ticks.erase(t.ticks.begin() + static_cast<std::ptrdiff_t>(i));
        t.w.erase(t.w.begin() + static_cast<std::ptrdiff_t>(i));
        t.sectors.erase(t.sectors.begin() + static_cast<std::ptrdiff_t>(i));
        std::size_t p = (i + t.size() - 1) % t.size();
        t.sectors[p] = sector(t.ticks[p], t.ticks[t.next(p)]);
        repair(t, {p});
        return t;
    }

    // Inserts a sample at `tick` on edge k (between vertex k and k + 1).
    Outline inserted(const Outline& o, std::size_t k, int tick) {
        Outline t = o;
        std::size_t at = k + 1;
        t.ticks.insert(t.ticks.begin() + static_cast<std::ptrdiff_t>(at), tick);
        t.w.insert(t.w.begin() + static_cast<std::ptrdiff_t>(at), std::nan(""));
        t.sectors.insert(t.sectors.begin() + static_cast<std::ptrdiff_t>(at), nullptr);
        t.sectors[k] = sector(t.ticks[k], tick);
        t.sectors[at] = sector(tick, t.ticks[t.next(at)]);
        repair(t, {k, at});
        return t;
    }

    // Tries offsets d in [1, span) through `trial(d)`, coarsely first (about kScanSteps of them), then
    // every tick around the best one so far, which `trial` keeps in `bestOffset` (0: none better).
    template <class Trial>
    void scanOffsets(int span, Trial&& trial, const int& bestOffset) {
        static constexpr int kScanSteps = 16;
        int stride = std::max(1, span / kScanSteps);
        for (int d = 1; d < span; d += stride) trial(d);
        if (stride == 1 || bestOffset == 0) return;
        int centre = bestOffset;
        for (int d = std::max(1, centre - stride + 1); d < std::min(span, centre + stride); ++d)
            if ((d - 1) % stride != 0) trial(d);
    }

    // Moves sample i to its best grid angle between its neighbours; true if that helped.
    bool bestMove(Outline& o, std::size_t i) {
        int prevTick = o.ticks[o.prev(i)], nextTick = o.ticks[o.next(i)];
        int span = gap(prevTick, nextTick);
        if (span < 2) return false;
        Outline best = o;
        int bestOffset = 0;
        scanOffsets(
            span,
            [&](int d) {
                int tick = (prevTick + d) % fullTurn_;
                if (tick == o.ticks[i] || d > maxGapTicks_ || span - d > maxGapTicks_) return;
                Outline t = moved(o, i, tick);
                if (t.score < best.score - 1e-12 * std::fabs(best.score)) best = std::move(t), bestOffset = d;
            },
            bestOffset);
        if (bestOffset == 0) return false;
        o = std::move(best);
        return true;
    }

    // Removes the cheapest sample and inserts one where it gains most, if the swap helps. (Also trying
    // the second and third cheapest changed nothing on the demo's sprites and cost twice the time.)
    bool exchange(Outline& o) {
        if (o.size() < 4) return false;
        std::optional<std::size_t> gone;
        double cheapest = kInf;
        for (std::size_t i = 0; i < o.size(); ++i) {
            if (gap(o.ticks[o.prev(i)], o.ticks[o.next(i)]) > maxGapTicks_) continue;
            double score = removed(o, i).score;
            if (score < cheapest) cheapest = score, gone = i;
        }
        if (!gone) return false;
        Outline r = removed(o, *gone);
        Outline best = o;
        for (std::size_t k = 0; k < r.size(); ++k) {
            int from = r.ticks[k], span = gap(from, r.ticks[r.next(k)]);
            int bestOffset = 0;
            scanOffsets(
                span,
                [&](int d) {
                    int tick = (from + d) % fullTurn_;
                    if (tick == o.ticks[*gone]) return;  // putting it back is no exchange
                    Outline t = inserted(r, k, tick);
                    if (t.score < best.score - 1e-12 * std::fabs(best.score))
                        best = std::move(t), bestOffset = d;
                },
                bestOffset);
        }
        if (!(best.score < o.score - 1e-12 * std::fabs(o.score))) return false;
        o = std::move(best);
        return true;
    }

    const RadialField& field_;
    bool container_;
    int ticksPerDegree_;
    int fullTurn_;
    int maxGapTicks_;
    std::vector<Vec2> dir_;
    std::vector<double> bound_;
};

// The coarsest angle grid (ticks per degree) whose step is at most half a pixel of arc at radius r.
int ticksPerDegreeFor(double r, int samples) {
    for (int tpd : {1, 2, 4, 5, 10, 20}) {
        double arc = degToRad(1.0 / tpd) * r;
        if (arc <= 0.5 && 360 * tpd >= 8 * samples) return tpd;
    }
    return 20;
}

// One sample per kAutoSpacing px of the boundary's length (pixel edges · π/4 ≈ the Euclidean length).
int autoSamples(const PixelSet& set, bool container) {
    auto solid = [&](int x, int y) {
        bool outside = x < 0 || y < 0 || x >= set.width || y >= set.height;
        return outside ? container : set.has(x, y);
    };
    long edges = 0;
    for (int y = -1; y <= set.height; ++y)
        for (int x = -1; x <= set.width; ++x) {
            if (solid(x, y) != solid(x + 1, y)) ++edges;
            if (solid(x, y) != solid(x, y + 1)) ++edges;
        }
    double length = edges * (kPi / 4.0);
    int n = static_cast<int>(std::ceil(length / BoundsGenOptions::kAutoSpacing));
    return std::clamp(n, BoundsGenOptions::kAutoMin,
                      container ? BoundsGenOptions::kAutoMaxContainer : BoundsGenOptions::kAutoMax);
}

// Whether `centre` lies on a wall pixel's closed square or outside the image (container fits).
bool centreOnWall(const PixelSet& walls, const Vec2& centre) {
    double gx = centre.x() + walls.width * 0.5, gy = walls.height * 0.5 - centre.y();
    if (gx <= 0.0 || gy <= 0.0 || gx >= walls.width || gy >= walls.height) return true;
    int x0 = static_cast<int>(std::floor(gx)), y0 = static_cast<int>(std::floor(gy));
    for (int y = y0 - 1; y <= y0 + 1; ++y)
        for (int x = x0 - 1; x <= x0 + 1; ++x)
            if (walls.has(x, y) && gx >= x && gx <= x + 1 && gy >= y && gy <= y + 1) return true;
    return false;
}

std::string pointText(const Vec2& p) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "(%g, %g)", p.x(), p.y());
    return buffer;
}

Error optionError(std::string what, std::string expected) {
    return Error{"", 0, 0, std::move(what), std::move(expected)};
}

// Fits one CollisionRadii around (or inside) `set` from `centre`; reports through `progress`.
Result<RadiiSpec> fitOne(const PixelSet& set, const Vec2& centre, bool container, int samples,
                         const std::function<void(double)>& progress) {
    RadialField field(set, centre, container);
    if (container && (centreOnWall(set, centre) || field.nearestSquareDistance() <= 0.0))
        return optionError("the centre " + pointText(centre) + " lies on an opaque pixel",
                           "a container's centre in its free space (--centre X,Y)");
    int n = samples > 0 ? samples : autoSamples(set, container);
    double reach = field.maxCornerDistance();
    if (container) {
        reach = 0.0;
        for (int k = 0; k < 360; ++k) reach = std::max(reach, field.rayLimit(direction(degToRad(k))));
    }
    int tpd = ticksPerDegreeFor(reach, n);
    int maxGap = static_cast<int>(BoundsGenOptions::kMaxGapDegrees * tpd);
    Fitter fitter(field, tpd, maxGap);
    // The start matters when all samples would have to turn together (4 samples around a square):
    // try kOffsets rotations of the even spread and keep the best.
    constexpr int kOffsets = 8;
    Outline outline = fitter.uniform(n, 0);
    for (int j = 1; j < kOffsets; ++j) {
        Outline rotated = fitter.uniform(n, j * (fitter.fullTurn() / n) / kOffsets);
        if (rotated.score < outline.score) outline = std::move(rotated);
    }
    double pixelArea = container ? static_cast<double>(set.width) * set.height - set.count() : set.count();
    fitter.optimiseAngles(outline, pixelArea, [&](int pass) {
        if (progress) progress(static_cast<double>(pass) / kMaxPasses);
    });

    RadiiSpec spec;
    spec.centre = centre;
    spec.interpolate = true;
    std::size_t first = static_cast<std::size_t>(
        std::min_element(outline.ticks.begin(), outline.ticks.end()) - outline.ticks.begin());
    for (std::size_t j = 0; j < outline.size(); ++j) {
        std::size_t k = (first + j) % outline.size();
        double r = 1.0 / outline.w[k];
        r = container ? std::floor((r - kMargin) * kRadiusScale) / kRadiusScale
                      : std::ceil((r + kMargin) * kRadiusScale) / kRadiusScale;
        spec.samples.push_back({fitter.degrees(outline.ticks[k]), std::max(r, 1.0 / kRadiusScale)});
    }
    // The engine's own trigonometry decides; nudge the radii in the rare case rounding disagrees.
    for (int attempt = 1; attempt <= 20; ++attempt) {
        FitQuality q =
            measureFit(set, CollisionRadii::fromDegrees(spec.centre, spec.samples, true), container);
        if (q.worstMiss == 0.0) break;
        for (DegreeSample& s : spec.samples)
            s[1] = std::max(1.0 / kRadiusScale, s[1] + (container ? -1.0 : 1.0) * attempt / kRadiusScale);
    }
    return spec;
}

}  // namespace

std::vector<PixelSet> splitAlongPrincipalAxis(const PixelSet& set, int k) {
    if (k <= 1) return {set};
    Vec2 mean = set.centroid();
    double sxx = 0, syy = 0, sxy = 0;
    std::vector<std::pair<int, int>> pixels;
    for (int y = 0; y < set.height; ++y)
        for (int x = 0; x < set.width; ++x)
            if (set.has(x, y)) {
                Vec2 d = Vec2(x + 0.5 - set.width * 0.5, set.height * 0.5 - y - 0.5) - mean;
                sxx += d.x() * d.x(), syy += d.y() * d.y(), sxy += d.x() * d.y();
                pixels.push_back({x, y});
            }
    // The principal axis of the covariance: θ = ½·atan2(2·sxy, sxx − syy).
    Vec2 axis = direction(0.5 * trig::atan2(2.0 * sxy, sxx - syy));
    double lo = kInf, hi = -kInf;
    auto along = [&](int x, int y) {
        return (Vec2(x + 0.5 - set.width * 0.5, set.height * 0.5 - y - 0.5) - mean).dot(axis);
    };
    for (auto [x, y] : pixels) lo = std::min(lo, along(x, y)), hi = std::max(hi, along(x, y));
    std::vector<PixelSet> parts(static_cast<std::size_t>(k), PixelSet{set.width, set.height, {}});
    for (PixelSet& part : parts) part.member.assign(set.member.size(), 0);
    for (auto [x, y] : pixels) {
        int index = hi > lo ? static_cast<int>((along(x, y) - lo) / (hi - lo) * k) : 0;
        parts[static_cast<std::size_t>(std::clamp(index, 0, k - 1))]
            .member[static_cast<std::size_t>(y) * set.width + x] = 1;
    }
    std::erase_if(parts, [](const PixelSet& p) { return p.count() == 0; });
    return parts;
}

int PixelSet::count() const {
    return static_cast<int>(std::count(member.begin(), member.end(), std::uint8_t{1}));
}

Vec2 PixelSet::centroid() const {
    Vec2 sum = Vec2::Zero();
    int n = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            if (has(x, y)) sum += Vec2(x + 0.5 - width * 0.5, height * 0.5 - y - 0.5), ++n;
    return n ? Vec2(sum / n) : Vec2(Vec2::Zero());
}

PixelSet PixelSet::opaque(const AlphaMask& mask, std::uint8_t threshold) {
    PixelSet set{mask.width, mask.height, {}};
    set.member.resize(mask.alpha.size());
    for (int y = 0; y < mask.height; ++y)
        for (int x = 0; x < mask.width; ++x)
            set.member[static_cast<std::size_t>(y) * mask.width + x] = mask.opaque(x, y, threshold) ? 1 : 0;
    return set;
}

FitQuality measureFit(const PixelSet& pixels, const CollisionRadii& radii, bool container) {
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

Result<GeneratedBounds> generateBounds(const AlphaMask& sprite, const BoundsGenOptions& options) {
    if (options.samples != 0 && options.samples < 3)
        return optionError("-n " + std::to_string(options.samples) + " is too few samples",
                           "at least 3 samples (straight edges need 3), or 0 for automatic");
    if (options.samples > 720)
        return optionError("-n " + std::to_string(options.samples) + " is too many samples",
                           "at most 720 samples");
    if (options.radii < 1 || options.radii > 16)
        return optionError("--radii " + std::to_string(options.radii) + " is out of range", "1 to 16 radii");
    if (options.container && options.radii != 1)
        return optionError("--container with --radii " + std::to_string(options.radii),
                           "one CollisionRadii for a container");
    if (options.radii > 1 && options.centre)
        return optionError("--centre with --radii " + std::to_string(options.radii),
                           "--centre only for one radii; each part of a split uses its own centroid");
    if (options.centre && !(std::isfinite(options.centre->x()) && std::isfinite(options.centre->y())))
        return optionError("a non-finite centre", "--centre X,Y with finite numbers");

    PixelSet opaque = PixelSet::opaque(sprite, options.threshold);
    GeneratedBounds out;
    if (!options.container && opaque.count() == 0)
        return optionError("no opaque pixels (alpha above " + std::to_string(options.threshold) + ")",
                           "a sprite with an opaque shape to enclose");
    std::vector<PixelSet> parts =
        options.container ? std::vector<PixelSet>{opaque} : splitAlongPrincipalAxis(opaque, options.radii);
    for (std::size_t k = 0; k < parts.size(); ++k) {
        Vec2 centre = options.centre      ? *options.centre
                      : options.container ? Vec2(Vec2::Zero())
                                          : parts[k].centroid();
        auto progress = [&](double fraction) {
            if (options.progress)
                options.progress("radii " + std::to_string(k + 1) + "/" + std::to_string(parts.size()),
                                 (k + fraction) / parts.size());
        };
        Result<RadiiSpec> spec = fitOne(parts[k], centre, options.container, options.samples, progress);
        if (!spec) return spec.error();
        out.quality.push_back(measureFit(
            parts[k], CollisionRadii::fromDegrees(spec->centre, spec->samples, true), options.container));
        out.partPixels.push_back(parts[k].count());
        out.spec.radii.push_back(std::move(*spec));
    }
    if (options.progress) options.progress("done", 1.0);
    return out;
}

}  // namespace polar
