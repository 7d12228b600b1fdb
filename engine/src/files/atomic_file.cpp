#include "polar/atomic_file.h"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#if defined(__unix__) || defined(__APPLE__)
#include <fcntl.h>
#include <signal.h>
#include <unistd.h>
#define POLAR_HAVE_FSYNC 1
#endif

namespace polar {
namespace {

bool injected(const AtomicWriteFault& fault, AtomicWriteStep step) {
    return fault && fault(step);
}

Error writeError(const std::string& path, const std::string& what) {
    return Error{path, 0, 0, what, "a writable folder with free space"};
}

long currentProcess() {
#ifdef POLAR_HAVE_FSYNC
    return static_cast<long>(::getpid());
#else
    return 0;
#endif
}

// The process id in a temporary file's name "NAME.PID-N.tmp" made for the file "NAME", or -1.
long writerOf(const std::string& candidate, const std::string& name) {
    constexpr std::string_view suffix = ".tmp";
    if (candidate.size() <= name.size() + 1 + suffix.size() || candidate.compare(0, name.size(), name) != 0 ||
        candidate[name.size()] != '.' ||
        candidate.compare(candidate.size() - suffix.size(), suffix.size(), suffix) != 0)
        return -1;
    std::string middle =
        candidate.substr(name.size() + 1, candidate.size() - name.size() - 1 - suffix.size());
    std::size_t dash = middle.find('-');
    if (dash == 0 || dash == std::string::npos || dash + 1 == middle.size() ||
        middle.find_first_not_of("0123456789-") != std::string::npos ||
        middle.find('-', dash + 1) != std::string::npos)
        return -1;
    try {
        return std::stol(middle.substr(0, dash));
    } catch (...) {
        return -1;
    }
}

// Removes the temporary files of earlier writes of `path` whose process has gone (killed in the
// middle of a write): they can never be renamed into place. A live writer's file is left alone.
void removeAbandonedTemporaries([[maybe_unused]] const std::filesystem::path& path) {
#ifdef POLAR_HAVE_FSYNC
    namespace fs = std::filesystem;
    const std::string name = path.filename().string();
    const fs::path folder = path.parent_path().empty() ? fs::path(".") : path.parent_path();
    std::error_code ec;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        long pid = writerOf(it->path().filename().string(), name);
        if (pid <= 0 || pid == currentProcess()) continue;
        if (::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) {
            std::error_code ignored;
            fs::remove(it->path(), ignored);
        }
    }
#endif
}

// Creates a temporary file beside `path` that no other writer uses, "NAME.PID-N.tmp".
std::FILE* createTemporary(const std::string& path, std::string& temp) {
    static std::atomic<unsigned long> counter{0};
    temp = path + "." + std::to_string(currentProcess()) + "-" + std::to_string(counter++) + ".tmp";
#ifdef POLAR_HAVE_FSYNC
    int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) return nullptr;
    std::FILE* out = ::fdopen(fd, "wb");
    if (!out) ::close(fd);
    return out;
#else
    return std::fopen(temp.c_str(), "wb");
#endif
}

}  // namespace

std::optional<Error> writeFileAtomically(const std::string& path, std::string_view contents,
                                         const AtomicWriteFault& fault) {
    namespace fs = std::filesystem;
    const char* simulated = "no space left on device (simulated)";
    removeAbandonedTemporaries(fs::path(path));

    std::string temp = path + ".tmp";
    bool openFault = injected(fault, AtomicWriteStep::kOpen);
    std::FILE* out = openFault ? nullptr : createTemporary(path, temp);
    if (!out)
        return writeError(path, "cannot create the temporary file " + temp + ": " +
                                    (openFault ? simulated : std::strerror(errno)));
    auto abandon = [&](const std::string& what) {
        std::fclose(out);
        std::remove(temp.c_str());
        return writeError(path, what);
    };

    if (injected(fault, AtomicWriteStep::kWrite)) {
        std::fwrite(contents.data(), 1, contents.size() / 2, out);
        return abandon(std::string("cannot write the file: ") + simulated);
    }
    if (std::fwrite(contents.data(), 1, contents.size(), out) != contents.size() || std::fflush(out) != 0)
        return abandon(std::string("cannot write the file: ") + std::strerror(errno));

    if (injected(fault, AtomicWriteStep::kSync))
        return abandon(std::string("cannot flush the file to the disk: ") + simulated);
#ifdef POLAR_HAVE_FSYNC
    if (::fsync(::fileno(out)) != 0)
        return abandon(std::string("cannot flush the file to the disk: ") + std::strerror(errno));
#endif
    if (std::fclose(out) != 0) {
        std::remove(temp.c_str());
        return writeError(path, std::string("cannot close the file: ") + std::strerror(errno));
    }

    std::error_code ec;
    fs::perms perms = fs::status(path, ec).permissions();
    if (!ec && perms != fs::perms::unknown) fs::permissions(temp, perms, ec);

    if (injected(fault, AtomicWriteStep::kRename)) {
        std::remove(temp.c_str());
        return writeError(path, std::string("cannot replace the file: ") + simulated);
    }
    fs::rename(temp, path, ec);
    if (ec) {
        std::remove(temp.c_str());
        return writeError(path, "cannot replace the file: " + ec.message());
    }
    syncFolder(fs::path(path).parent_path());
    return std::nullopt;
}

void syncFolder([[maybe_unused]] const std::filesystem::path& folder) {
#ifdef POLAR_HAVE_FSYNC
    int fd = ::open(folder.empty() ? "." : folder.c_str(), O_RDONLY);
    if (fd >= 0) {
        ::fsync(fd);
        ::close(fd);
    }
#endif
}

}  // namespace polar
