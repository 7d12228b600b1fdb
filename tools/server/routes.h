#pragma once
// The HTTP face of the server (cpp-httplib): every route, its request read and checked here at the
// edge and handed to one Service function, and every error answered as JSON.
#include <memory>
#include <span>
#include <string>

#include "run_limits.h"
#include "service.h"

namespace polar::server {

// One route as the OpenAPI file names it ("GET", "/v1/runs/{id}").
struct RouteName {
    const char* method;
    const char* path;
};
// Every route the server registers: the table the routes are registered from.
std::span<const RouteName> routeNames();

class HttpServer {
  public:
    HttpServer(Service& service, const Limits& limits);
    ~HttpServer();
    HttpServer(const HttpServer&) = delete;
    HttpServer& operator=(const HttpServer&) = delete;

    // Binds to `address` and `port` (0: any free port); the port bound, or -1 when it cannot.
    int bind(const std::string& address, int port);
    // Answers requests until stop() (from another thread or a signal handler's thread).
    void serve();
    void stop();

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace polar::server
