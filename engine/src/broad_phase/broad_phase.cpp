#include "polar/broad_phase.h"

namespace polar {

const char* broadPhaseName(BroadPhase method) {
    switch (method) {
        case BroadPhase::AllPairs:
            return "all-pairs";
        case BroadPhase::Grid:
            return "grid";
        case BroadPhase::SortAndSweep:
            return "sort-and-sweep";
    }
    return "?";
}

std::optional<BroadPhase> broadPhaseFromName(std::string_view name) {
    for (BroadPhase method : kAllBroadPhases)
        if (name == broadPhaseName(method)) return method;
    return std::nullopt;
}

}  // namespace polar
