#pragma once
// One HTTP request through libcurl, for polarcade-boards.
#include <string>

namespace polar::boards {

struct HttpReply {
    long status = 0;  // 0 when no answer came
    std::string body;
    std::string error;  // why no answer came (libcurl's words)
};

// GET (an empty `body` and `contentType`) or POST `body` to `url`, waiting at most `timeoutSeconds`.
HttpReply httpRequest(const std::string& url, const std::string& body = "",
                      const std::string& contentType = "", long timeoutSeconds = 60, bool post = false);

// `text` with every byte outside A-Z a-z 0-9 -._~ written as %XX, for a query value.
std::string urlEncode(const std::string& text);

}  // namespace polar::boards
