#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "polar/collision.h"
#include "polar/game_object.h"
#include "polar/tasks.h"
#include "world/contact_groups.h"

namespace polar {

// The end of a step's collisions on several workers, with the bits of one thread: the lists of what
// each object touched (World::collidedWith), and, when the response runs, every hit's response.
//
// Why the same bits? A response reads and writes its two objects only, so what decides an object's
// bits is the order of the hits on it. The hits are joined into contact groups (contact_groups.h),
// and each group goes whole to one bucket of hits, in pair order; a bucket runs on one thread,
// contacts first, then the container walls, as World's one-thread pass does. Every object meets its
// hits in the same order. The lists: each hit's two entries (object, partner) are dealt, in pair
// order, to the range of objects their object lies in; each range is then counted and placed by
// one thread, as the one-thread counting sort places it. No atomic counter decides a position.
//
// Why buckets of groups, not graph colours (Box2D's way)? Colours run a hit after hits of lower
// colours, not after the hits before it in pair order, which would change the bits. Groups keep the
// order. A bucket is a hash of its group's root, so the many small groups of a field spread evenly;
// a single group as large as the scene runs on one thread, as it would have anyway.
//
// The passes share one split of the objects and of the hits into blocks (BlockSplit), and block b
// of one pass's domain is item b of the next pass's, so every pass is one task over every worker:
// four tasks for the lists, five with the responses.
class SharedResponse {
  public:
    // What a response is: respond(context, hit) moves the hit's two objects and nothing else.
    struct Responder {
        void (*respond)(void* context, const PairReport& hit) = nullptr;
        void* context = nullptr;
    };

    // Fills `begins` (objects.size() + 1 run starts) and `ids` (2 · hits.size() partner ids) as
    // World's one-thread lists, and with a responder responds to every hit, on `tasks`. The hits are
    // in pair order, with a, b < objects.size(). Room is taken on the calling thread.
    void run(TaskSystem& tasks, std::span<const PairReport> hits, std::span<const GameObject> objects,
             std::vector<std::uint32_t>& begins, std::vector<ObjectId>& ids, const Responder* responder);

    std::size_t bytes() const;

  private:
    // A hit's entry in its object's list, on the way to the range of objects that object lies in.
    struct Entry {
        std::uint32_t object = 0;
        ObjectId partner = 0;
    };

    ContactGroups groups_;
    std::vector<Entry> entries_;              // by range of objects, pair order within
    std::vector<std::uint32_t> entryAt_;      // per range and block of hits: entries, then where they go
    std::vector<std::uint8_t> bucketOf_;      // per hit: its group's bucket
    std::vector<std::uint32_t> order_;        // hit indices bucket by bucket, pair order within
    std::vector<std::uint32_t> hitAt_;        // per bucket and block of hits: hits, then where they go
    std::vector<std::uint32_t> bucketBegin_;  // bucket u's hits are order_[bucketBegin_[u], [u + 1])
};

}  // namespace polar
