#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace polar {

// How closely the narrow phase follows the outlines, from cheapest to truest. A scene picks one with
// "accuracy" (scene_file.h); WorldDef::accuracy sets it in code.
//   bounds:    the default: each Bound by its file's interpolate flag (nearest or chord),
//              closest pair of radii only: the collision rule |u|² ≤ (rA + rB)² as stated.
//   circle:    one bounding circle per Bound (max radius × the largest stretch of L); a
//              container's wall is its inscribed circle (min radius × the smallest stretch), so the
//              level errs toward a hit in both kinds of pair.
//   nearest:   the rule with every Bound read without interpolation.
//   chord:     the rule with straight-edge interpolation (nearest where chord is undefined: fewer
//              than 3 samples or a gap of 180° or more).
//   all-radii: the rule (each bound by its flag) on every pair of radii, not only the closest one.
//              Contact: any pair hits. Container: a held radii leaves when it reaches the wall of
//              every container radii (the container's radii are rooms; it must be inside one).
//   exact:     the true overlap of the outlines (each bound by its flag: star polygons or stars of
//              circular arcs, mapped into the world). Contact: the two regions share a point
//              (touching counts). Container: the held outline is not wholly inside the container's
//              (touching the wall counts), with several radii read as in all-radii.
enum class Accuracy : std::uint8_t { Bounds, Circle, Nearest, Chord, AllRadii, Exact };

inline constexpr Accuracy kAllAccuracies[] = {Accuracy::Bounds, Accuracy::Circle,   Accuracy::Nearest,
                                              Accuracy::Chord,  Accuracy::AllRadii, Accuracy::Exact};

// "bounds", "circle", "nearest", "chord", "all-radii", "exact".
const char* accuracyName(Accuracy accuracy);
std::optional<Accuracy> accuracyFromName(std::string_view name);
// Every name in quotes, comma-separated, for error messages.
std::string accuracyNameList();

}  // namespace polar
