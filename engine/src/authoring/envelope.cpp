#include "authoring/envelope.h"

#include <cstddef>
#include <limits>

namespace polar {

// Walks from lo: at each step the active line is overtaken first by a line of smaller
// slope (lower) or larger slope (upper), so it ends after at most one step per line.
std::vector<EnvelopePiece> envelope(const std::vector<EnvelopeLine>& lines, double lo, double hi,
                                    bool lower) {
    auto better = [&](const EnvelopeLine& a, const EnvelopeLine& b, double x) {
        double ya = a.at(x), yb = b.at(x);
        if (ya != yb) return lower ? ya < yb : ya > yb;
        return lower ? a.m < b.m : a.m > b.m;
    };
    std::size_t active = 0;
    for (std::size_t k = 1; k < lines.size(); ++k)
        if (better(lines[k], lines[active], lo)) active = k;
    std::vector<EnvelopePiece> pieces;
    double x = lo;
    while (true) {
        const EnvelopeLine& cur = lines[active];
        double nextX = std::numeric_limits<double>::infinity();
        std::size_t nextLine = active;
        for (std::size_t k = 0; k < lines.size(); ++k) {
            const EnvelopeLine& l = lines[k];
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

}  // namespace polar
