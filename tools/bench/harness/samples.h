#pragma once
// A sample of timings and what the tables quote of it: the median, the spread (interquartile range
// over the median), the best and the worst.
#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

namespace polar::bench {

// The median of `v` in place (its order changes; nothing is allocated): the middle value, or the
// mean of the two middle ones; 0 for none.
inline double medianInPlace(std::span<double> v) {
    if (v.empty()) return 0.0;
    const std::size_t m = v.size() / 2;
    std::nth_element(v.begin(), v.begin() + m, v.end());
    if (v.size() % 2) return v[m];
    return 0.5 * (*std::max_element(v.begin(), v.begin() + m) + v[m]);
}

// The median of a sample (copied, so the caller's order stays).
inline double median(std::vector<double> v) {
    return medianInPlace(v);
}

struct Summary {
    std::size_t count = 0;
    double median = 0;
    double q1 = 0, q3 = 0;  // the lower and upper quartiles (medians of the lower and upper halves)
    double best = 0, worst = 0;

    // (q3 − q1) / median in %: how far apart the middle half of the sample lies.
    double spreadPercent() const { return median > 0 ? 100.0 * (q3 - q1) / median : 0.0; }
};

// The median of a sorted range.
inline double sortedMedian(std::span<const double> v) {
    if (v.empty()) return 0.0;
    const std::size_t m = v.size() / 2;
    return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

inline Summary summarize(std::vector<double> v) {
    Summary s;
    s.count = v.size();
    if (v.empty()) return s;
    std::sort(v.begin(), v.end());
    const std::span<const double> all(v);
    const std::size_t half = std::max<std::size_t>(v.size() / 2, 1);  // odd sizes leave the median out
    s.median = sortedMedian(all);
    s.q1 = sortedMedian(all.first(half));
    s.q3 = sortedMedian(all.last(half));
    s.best = v.front();
    s.worst = v.back();
    return s;
}

}  // namespace polar::bench
