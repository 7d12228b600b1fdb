#include "routes.h"

#include <httplib.h>

#include <charconv>

namespace polar::server {
namespace {

using Handler = std::function<Answer(const httplib::Request&, Service&)>;
constexpr const char* kJson = "application/json";

// A request value that cannot be used: answered 400 with its message.
struct BadRequest {
    std::string message;
};

std::string text(const httplib::Request& req, const char* name, const std::string& fallback) {
    return req.has_param(name) ? req.get_param_value(name) : fallback;
}

std::int64_t number(const httplib::Request& req, const char* name, std::int64_t fallback, std::int64_t lowest,
                    std::int64_t highest) {
    if (!req.has_param(name)) return fallback;
    const std::string value = req.get_param_value(name);
    std::int64_t n = 0;
    auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), n);
    if (ec != std::errc() || end != value.data() + value.size() || n < lowest || n > highest)
        throw BadRequest{std::string("query parameter ") + name + "=" + value +
                         ": expected a whole number from " + std::to_string(lowest) + " to " +
                         std::to_string(highest)};
    return n;
}

// The board a query names: scene, mode, ranked, from and count, with the server's defaults.
BoardQuery boardQuery(const httplib::Request& req) {
    BoardQuery q;
    q.scene = text(req, "scene", "scenes/cave.json");
    q.mode = text(req, "mode", defaultMode());
    const std::string ranked = text(req, "ranked", "true");
    if (ranked != "true" && ranked != "false")
        throw BadRequest{"query parameter ranked=" + ranked + ": expected true or false"};
    q.ranked = ranked == "true";
    q.from = number(req, "from", 1, 1, std::int64_t{1} << 40);
    q.count = static_cast<int>(number(req, "count", 20, 1, 100));
    return q;
}

Season season(const httplib::Request& req) {
    const std::string word = text(req, "season", "all");
    if (word == "all") return Season::kAllTime;
    if (word == "week") return Season::kWeek;
    if (word == "today") return Season::kToday;
    throw BadRequest{"query parameter season=" + word + ": expected all, week or today"};
}

std::string requiredName(const httplib::Request& req) {
    if (!req.has_param("name") || req.get_param_value("name").empty())
        throw BadRequest{"query parameter name is missing; expected a player's name"};
    return req.get_param_value("name");
}

std::int64_t runId(const httplib::Request& req) {
    std::int64_t id = 0;
    const std::string& digits = req.matches[1].str();
    auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), id);
    if (ec != std::errc() || end != digits.data() + digits.size())
        throw BadRequest{"run id " + digits + ": expected a run's number"};
    return id;
}

struct Route {
    RouteName name;
    const char* pattern;  // httplib's regular expression for the path
    Handler handler;
};

// The one table: the routes registered, and the names the OpenAPI test compares.
const std::vector<Route>& routeTable() {
    static const std::vector<Route> table = {
        {{"GET", "/v1/server"}, "/v1/server", [](const auto&, Service& s) { return s.server(); }},
        {{"POST", "/v1/tokens"}, "/v1/tokens", [](const auto&, Service& s) { return s.issueToken(); }},
        {{"POST", "/v1/runs"},
         "/v1/runs",
         [](const httplib::Request& req, Service& s) {
             Result<Submission> submission = parseSubmission(req.body);
             if (!submission) throw BadRequest{submission.error().message()};
             return s.submit(*submission, req.remote_addr);
         }},
        {{"GET", "/v1/runs/{id}"},
         R"(/v1/runs/(\d{1,18}))",
         [](const httplib::Request& req, Service& s) { return s.run(runId(req)); }},
        {{"GET", "/v1/runs/{id}/replay"}, R"(/v1/runs/(\d{1,18})/replay)", nullptr},  // text, see below
        {{"GET", "/v1/boards/top"},
         "/v1/boards/top",
         [](const httplib::Request& req, Service& s) { return s.top(boardQuery(req), season(req)); }},
        {{"GET", "/v1/boards/around"},
         "/v1/boards/around",
         [](const httplib::Request& req, Service& s) {
             return s.around(boardQuery(req), season(req), requiredName(req));
         }},
        {{"GET", "/v1/players/best"},
         "/v1/players/best",
         [](const httplib::Request& req, Service& s) { return s.playerBest(requiredName(req)); }},
    };
    return table;
}

void answer(httplib::Response& res, const Answer& a) {
    res.status = a.status;
    if (a.retryAfterSeconds > 0) res.set_header("Retry-After", std::to_string(a.retryAfterSeconds));
    res.set_content(a.body, kJson);
}

// Runs a handler, turning a bad value into 400 and a failing database into 500.
void guarded(const httplib::Request& req, httplib::Response& res, const std::function<void()>& work) {
    try {
        work();
    } catch (const BadRequest& bad) {
        answer(res, errorAnswer(400, "bad-request", bad.message));
    } catch (const StorageError& e) {
        answer(res, errorAnswer(500, "storage", e.what()));
    }
    (void)req;
}

// The words of statuses httplib answers by itself (an unreadable request, a body too large).
const char* statusWord(int status) {
    switch (status) {
        case 400:
            return "bad-request";
        case 404:
            return "not-found";
        case 405:
            return "method-not-allowed";
        case 413:
            return "too-large";
        case 414:
            return "uri-too-long";
        default:
            return "http-error";
    }
}

}  // namespace

std::span<const RouteName> routeNames() {
    static const std::vector<RouteName> names = [] {
        std::vector<RouteName> v;
        for (const Route& r : routeTable()) v.push_back(r.name);
        return v;
    }();
    return names;
}

struct HttpServer::Impl {
    httplib::Server http;
};

HttpServer::HttpServer(Service& service, const Limits& limits) : impl_(std::make_unique<Impl>()) {
    httplib::Server& http = impl_->http;
    http.set_payload_max_length(limits.maxBodyBytes);
    // A client that sends nothing for this long is dropped: a trickle cannot hold a thread for long.
    http.set_read_timeout(5, 0);
    http.set_write_timeout(5, 0);
    http.set_keep_alive_timeout(5);
    http.set_default_headers({{"X-Content-Type-Options", "nosniff"}, {"Cache-Control", "no-store"}});
    for (const Route& route : routeTable()) {
        httplib::Server::Handler handler;
        if (route.handler) {
            handler = [&service, work = route.handler](const httplib::Request& req, httplib::Response& res) {
                guarded(req, res, [&] { answer(res, work(req, service)); });
            };
        } else {
            handler = [&service](const httplib::Request& req, httplib::Response& res) {
                guarded(req, res, [&] {
                    std::optional<std::string> bytes = service.replay(runId(req));
                    if (!bytes)
                        return answer(res, errorAnswer(404, "no-run", "no run " + req.matches[1].str()));
                    res.set_content(*bytes, "text/plain; charset=utf-8");
                });
            };
        }
        if (std::string_view(route.name.method) == "GET")
            http.Get(route.pattern, handler);
        else
            http.Post(route.pattern, handler);
    }
    // A body declared larger than the limit is answered before a byte of it is read (httplib alone
    // would read it through to throw it away), and the connection is closed.
    http.set_pre_routing_handler([max = limits.maxBodyBytes](const httplib::Request& req,
                                                             httplib::Response& res) {
        const std::string length = req.get_header_value("Content-Length");
        std::uint64_t declared = 0;
        auto [end, ec] = std::from_chars(length.data(), length.data() + length.size(), declared);
        if (length.empty() || ec != std::errc() || end != length.data() + length.size() || declared <= max)
            return httplib::Server::HandlerResponse::Unhandled;
        answer(res, errorAnswer(413, "too-large",
                                "the body is " + length + " bytes; this server takes at most " +
                                    std::to_string(max)));
        res.set_header("Connection", "close");
        return httplib::Server::HandlerResponse::Handled;
    });
    http.set_error_handler([](const httplib::Request& req, httplib::Response& res) {
        if (!res.body.empty()) return;
        std::string message =
            res.status == 404   ? "no route " + req.method + " " + req.path + "; see openapi.json"
            : res.status == 413 ? "the body is larger than the server takes"
                                : "the request could not be read as HTTP/1.1; expected a request line, "
                                  "headers and a body of its Content-Length (0 for an empty POST)";
        answer(res, errorAnswer(res.status, statusWord(res.status), message));
    });
    http.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr) {
        answer(res, errorAnswer(500, "internal", "the server failed answering this request"));
    });
}

HttpServer::~HttpServer() = default;

int HttpServer::bind(const std::string& address, int port) {
    if (port == 0) return impl_->http.bind_to_any_port(address);
    return impl_->http.bind_to_port(address, port) ? port : -1;
}

void HttpServer::serve() {
    impl_->http.listen_after_bind();
}

void HttpServer::stop() {
    impl_->http.stop();
}

}  // namespace polar::server
