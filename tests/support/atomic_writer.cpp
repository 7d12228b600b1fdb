// polar-atomic-writer: rewrites one file again and again through the game's own atomic writes, for
// the test that kills it with SIGKILL at random moments (tests/game/atomic_kill_test.cpp).
//   polar-atomic-writer bytes FILE SIZE [COUNT]  alternates atomicContents(0 or 1, SIZE); the first
//                                                write is the version FILE does not hold
//   polar-atomic-writer scores FILE [COUNT]      loads the high-score table FILE as the game does,
//                                                adds a new best score and saves it (HighScores::save)
// COUNT writes (0 or none: until killed). Exit code 2 on a bad command line or a failed write.
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>

#include "atomic_contents.h"
#include "files/high_scores.h"
#include "polar/atomic_file.h"
#include "polar/error.h"

int main(int argc, char** argv) {
    const std::string mode = argc > 1 ? argv[1] : "";
    const bool bytes = mode == "bytes" && (argc == 4 || argc == 5);
    const bool scores = mode == "scores" && (argc == 3 || argc == 4);
    if (!bytes && !scores) {
        std::fprintf(stderr, "usage: polar-atomic-writer bytes FILE SIZE [COUNT] | scores FILE [COUNT]\n");
        return 2;
    }
    const std::string path = argv[2];
    const char* countArg = bytes ? (argc == 5 ? argv[4] : nullptr) : (argc == 4 ? argv[3] : nullptr);
    const long count = countArg ? std::atol(countArg) : 0;

    std::string contents[2];
    int version = 1;
    if (bytes) {
        const std::size_t size = static_cast<std::size_t>(std::atol(argv[3]));
        contents[0] = polar::testing::atomicContents(0, size);
        contents[1] = polar::testing::atomicContents(1, size);
        std::optional<polar::SourceFile> old = polar::diskReader()(path);
        version = old && old->text == contents[1] ? 0 : 1;
    }
    for (long n = 0; count == 0 || n < count; ++n, version ^= 1) {
        std::optional<polar::Error> error;
        if (bytes) {
            error = polar::writeFileAtomically(path, contents[version]);
        } else {
            std::optional<polar::Error> problem;
            polar::game::HighScores table = polar::game::HighScores::load(path, &problem);
            if (problem) {
                std::fprintf(stderr, "%s\n", problem->message().c_str());
                return 2;
            }
            int best = table.entries().empty() ? 0 : table.entries().front().score;
            table.insert({"AAA", best + 1, static_cast<int>(n % 9) + 1});
            error = table.save();
        }
        if (error) {
            std::fprintf(stderr, "%s\n", error->message().c_str());
            return 2;
        }
    }
    return 0;
}
