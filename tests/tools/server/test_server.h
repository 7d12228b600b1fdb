#pragma once
// A polarcade-server in the test's own process: SQLite in a fresh folder, the verifier pool, the
// HTTP routes on a free loopback port, and a clock the test moves by hand. Stopped when it goes
// out of scope.
#include <httplib.h>

#include <atomic>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

#include "routes.h"
#include "service.h"
#include "signature.h"
#include "sqlite_storage.h"
#include "verify_pool.h"

namespace polar::testing {

class TestServer {
  public:
    explicit TestServer(const std::filesystem::path& folder, server::Limits limits = {},
                        double cpuSeconds = 5.0) {
        std::string error;
        storage_ = server::openSqliteStorage((folder / "runs.sqlite").string(), error);
        EXPECT_TRUE(storage_) << error;
        server::ServerGames games = server::serverGames(POLAR_ASSET_DIR);
        games.cpuSeconds = cpuSeconds;
        pool_ = std::make_unique<server::VerifyPool>(games, 2, limits.verifyQueue);
        service_ =
            std::make_unique<server::Service>(*storage_, *pool_, limits, [this] { return now.load(); });
        http_ = std::make_unique<server::HttpServer>(*service_, limits);
        port = http_->bind("127.0.0.1", 0);
        EXPECT_GT(port, 0);
        thread_ = std::thread([this] { http_->serve(); });
    }
    ~TestServer() {
        http_->stop();
        thread_.join();
    }

    httplib::Client client() const {
        httplib::Client c("127.0.0.1", port);
        c.set_read_timeout(60, 0);
        return c;
    }
    server::Storage& storage() { return *storage_; }

    int port = -1;
    std::atomic<std::int64_t> now{1'767'225'600'000};  // 2026-01-01T00:00:00Z, a Thursday

  private:
    std::unique_ptr<server::Storage> storage_;
    std::unique_ptr<server::VerifyPool> pool_;
    std::unique_ptr<server::Service> service_;
    std::unique_ptr<server::HttpServer> http_;
    std::thread thread_;
};

// A submission body for `replay`, signed by `key` (a secret key) as `name` with `token`.
inline nlohmann::json signedBody(const std::string& name, const std::string& replay,
                                 const server::KeyPair& key, const std::string& token = "") {
    nlohmann::json body{
        {"name", name},
        {"public_key", server::toHex(key.publicKey)},
        {"signature", server::toHex(server::sign(
                          key.secretKey, server::signedMessage(name, server::sha256Hex(replay), token)))},
        {"replay", replay}};
    if (!token.empty()) body["token"] = token;
    return body;
}

}  // namespace polar::testing
