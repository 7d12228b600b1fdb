// polarcade-server: world high-score boards that rank only runs the server played again itself.
#include <signal.h>

#include <cstdio>
#include <thread>

#include "cli.h"
#include "files/assets.h"
#include "routes.h"
#include "storage.h"
#include "verify_pool.h"

namespace {

struct Flags {
    std::string address = "127.0.0.1";
    int port = 7460;
    std::string db = "sqlite:polarcade-server.sqlite";
    polar::server::Limits limits;
    std::uint64_t maxTicks = 216'000;
    double verifyCpuSeconds = 5.0;
};

void addFlags(polar::cli::Command& app, Flags& f) {
    app.option("--address", f.address,
               "The address to listen on (127.0.0.1: this machine only; 0.0.0.0: every interface)")
        .showDefault();
    app.option("--port", f.port, "The port to listen on (0: any free port, printed at start)", {0, 65535})
        .showDefault();
    app.option("--db", f.db, "Where runs are kept: sqlite:PATH (one file, created and migrated at start)")
        .typeName("sqlite:PATH")
        .showDefault();
    app.option("--verifiers", f.limits.verifyWorkers, "Threads that verify runs", {1, 256}).showDefault();
    app.option("--queue", f.limits.verifyQueue,
               "Runs waiting for a verifier; a submission beyond it is answered 503 with Retry-After",
               {1, 100000})
        .showDefault();
    app.option("--max-body", f.limits.maxBodyBytes,
               "The largest request body in bytes; larger is answered 413", {1024, std::size_t{1} << 30})
        .showDefault();
    app.option("--runs-per-key", f.limits.runsPerKeyPerMinute,
               "Submissions a minute from one key; more are answered 429", {1, 100000})
        .showDefault();
    app.option("--runs-per-address", f.limits.runsPerAddressPerMinute,
               "Submissions a minute from one address; more are answered 429", {1, 100000})
        .showDefault();
    app.option("--max-ticks", f.maxTicks, "The longest run verified, in ticks (60 a second)", {1, 10'000'000})
        .showDefault();
    app.option("--verify-cpu", f.verifyCpuSeconds,
               "CPU seconds one run may take to verify; a slower one is refused", {0.01, 3600.0})
        .showDefault();
    app.option(
           "--token-tolerance", f.limits.tokenTolerance,
           "A ranked run's ticks at 60 a second, times this, must fit in the time since its token was issued",
           {0.0, 1.0})
        .showDefault();
}

}  // namespace

int main(int argc, char** argv) {
    polar::cli::Command app{
        "Keeps Polarcade's world high-score boards over HTTP (a JSON API, tools/server/openapi.json). Every "
        "submitted replay is played again with the game's own rules before it is stored: the score, wave and "
        "length a board shows are the server's. Runs are signed with the player's Ed25519 key; a name "
        "belongs to "
        "the first key that uses it. Stops on SIGINT or SIGTERM. Exit code 0 after a stop; 2: bad arguments, "
        "a "
        "database that cannot be opened or an address that cannot be bound.",
        "polarcade-server"};
    Flags flags;
    addFlags(app, flags);
    if (int code = app.parse(argc, argv); code >= 0) return code;

    polar::Result<std::string> root = polar::game::AssetFs::findRoot();
    if (!root) {
        std::fprintf(stderr, "polarcade-server: %s\n", root.error().message().c_str());
        return polar::cli::kBadInput;
    }
    std::string error;
    std::unique_ptr<polar::server::Storage> storage = polar::server::openStorage(flags.db, error);
    if (!storage) {
        std::fprintf(stderr, "polarcade-server: %s\n", error.c_str());
        return polar::cli::kBadInput;
    }
    polar::server::ServerGames games = polar::server::serverGames(*root);
    games.maxTicks = flags.maxTicks;
    games.cpuSeconds = flags.verifyCpuSeconds;
    const std::size_t scenes = games.scenes.size();

    // SIGINT and SIGTERM are waited for on a thread of their own, blocked everywhere else (the
    // mask is inherited by every thread started after this).
    sigset_t stopSignals;
    sigemptyset(&stopSignals);
    sigaddset(&stopSignals, SIGINT);
    sigaddset(&stopSignals, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &stopSignals, nullptr);

    polar::server::VerifyPool pool(std::move(games), flags.limits.verifyWorkers, flags.limits.verifyQueue);
    polar::server::Service service(*storage, pool, flags.limits);
    polar::server::HttpServer http(service, flags.limits);
    const int port = http.bind(flags.address, flags.port);
    if (port < 0) {
        std::fprintf(stderr,
                     "polarcade-server: cannot listen on %s:%d; expected a free port on a local address\n",
                     flags.address.c_str(), flags.port);
        return polar::cli::kBadInput;
    }
    std::printf("polarcade-server: listening on http://%s:%d (%s, schema %d, %zu scenes)\n",
                flags.address.c_str(), port, flags.db.c_str(), storage->schemaVersion(), scenes);
    std::fflush(stdout);
    std::thread waiter([&] {
        int signal = 0;
        sigwait(&stopSignals, &signal);
        http.stop();
    });
    http.serve();
    // serve() also returns when the listening socket fails; wake the waiter so it can be joined.
    pthread_kill(waiter.native_handle(), SIGTERM);
    waiter.join();
    std::printf("polarcade-server: stopped\n");
    return 0;
}
