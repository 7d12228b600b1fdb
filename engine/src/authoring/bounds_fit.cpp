#include "authoring/bounds_fit.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include "authoring/envelope.h"
#include "authoring/radial_field.h"

namespace polar {
namespace {

// The smallest radius an enclosing outline uses toward directions with no opaque pixel.
constexpr double kMinRadius = 0.25;
// Safety margin before rounding radii to 3 decimals (away from the pixels), so that a pixel corner
// lying exactly on an edge stays on the right side when the engine's trigonometry rounds differently.
constexpr double kMargin = 1e-6;
constexpr double kRadiusScale = 1000.0;  // radii are written with 3 decimals
constexpr int kMaxPasses = 12;

// A corner inside one edge's sector, written as q = λ·u1 + μ·u2 along the sector's two rays.
// The edge from r1·u1 to r2·u2 has q on its inner side iff λ/r1 + μ/r2 ≤ 1, that is
// λ·w1 + μ·w2 ≤ 1 with w = 1/r: linear in the inverse radii, which is what makes fitting tractable.
struct SectorPoint {
    double lambda;
    double mu;
};

// One edge of a FitPolygon: the corners in its sector (between its two rays) that bind its end
// radii, as SectorPoints, and sin Δ of the angle Δ between the rays.
struct FitEdge {
    std::vector<SectorPoint> points;
    double sinDelta = 0.0;  // sin of the angle between the two rays, for the area ½·r1·r2·sin Δ
};
using FitEdgePtr = std::shared_ptr<const FitEdge>;

// A polygon under construction: sample angles as integer ticks of the angle grid, inverse radii,
// and its edges (edge k joins vertex k and k + 1, circularly). The ticks run
// counter-clockwise but may start anywhere (a sample moved across 0° stays where it is in the list).
struct FitPolygon {
    std::vector<int> ticks;
    std::vector<double> w;
    std::vector<FitEdgePtr> edges;
    double score = 0.0;  // lower is better: the area (enclosing) or minus the area (container)

    std::size_t size() const { return ticks.size(); }
    std::size_t prev(std::size_t i) const { return (i + size() - 1) % size(); }
    std::size_t next(std::size_t i) const { return (i + 1) % size(); }
};

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
    FitPolygon uniform(int n, int offset) {
        FitPolygon o;
        for (int k = 0; k < n; ++k) {
            int t = static_cast<int>((static_cast<long long>(k) * fullTurn_ + n / 2) / n);
            o.ticks.push_back((t + offset) % fullTurn_);
        }
        o.w.assign(o.size(), std::nan(""));
        for (std::size_t k = 0; k < o.size(); ++k) o.edges.push_back(edge(o.ticks[k], o.ticks[o.next(k)]));
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
    void optimiseAngles(FitPolygon& o, double pixelArea, Report&& report) {
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

    double area(const FitPolygon& o) const {
        double sum = 0.0;
        for (std::size_t k = 0; k < o.size(); ++k)
            sum += 0.5 * o.edges[k]->sinDelta / (o.w[k] * o.w[o.next(k)]);
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

    // The edge from the ray at tick t1 counter-clockwise to the ray at tick t2.
    FitEdgePtr edge(int t1, int t2) const {
        auto s = std::make_shared<FitEdge>();
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
    std::pair<double, double> edgeOptimum(const FitEdge& s, double b1, double b2) const {
        std::vector<EnvelopeLine> lines{{0.0, b2}};
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
            auto consider = [&](double x, const EnvelopeLine& l) {
                double f = x * l.at(x);
                if (x > 0.0 && l.at(x) > 0.0 && f > bestF) bestF = f, bestX = x;
            };
            for (const EnvelopePiece& piece : envelope(lines, 0.0, x1, true)) {
                consider(piece.x1, piece.line);
                consider(piece.x0, piece.line);
                if (piece.line.m < 0.0) {
                    double xs = -piece.line.b / (2.0 * piece.line.m);
                    if (xs > piece.x0 && xs < piece.x1) consider(xs, piece.line);
                }
            }
            double y = kInf;
            for (const EnvelopeLine& l : lines) y = std::min(y, l.at(bestX));
            if (!(y > 0.0)) return {x1 * 0.5, b2 * 0.5};  // degenerate; still valid, polished later
            return {bestX, y};
        }
        // Container: minimise x·env(x) over [x1, ∞) on the upper envelope; per piece concave, so
        // the minimum is at a piece's left end.
        double bestX = x1, bestF = kInf;
        for (const EnvelopePiece& piece : envelope(lines, x1, kInf, false)) {
            double f = piece.x0 * piece.line.at(piece.x0);
            if (f < bestF) bestF = f, bestX = piece.x0;
        }
        double y = -kInf;
        for (const EnvelopeLine& l : lines) y = std::max(y, l.at(bestX));
        return {bestX, y};
    }

    // The w for vertex i that its two edges and its ray allow, given its neighbours.
    double tightest(const FitPolygon& o, std::size_t i) {
        std::size_t p = o.prev(i), n = o.next(i);
        double w = bound(o.ticks[i]);
        for (const SectorPoint& q : o.edges[p]->points)
            if (q.mu > kOnRay) w = better(w, (1.0 - q.lambda * o.w[p]) / q.mu);
        for (const SectorPoint& q : o.edges[i]->points)
            if (q.lambda > kOnRay) w = better(w, (1.0 - q.mu * o.w[n]) / q.lambda);
        return w;
    }

    void descend(FitPolygon& o, std::size_t i) {
        double w = tightest(o, i);
        if (w > 0.0 && std::isfinite(w)) o.w[i] = w;
    }

    // Grows radius i a little when its neighbours can then shrink by more.
    void pivot(FitPolygon& o, std::size_t i) {
        static constexpr double kFactors[] = {0.995, 0.98, 0.95, 0.9, 0.8, 0.6};
        std::size_t p = o.prev(i), n = o.next(i);
        auto local = [&](const FitPolygon& x) {
            if (x.size() <= 4) return container_ ? -area(x) : area(x);
            double sum = 0.0;
            for (std::size_t k : {o.prev(p), p, i, n})
                sum += 0.5 * x.edges[k]->sinDelta / (x.w[k] * x.w[x.next(k)]);
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

    void polish(FitPolygon& o, const std::vector<std::size_t>& window, int sweeps) {
        for (int s = 0; s < sweeps; ++s) {
            for (std::size_t i : window) descend(o, i);
            if (o.size() >= 3)
                for (std::size_t i : window) pivot(o, i);
        }
        o.score = container_ ? -area(o) : area(o);
    }

    void polishUntilStable(FitPolygon& o) {
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
    void solveExactly(FitPolygon& o) {
        const std::size_t n = o.size();
        std::vector<double> w = o.w;
        for (double& x : w) x *= 1.0 - 1e-4;  // strictly inside every constraint
        std::size_t constraints = 2 * n;
        for (const FitEdgePtr& s : o.edges) constraints += s->points.size();

        // The barrier's value, or ∞ outside the feasible set.
        auto value = [&](const std::vector<double>& v, double t) {
            double f = 0.0;
            for (std::size_t k = 0; k < n; ++k) {
                std::size_t j = (k + 1) % n;
                if (!(v[k] > 0.0)) return kInf;
                double slack = bound(o.ticks[k]) - v[k];
                if (!(slack > 0.0)) return kInf;
                f += t * 0.5 * o.edges[k]->sinDelta / (v[k] * v[j]) - std::log(slack) - std::log(v[k]);
                for (const SectorPoint& p : o.edges[k]->points) {
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
                    double a = w[k], b = w[j], s = o.edges[k]->sinDelta;
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
                    for (const SectorPoint& p : o.edges[k]->points) {
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
        FitPolygon solved = o;
        solved.w = w;
        solved.score = area(solved);
        if (solved.score < o.score) o = std::move(solved);
    }

    // Makes the polygon valid again after the edges in `changed` were rebuilt (their end
    // vertices may hold NaN), then polishes the neighbourhood.
    void repair(FitPolygon& o, const std::vector<std::size_t>& changed) {
        for (std::size_t k : changed) {
            std::size_t a = k, b = o.next(k);
            auto [w1, w2] = edgeOptimum(*o.edges[k], bound(o.ticks[a]), bound(o.ticks[b]));
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

    FitPolygon moved(const FitPolygon& o, std::size_t i, int tick) {
        FitPolygon t = o;
        t.ticks[i] = tick;
        t.w[i] = std::nan("");
        std::size_t p = t.prev(i);
        t.edges[p] = edge(t.ticks[p], tick);
        t.edges[i] = edge(tick, t.ticks[t.next(i)]);
        repair(t, {p, i});
        return t;
    }

    FitPolygon removed(const FitPolygon& o, std::size_t i) {
        FitPolygon t = o;
        t.ticks.erase(t.ticks.begin() + static_cast<std::ptrdiff_t>(i));
        t.w.erase(t.w.begin() + static_cast<std::ptrdiff_t>(i));
        t.edges.erase(t.edges.begin() + static_cast<std::ptrdiff_t>(i));
        std::size_t p = (i + t.size() - 1) % t.size();
        t.edges[p] = edge(t.ticks[p], t.ticks[t.next(p)]);
        repair(t, {p});
        return t;
    }

    // Inserts a sample at `tick` on edge k (between vertex k and k + 1).
    FitPolygon inserted(const FitPolygon& o, std::size_t k, int tick) {
        FitPolygon t = o;
        std::size_t at = k + 1;
        t.ticks.insert(t.ticks.begin() + static_cast<std::ptrdiff_t>(at), tick);
        t.w.insert(t.w.begin() + static_cast<std::ptrdiff_t>(at), std::nan(""));
        t.edges.insert(t.edges.begin() + static_cast<std::ptrdiff_t>(at), nullptr);
        t.edges[k] = edge(t.ticks[k], tick);
        t.edges[at] = edge(tick, t.ticks[t.next(at)]);
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
    bool bestMove(FitPolygon& o, std::size_t i) {
        int prevTick = o.ticks[o.prev(i)], nextTick = o.ticks[o.next(i)];
        int span = gap(prevTick, nextTick);
        if (span < 2) return false;
        FitPolygon best = o;
        int bestOffset = 0;
        scanOffsets(
            span,
            [&](int d) {
                int tick = (prevTick + d) % fullTurn_;
                if (tick == o.ticks[i] || d > maxGapTicks_ || span - d > maxGapTicks_) return;
                FitPolygon t = moved(o, i, tick);
                if (t.score < best.score - 1e-12 * std::fabs(best.score)) best = std::move(t), bestOffset = d;
            },
            bestOffset);
        if (bestOffset == 0) return false;
        o = std::move(best);
        return true;
    }

    // Removes the cheapest sample and inserts one where it gains most, if the swap helps. Only the
    // cheapest: removing the second or third cheapest instead finds no better outline for the game's
    // sprites and takes twice as long.
    bool exchange(FitPolygon& o) {
        if (o.size() < 4) return false;
        std::optional<std::size_t> gone;
        double cheapest = kInf;
        for (std::size_t i = 0; i < o.size(); ++i) {
            if (gap(o.ticks[o.prev(i)], o.ticks[o.next(i)]) > maxGapTicks_) continue;
            double score = removed(o, i).score;
            if (score < cheapest) cheapest = score, gone = i;
        }
        if (!gone) return false;
        FitPolygon r = removed(o, *gone);
        FitPolygon best = o;
        for (std::size_t k = 0; k < r.size(); ++k) {
            int from = r.ticks[k], span = gap(from, r.ticks[r.next(k)]);
            int bestOffset = 0;
            scanOffsets(
                span,
                [&](int d) {
                    int tick = (from + d) % fullTurn_;
                    if (tick == o.ticks[*gone]) return;  // putting it back is no exchange
                    FitPolygon t = inserted(r, k, tick);
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

}  // namespace

Result<BoundSpec> fitBound(const PixelSet& set, const Vec2& centre, bool container, int samples,
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
    FitPolygon polygon = fitter.uniform(n, 0);
    for (int j = 1; j < kOffsets; ++j) {
        FitPolygon rotated = fitter.uniform(n, j * (fitter.fullTurn() / n) / kOffsets);
        if (rotated.score < polygon.score) polygon = std::move(rotated);
    }
    double pixelArea = container ? static_cast<double>(set.width) * set.height - set.count() : set.count();
    fitter.optimiseAngles(polygon, pixelArea, [&](int pass) {
        if (progress) progress(static_cast<double>(pass) / kMaxPasses);
    });

    BoundSpec spec;
    spec.centre = centre;
    spec.interpolate = true;
    std::size_t first = static_cast<std::size_t>(
        std::min_element(polygon.ticks.begin(), polygon.ticks.end()) - polygon.ticks.begin());
    for (std::size_t j = 0; j < polygon.size(); ++j) {
        std::size_t k = (first + j) % polygon.size();
        double r = 1.0 / polygon.w[k];
        r = container ? std::floor((r - kMargin) * kRadiusScale) / kRadiusScale
                      : std::ceil((r + kMargin) * kRadiusScale) / kRadiusScale;
        spec.samples.push_back({fitter.degrees(polygon.ticks[k]), std::max(r, 1.0 / kRadiusScale)});
    }
    // The engine's own trigonometry decides; nudge the radii in the rare case rounding disagrees.
    for (int attempt = 1; attempt <= 20; ++attempt) {
        FitQuality q = measureFit(set, Bound::fromDegrees(spec.centre, spec.samples, true), container);
        if (q.worstMiss == 0.0) break;
        for (DegreeSample& s : spec.samples)
            s[1] = std::max(1.0 / kRadiusScale, s[1] + (container ? -1.0 : 1.0) * attempt / kRadiusScale);
    }
    return spec;
}

}  // namespace polar
