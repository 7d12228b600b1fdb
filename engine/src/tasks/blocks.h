#pragma once
#include <cstddef>
#include <cstdint>

#include "tasks/parallel_for.h"

namespace polar {

// [0, count) cut into `blocks` ranges whose sizes differ by at most one: block b is
// [count·b/blocks, count·(b + 1)/blocks). The cut depends on count and blocks alone, never on the
// threads, so a pass that writes per-block outputs (counts, sums) gets the same ones at any worker
// count, and a later pass can read them by block.
struct BlockSplit {
    std::size_t count = 0;
    std::uint32_t blocks = 1;

    std::size_t begin(std::uint32_t b) const { return count * b / blocks; }
    std::size_t end(std::uint32_t b) const { return count * (b + 1) / blocks; }
};

// Calls body(b) for every block b in [0, blocks), on `tasks` (one block per range, claimed as the
// workers come free) or, with tasks null, on the calling thread in order.
template <class Body>
void forEachBlock(TaskSystem* tasks, std::uint32_t blocks, Body&& body) {
    auto ranges = [&](std::uint32_t begin, std::uint32_t end, std::uint32_t) {
        for (std::uint32_t b = begin; b < end; ++b) body(b);
    };
    if (tasks && blocks > 1)
        parallelFor(*tasks, blocks, 1, ranges);
    else
        ranges(0, blocks, 0);
}

}  // namespace polar
