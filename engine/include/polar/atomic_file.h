#pragma once
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "polar/error.h"

namespace polar {

// The steps of an atomic write, in order; a test can make any of them fail.
enum class AtomicWriteStep { kOpen, kWrite, kSync, kRename };

// A test hook: returns true to make that step fail as a full disk would (a failed kWrite first
// writes half of the contents, so the temporary file is really torn).
using AtomicWriteFault = std::function<bool(AtomicWriteStep)>;

// Writes `contents` to `path` so that readers see the old file or the new one, never a torn one.
//
// Why not just overwrite? A crash, a full disk or a killed process in the middle of a plain write
// leaves half a file, and the player's high scores or the modder's bounds are gone. Here the text
// goes to a temporary file "NAME.PID-N.tmp" in the same folder (its own per write, so two writers
// never tear each other's), is flushed to the disk, and only then renamed over `path` (rename within
// one file system is atomic on POSIX). On any failure the temporary file is removed and `path` is
// untouched; one left by a killed process is removed by the next write of `path`. An existing
// file's permissions are kept.
std::optional<Error> writeFileAtomically(const std::string& path, std::string_view contents,
                                         const AtomicWriteFault& fault = {});

// Flushes a folder's entries (a rename into it) to the disk, best effort: after a crash the renamed
// file is there, not only its data. An empty path is the current folder.
void syncFolder(const std::filesystem::path& folder);

}  // namespace polar
