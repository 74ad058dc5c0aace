#pragma once
// Every file the suite writes is whole or absent (DESIGN.md, "Outputs are whole or absent"): its
// bytes go to a temporary file beside the destination, are flushed and synced, and only then is
// the temporary renamed over the destination. A failure at any step is one Error naming the file
// and the reason, and leaves nothing behind. Several files can be written as one batch: none of
// them appears unless every one of them could be written.
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace pbr {

// Writes `bytes` to `path`, whole or not at all. The destination's folder must exist (the suite
// never creates a folder a user named). An existing device or pipe (/dev/null, /dev/full, a FIFO)
// is written directly, with every error checked, since it cannot be replaced by a rename.
// Throws Error("<path>: <reason>").
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);
// The same for the bytes `encode` returns (a PNG, a KTX file); an Error it throws gets the path
// in front, so that every failure names the file.
void writeFileAtomically(const std::filesystem::path& path,
                         const std::function<std::string()>& encode);

// Files that appear together or not at all: each is written to its temporary first, then all are
// renamed. Nothing touches the destinations before commit().
class OutputBatch {
public:
    OutputBatch() = default;
    OutputBatch(const OutputBatch&) = delete;
    OutputBatch& operator=(const OutputBatch&) = delete;
    ~OutputBatch();  // removes any temporary a failed commit left

    void add(std::filesystem::path path, std::string bytes);
    bool empty() const { return files_.empty(); }
    // Writes every file; throws Error naming the first that failed, after removing every
    // temporary (so no destination changed).
    void commit();
    // The destinations, in the order they were added.
    std::vector<std::filesystem::path> paths() const;

private:
    struct File {
        std::filesystem::path path;
        std::string bytes;
        std::filesystem::path temporary;  // empty until written; stays empty for devices
    };
    std::vector<File> files_;
};

// Checks, before anything is rendered, that `path` can take an output file: it is not a folder
// and its folder exists. `shown` is the path as the user typed it, for the message. Throws Error.
void requireWritableFilePath(const std::filesystem::path& path, const std::string& shown);
// The same for a folder that output files go into: it exists and is a folder.
void requireOutputFolder(const std::filesystem::path& dir, const std::string& shown);

}  // namespace pbr
