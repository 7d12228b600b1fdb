#pragma once
#include <optional>
#include <string_view>

namespace polar {

// How a World finds the pairs worth giving to the narrow phase. Every method reports exactly the
// same hits in the same order with the same responses; they differ only in speed.
//   AllPairs:     every pair A < B in creation order: the reference the others must match, O(n²).
//   Grid:         a uniform grid hashed by cell, rebuilt each step; objects far larger than a cell
//                 and containers are paired by a linear pass instead. The default (see README).
//   SortAndSweep: boxes sorted along x (insertion sort, coherent from step to step), swept for
//                 overlap; measured against the grid.
enum class BroadPhase { AllPairs, Grid, SortAndSweep };

inline constexpr BroadPhase kAllBroadPhases[] = {BroadPhase::AllPairs, BroadPhase::Grid,
                                                 BroadPhase::SortAndSweep};

// The scene-file name: "all-pairs", "grid", "sort-and-sweep".
const char* broadPhaseName(BroadPhase method);
std::optional<BroadPhase> broadPhaseFromName(std::string_view name);

}  // namespace polar
