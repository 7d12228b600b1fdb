#include "world/shared_response.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cassert>

#include "tasks/blocks.h"

namespace polar {
namespace {

// Blocks per worker: enough that a worker held up (a dense bucket, a late wake-up) is balanced by the
// others; the tables of counts grow as the square of the blocks, hence the cap (buckets fit a byte).
constexpr std::uint32_t kBlocksPerWorker = 4;
constexpr std::uint32_t kMaxBlocks = 256;
// How far ahead the responses fetch: a hit's line this many hits ahead, its objects' lines half as
// far (their addresses come from the hit, which has arrived by then).
constexpr std::uint32_t kHitsAhead = 16;
constexpr std::uint32_t kObjectsAhead = 8;

// Which bucket a group goes to: its root hashed (Fibonacci hashing) onto [0, buckets). Roots of
// neighbouring groups are often near in index; the hash spreads them.
std::uint32_t bucketOf(std::uint32_t root, std::uint32_t buckets) {
    return static_cast<std::uint32_t>((std::uint64_t(root * 0x9E3779B1u) * buckets) >> 32);
}

void prefetchLines(const void* start, std::size_t bytes) {
    const char* p = static_cast<const char*>(start);
    for (std::size_t line = 0; line < bytes; line += 64) __builtin_prefetch(p + line);
}

// Runs of counts per (key, block), key-major, into where each key's items from each block start:
// keys in order, blocks in order within a key, so the items of one key keep their order.
void startRuns(std::vector<std::uint32_t>& at, std::uint32_t keys, std::uint32_t blocks) {
    std::uint32_t placed = 0;
    for (std::size_t k = 0; k < std::size_t(keys) * blocks; ++k) {
        std::uint32_t count = at[k];
        at[k] = placed;
        placed += count;
    }
}

}  // namespace

void SharedResponse::run(TaskSystem& tasks, std::span<const PairReport> hits,
                         std::span<const GameObject> objects, std::vector<std::uint32_t>& begins,
                         std::vector<ObjectId>& ids, const Responder* responder) {
    const std::uint32_t blocks = std::min(kMaxBlocks, kBlocksPerWorker * tasks.workerCount());
    const BlockSplit hitBlocks{hits.size(), blocks};
    // The lists' ranges of objects: 2^shift objects each (a shift, not a division, per entry), at
    // most `blocks` of them.
    const std::size_t n = objects.size();
    const int shift = std::bit_width((std::max<std::size_t>(n, 1) - 1) / blocks);
    const auto ranges = static_cast<std::uint32_t>(((n - 1) >> shift) + 1);
    assert(ranges <= blocks);
    const bool responds = responder != nullptr;
    const std::uint32_t buckets = blocks;

    // Room, taken here so that no worker allocates.
    begins.resize(n + 1);
    if (2 * hits.size() > ids.capacity())
        ids.reserve(std::max(2 * hits.size(), 2 * ids.capacity()));  // as resize would grow it
    ids.resize(2 * hits.size());
    entries_.resize(hits.size());
    entryAt_.resize(std::size_t(ranges) * blocks);
    if (responds) {
        groups_.resize(n);
        bucketOf_.resize(hits.size());
        order_.resize(hits.size());
        hitAt_.resize(std::size_t(buckets) * blocks);
        bucketBegin_.resize(buckets + 1);
    }

    // 1. Hits: each block counts its B entries per range of objects, and joins its pairs' groups.
    forEachBlock(&tasks, blocks, [&](std::uint32_t b) {
        // Counted apart, then written out once: the blocks' counts share cache lines.
        std::array<std::uint32_t, kMaxBlocks> count{};
        for (std::size_t k = hitBlocks.begin(b), end = hitBlocks.end(b); k < end; ++k) {
            if (responds && k + 16 < end) groups_.prefetch(hits[k + 16].b);
            const PairReport& hit = hits[k];
            assert(hit.a < hit.b && hit.b < n);
            ++count[hit.b >> shift];
            if (responds) groups_.join(hit.a, hit.b);
        }
        for (std::uint32_t r = 0; r < ranges; ++r) entryAt_[std::size_t(r) * blocks + b] = count[r];
    });
    startRuns(entryAt_, ranges, blocks);
    // 2. Hits: each B entry dealt to its range, in pair order; each hit's bucket (the groups are final).
    forEachBlock(&tasks, blocks, [&](std::uint32_t b) {
        std::array<std::uint32_t, kMaxBlocks> next;
        for (std::uint32_t r = 0; r < ranges; ++r) next[r] = entryAt_[std::size_t(r) * blocks + b];
        std::array<std::uint32_t, kMaxBlocks> count{};
        for (std::size_t k = hitBlocks.begin(b), end = hitBlocks.end(b); k < end; ++k) {
            // A's ids, though ascending, lie too far apart for the hardware to see a stream.
            if (k + 16 < end) __builtin_prefetch(&objects[hits[k + 16].a].id);
            const PairReport& hit = hits[k];
            entries_[next[hit.b >> shift]++] = {hit.b, objects[hit.a].id};
            if (!responds) continue;
            std::uint32_t u = bucketOf(groups_.root(hit.a), buckets);
            bucketOf_[k] = static_cast<std::uint8_t>(u);
            ++count[u];
        }
        if (responds)
            for (std::uint32_t u = 0; u < buckets; ++u) hitAt_[std::size_t(u) * blocks + b] = count[u];
    });
    if (responds) {
        startRuns(hitAt_, buckets, blocks);
        for (std::uint32_t u = 0; u < buckets; ++u) bucketBegin_[u] = hitAt_[std::size_t(u) * blocks];
        bucketBegin_[buckets] = static_cast<std::uint32_t>(hits.size());
    }
    // 3. Ranges: each counts and places its objects' entries, as the one-thread counting sort does.
    // An object's partners in pair order are those it is B to (A < B, so those hits come first),
    // then those it is A to: a run of the hits, which are in A's order. Hits: each in its bucket.
    forEachBlock(&tasks, blocks, [&](std::uint32_t b) {
        if (b < ranges) {
            const auto first = static_cast<std::uint32_t>(std::size_t(b) << shift);
            const auto last = static_cast<std::uint32_t>(std::min(n, std::size_t(b + 1) << shift));
            const std::uint32_t from = entryAt_[std::size_t(b) * blocks];
            const std::uint32_t to = b + 1 < ranges ? entryAt_[std::size_t(b + 1) * blocks]
                                                    : static_cast<std::uint32_t>(hits.size());
            auto byA = [](const PairReport& hit, std::uint32_t a) { return hit.a < a; };
            const auto asA = static_cast<std::uint32_t>(
                std::lower_bound(hits.begin(), hits.end(), first, byA) - hits.begin());
            const auto asAEnd = static_cast<std::uint32_t>(
                std::lower_bound(hits.begin() + asA, hits.end(), last, byA) - hits.begin());
            std::fill(begins.begin() + first, begins.begin() + last, 0u);
            for (std::uint32_t e = from; e < to; ++e) ++begins[entries_[e].object];
            for (std::uint32_t k = asA; k < asAEnd; ++k) ++begins[hits[k].a];
            // Before the range: the B entries of the ranges before it, and an A entry per hit before.
            std::uint32_t start = from + asA;
            for (std::uint32_t i = first; i < last; ++i) {
                std::uint32_t count = begins[i];
                begins[i] = start;
                start += count;
            }
            for (std::uint32_t e = from; e < to; ++e) ids[begins[entries_[e].object]++] = entries_[e].partner;
            for (std::uint32_t k = asA; k < asAEnd; ++k) {
                if (k + 16 < asAEnd) __builtin_prefetch(&objects[hits[k + 16].b].id);
                ids[begins[hits[k].a]++] = objects[hits[k].b].id;
            }
            // Placing moved each start to the next run's: back by one run.
            for (std::uint32_t i = last - 1; i > first; --i) begins[i] = begins[i - 1];
            begins[first] = from + asA;
        }
        if (!responds) return;
        std::array<std::uint32_t, kMaxBlocks> next;
        for (std::uint32_t u = 0; u < buckets; ++u) next[u] = hitAt_[std::size_t(u) * blocks + b];
        for (std::size_t k = hitBlocks.begin(b); k < hitBlocks.end(b); ++k)
            order_[next[bucketOf_[k]]++] = static_cast<std::uint32_t>(k);
    });
    begins[n] = static_cast<std::uint32_t>(ids.size());
    if (!responds) return;
    // 4. Buckets: the responses, contacts first, then the walls, each in pair order; and the
    // bucket's groups undone, ready for the next run (the groups are no longer read).
    forEachBlock(&tasks, buckets, [&](std::uint32_t u) {
        const std::uint32_t first = bucketBegin_[u], last = bucketBegin_[u + 1];
        bool walls = false;
        for (std::uint32_t j = first; j < last; ++j) {
            if (j + kHitsAhead < last) prefetchLines(&hits[order_[j + kHitsAhead]], sizeof(PairReport));
            if (j + kObjectsAhead < last) {
                const PairReport& ahead = hits[order_[j + kObjectsAhead]];
                prefetchLines(&objects[ahead.a], sizeof(GameObject));
                prefetchLines(&objects[ahead.b], sizeof(GameObject));
            }
            const PairReport& hit = hits[order_[j]];
            if (hit.test.kind == ContactKind::Contact)
                responder->respond(responder->context, hit);
            else
                walls = true;
            groups_.ungroup(hit.a);
            groups_.ungroup(hit.b);
        }
        if (!walls) return;
        for (std::uint32_t j = first; j < last; ++j) {
            const PairReport& hit = hits[order_[j]];
            if (hit.test.kind == ContactKind::Container) responder->respond(responder->context, hit);
        }
    });
}

std::size_t SharedResponse::bytes() const {
    return groups_.bytes() + entries_.capacity() * sizeof(Entry) + bucketOf_.capacity() +
           (entryAt_.capacity() + order_.capacity() + hitAt_.capacity() + bucketBegin_.capacity()) *
               sizeof(std::uint32_t);
}

}  // namespace polar
