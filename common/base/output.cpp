#include "base/output.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <random>

#include "base/error.h"
#include "base/paths.h"

// The one platform-specific call of common/: pushing a file's bytes to the disk before the rename.
#if defined(_WIN32)
#include <io.h>
#else
#include <unistd.h>
#endif

namespace pbr {

namespace fs = std::filesystem;

namespace {

bool syncToDisk(std::FILE* file) {
#if defined(_WIN32)
    return _commit(_fileno(file)) == 0;
#else
    return ::fsync(::fileno(file)) == 0;
#endif
}

std::FILE* openForWriting(const fs::path& path) {
#if defined(_WIN32)
    return _wfopen(path.c_str(), L"wb");
#else
    return std::fopen(path.c_str(), "wb");
#endif
}

std::string lastSystemError() {
    return std::strerror(errno);
}

// Writes, flushes and (for a regular file) syncs; throws Error("<shown>: cannot write: ...").
void writeAll(const fs::path& path, std::string_view bytes, const std::string& shown, bool sync) {
    std::FILE* file = openForWriting(path);
    if (!file) throw Error(shown + ": cannot write: " + lastSystemError());
    std::string failure;
    if (std::fwrite(bytes.data(), 1, bytes.size(), file) != bytes.size() ||
        std::fflush(file) != 0 || (sync && !syncToDisk(file))) {
        failure = lastSystemError();
    }
    if (std::fclose(file) != 0 && failure.empty()) failure = lastSystemError();
    if (!failure.empty()) throw Error(shown + ": cannot write: " + failure);
}

// A name beside `path` that no other process or call picks: hidden, with random digits.
fs::path temporaryBeside(const fs::path& path) {
    static std::mt19937_64 generator{std::random_device{}()};
    char digits[17];
    std::snprintf(digits, sizeof digits, "%016llx", static_cast<unsigned long long>(generator()));
    std::string name = ".";
    name.append(path.filename().string()).append(".").append(digits).append(".tmp");
    return path.parent_path() / name;
}

// Where the bytes really go: through a symbolic link to its target, so the link stays a link.
fs::path destinationOf(const fs::path& path) {
    std::error_code ec;
    if (fs::is_symlink(path, ec)) {
        const fs::path target = fs::weakly_canonical(path, ec);
        if (!ec) return target;
    }
    return path;
}

bool isDevice(const fs::path& path) {
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    return !ec && fs::exists(status) && !fs::is_regular_file(status) && !fs::is_directory(status);
}

void requireFolderOf(const fs::path& path, const std::string& shown) {
    const fs::path parent = path.parent_path();
    if (parent.empty()) return;
    std::error_code ec;
    if (!fs::exists(parent, ec)) {
        throw Error(shown + ": no such folder '" + parent.string() + "'");
    }
    if (!fs::is_directory(parent, ec)) {
        throw Error(shown + ": '" + parent.string() + "' is not a folder");
    }
}

}  // namespace

void requireWritableFilePath(const fs::path& path, const std::string& shown) {
    std::error_code ec;
    if (fs::is_directory(path, ec)) throw Error(shown + ": is a directory");
    requireFolderOf(destinationOf(path), shown);
}

void requireOutputFolder(const fs::path& dir, const std::string& shown) {
    std::error_code ec;
    if (!fs::exists(dir, ec)) throw Error(shown + ": no such folder");
    if (!fs::is_directory(dir, ec)) throw Error(shown + ": not a folder");
}

OutputBatch::~OutputBatch() {
    std::error_code ec;
    for (const File& file : files_) {
        if (!file.temporary.empty()) fs::remove(file.temporary, ec);
    }
}

void OutputBatch::add(fs::path path, std::string bytes) {
    files_.push_back({std::move(path), std::move(bytes), {}});
}

std::vector<fs::path> OutputBatch::paths() const {
    std::vector<fs::path> out;
    for (const File& file : files_) out.push_back(file.path);
    return out;
}

void OutputBatch::commit() {
    std::error_code ec;
    auto removeTemporaries = [&] {
        for (File& file : files_) {
            if (!file.temporary.empty()) fs::remove(file.temporary, ec);
            file.temporary.clear();
        }
    };
    try {
        // Every regular file to its temporary first: a full disk or a missing folder stops
        // the batch before any destination changed.
        for (File& file : files_) {
            const std::string shown = displayPath(file.path);
            const fs::path destination = destinationOf(file.path);
            if (fs::is_directory(destination, ec)) throw Error(shown + ": is a directory");
            if (isDevice(destination)) continue;
            requireFolderOf(destination, shown);
            file.temporary = temporaryBeside(destination);
            writeAll(file.temporary, file.bytes, shown, true);
        }
        // Devices and pipes cannot be renamed onto: written directly, after every temporary.
        for (const File& file : files_) {
            const fs::path destination = destinationOf(file.path);
            if (file.temporary.empty() && isDevice(destination)) {
                writeAll(destination, file.bytes, displayPath(file.path), false);
            }
        }
    } catch (...) {
        removeTemporaries();
        throw;
    }
    for (File& file : files_) {
        if (file.temporary.empty()) continue;
        fs::rename(file.temporary, destinationOf(file.path), ec);
        if (ec) {
            const std::string reason = ec.message();
            removeTemporaries();
            throw Error(displayPath(file.path) + ": cannot write: " + reason);
        }
        file.temporary.clear();
    }
}

void writeFileAtomically(const fs::path& path, std::string_view bytes) {
    OutputBatch batch;
    batch.add(path, std::string(bytes));
    batch.commit();
}

void writeFileAtomically(const fs::path& path, const std::function<std::string()>& encode) {
    std::string bytes;
    try {
        bytes = encode();
    } catch (const Error& e) {
        throw Error(displayPath(path) + ": " + e.what());
    }
    writeFileAtomically(path, bytes);
}

}  // namespace pbr
