#include "polar/atomic_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#if defined(__unix__) || defined(__APPLE__)
#include <fcntl.h>
#include <unistd.h>
#define POLAR_HAVE_FSYNC 1
#endif

namespace polar {
namespace {

bool injected(const AtomicWriteFault& fault, AtomicWriteStep step) { return fault && fault(step); }

Error writeError(const std::string& path, const std::string& what) {
    return Error{path, 0, 0, what, "a writable folder with free space"};
}

// Flushes the folder entry of a rename to the disk, best effort.
void syncFolder([[maybe_unused]] const std::filesystem::path& folder) {
#ifdef POLAR_HAVE_FSYNC
    int fd = ::open(folder.empty() ? "." : folder.c_str(), O_RDONLY);
    if (fd >= 0) {
        ::fsync(fd);
        ::close(fd);
    }
#endif
}

}  // namespace

std::optional<Error> writeFileAtomically(const std::string& path, std::string_view contents,
                                         const AtomicWriteFault& fault) {
    namespace fs = std::filesystem;
    const std::string temp = path + ".tmp";
    const char* simulated = "no space left on device (simulated)";

    bool openFault = injected(fault, AtomicWriteStep::kOpen);
    std::FILE* out = openFault ? nullptr : std::fopen(temp.c_str(), "wb");
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

}  // namespace polar
