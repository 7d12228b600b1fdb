#include "replay/replay_writer.h"

#include <cassert>
#include <cerrno>
#include <cstring>
#include <filesystem>

#include "polar/atomic_file.h"
#include "replay/replay_text.h"
#include "replay/replay_verify.h"

#if defined(__unix__) || defined(__APPLE__)
#include <fcntl.h>
#include <unistd.h>
#define POLAR_HAVE_FSYNC 1
#endif

namespace polar::game {
namespace {

namespace fs = std::filesystem;
using detail::appendCheckpoint;
using detail::appendInputs;
using detail::appendTrace;
using detail::headerText;

constexpr const char* kSimulatedFull = "no space left on device (simulated)";

std::optional<Error> writeFailure(const std::string& path, const std::string& what) {
    return Error{path, 0, 0, what, "a writable folder with free space"};
}

}  // namespace

ReplayWriter::ReplayWriter(std::string path, std::FILE* file, ReplayWriteFault fault)
    : path_(std::move(path)), partPath_(partPathOf(path_)), file_(file), fault_(std::move(fault)) {}

ReplayWriter::~ReplayWriter() {
    if (file_) std::fclose(file_);
}

void ReplayWriter::abandon() {
    if (finished_) return;
    if (file_) std::fclose(file_);
    file_ = nullptr;
    std::remove(partPath_.c_str());
    finished_ = true;
}

Result<std::unique_ptr<ReplayWriter>> ReplayWriter::open(const std::string& path, const ReplayHeader& header,
                                                         ReplayWriteFault fault) {
    const std::string part = partPathOf(path);
    bool injected = fault && fault(ReplayWriteStep::kOpen);
    std::FILE* file = injected ? nullptr : std::fopen(part.c_str(), "wb");
    if (!file)
        return *writeFailure(
            path, "cannot create " + part + ": " + (injected ? kSimulatedFull : std::strerror(errno)));
    std::unique_ptr<ReplayWriter> writer(new ReplayWriter(path, file, std::move(fault)));
    if (auto error = writer->flush(headerText(header))) return *error;
    return writer;
}

std::optional<Error> ReplayWriter::flush(std::string text) {
    if (!file_) return writeFailure(path_, "the recording was already stopped");
    auto stop = [&](const std::string& what) {
        std::fclose(file_);
        file_ = nullptr;
        return writeFailure(path_, what + "; what was recorded before is kept in " + partPath_);
    };
    if (fault_ && fault_(ReplayWriteStep::kFlush)) {
        std::fwrite(text.data(), 1, text.size() / 2, file_);  // a torn write, as a full disk leaves it
        std::fflush(file_);
        return stop(std::string("cannot write the recording: ") + kSimulatedFull);
    }
    if (std::fwrite(text.data(), 1, text.size(), file_) != text.size() || std::fflush(file_) != 0)
        return stop(std::string("cannot write the recording: ") + std::strerror(errno));
    return std::nullopt;
}

std::optional<Error> ReplayWriter::record(Actions actions, const Game& game) {
    if (finished_ || !file_) return std::nullopt;
    actions_.push_back(actions & kAllActions);
    trace_.push_back(traceOf(game.hash()));
    if (game.tickCount() % kCheckpointInterval != 0) return std::nullopt;
    std::string text;
    appendInputs(text, actions_);
    appendTrace(text, trace_);
    appendCheckpoint(text, checkpointOf(game));
    actions_.clear();
    trace_.clear();
    lastCheckpoint_ = game.tickCount();
    return flush(std::move(text));
}

std::optional<Error> ReplayWriter::finish(const Game& game, std::string_view reason) {
    assert(isEndReason(reason) &&
           "a reason the reader refuses makes an unreadable replay: add it to kEndReasons");
    if (finished_) return std::nullopt;
    finished_ = true;
    std::string text;
    if (!actions_.empty()) {
        appendInputs(text, actions_);
        appendTrace(text, trace_);
        appendCheckpoint(text, checkpointOf(game));
    }
    text += "end " + std::to_string(game.tickCount()) + ' ' + std::string(reason) + '\n';
    if (auto error = flush(std::move(text))) return error;
    auto stop = [&](const std::string& what) {
        std::fclose(file_);
        file_ = nullptr;
        return writeFailure(path_, what + "; the recording is kept in " + partPath_);
    };
    if (fault_ && fault_(ReplayWriteStep::kFinish))
        return stop(std::string("cannot finish the file: ") + kSimulatedFull);
#ifdef POLAR_HAVE_FSYNC
    if (::fsync(::fileno(file_)) != 0)
        return stop(std::string("cannot flush the file to the disk: ") + std::strerror(errno));
#endif
    if (std::fclose(file_) != 0) {
        file_ = nullptr;
        return writeFailure(path_, std::string("cannot close the file: ") + std::strerror(errno) +
                                       "; the recording is kept in " + partPath_);
    }
    file_ = nullptr;
    std::error_code ec;
    fs::rename(partPath_, path_, ec);
    if (ec) return writeFailure(path_, "cannot rename " + partPath_ + " into place: " + ec.message());
    syncFolder(fs::path(path_).parent_path());
    return std::nullopt;
}

}  // namespace polar::game
