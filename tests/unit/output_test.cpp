// Every file the suite writes is whole or absent (common/base/output.h): the checks a full disk, a
// missing folder or a folder in the way must pass, in-process. The same through whole samples
// (a nearly full disk, /dev/full, 06's batch) is in tests/cli/output_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>

#include "base/error.h"
#include "base/output.h"
#include "base/paths.h"
#include "support/process.h"

namespace pbr {
namespace {

namespace fs = std::filesystem;
using test::folderEntries;
using test::readBytes;
using test::testOutputDir;

std::string errorOf(const std::function<void()>& write) {
    try {
        write();
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

TEST(Output, WritesAndReplacesWhole) {
    const fs::path dir = testOutputDir("output_replace");
    writeFileAtomically(dir / "a.txt", "first");
    writeFileAtomically(dir / "a.txt", "second, longer");
    EXPECT_EQ(readBytes(dir / "a.txt"), "second, longer");
    EXPECT_EQ(folderEntries(dir), std::vector<std::string>{"a.txt"});  // no temporary left
}

TEST(Output, MissingFolderIsNamedAndNothingIsCreated) {
    const fs::path dir = testOutputDir("output_unit_missing_folder");
    const std::string error =
        errorOf([&] { writeFileAtomically(dir / "nowhere" / "a.txt", "bytes"); });
    EXPECT_NE(error.find("a.txt: no such folder"), std::string::npos) << error;
    EXPECT_TRUE(folderEntries(dir).empty());
}

TEST(Output, AFolderInTheWayIsNamed) {
    const fs::path dir = testOutputDir("output_folder_in_the_way");
    fs::create_directory(dir / "taken");
    const std::string error = errorOf([&] { writeFileAtomically(dir / "taken", "bytes"); });
    EXPECT_NE(error.find("taken: is a directory"), std::string::npos) << error;
    EXPECT_EQ(folderEntries(dir), std::vector<std::string>{"taken"});
}

// /dev/full refuses every byte: the error says so, and no temporary appears anywhere.
TEST(Output, AFullDeviceIsAnErrorNotASilentLoss) {
    const std::string error = errorOf([] { writeFileAtomically("/dev/full", "bytes"); });
    EXPECT_NE(error.find("/dev/full: cannot write: No space left on device"), std::string::npos)
        << error;
    writeFileAtomically("/dev/null", "bytes");  // a device that takes them is fine
}

// A batch appears whole or not at all: the second file cannot be written, so the first (written
// before it in the batch) must not appear either, and an older file there keeps its bytes.
TEST(Output, ABatchIsAllOrNothing) {
    const fs::path dir = testOutputDir("output_batch");
    writeFileAtomically(dir / "one.txt", "old");
    {
        OutputBatch batch;
        batch.add(dir / "one.txt", "new");
        batch.add(dir / "two.txt", "new");
        batch.add(dir / "missing" / "three.txt", "new");
        const std::string error = errorOf([&] { batch.commit(); });
        EXPECT_NE(error.find("three.txt: no such folder"), std::string::npos) << error;
    }
    EXPECT_EQ(readBytes(dir / "one.txt"), "old");
    EXPECT_EQ(folderEntries(dir), std::vector<std::string>{"one.txt"});

    OutputBatch batch;
    batch.add(dir / "one.txt", "new");
    batch.add(dir / "two.txt", "new");
    batch.add("/dev/full", "new");  // devices are written after every temporary
    EXPECT_NE(errorOf([&] { batch.commit(); }).find("No space left"), std::string::npos);
    EXPECT_EQ(readBytes(dir / "one.txt"), "old");
    EXPECT_EQ(folderEntries(dir), std::vector<std::string>{"one.txt"});
}

TEST(Output, ALinkStaysALink) {
    const fs::path dir = testOutputDir("output_link");
    writeFileAtomically(dir / "target.txt", "old");
    fs::create_symlink("target.txt", dir / "link.txt");
    writeFileAtomically(dir / "link.txt", "new");
    EXPECT_TRUE(fs::is_symlink(dir / "link.txt"));
    EXPECT_EQ(readBytes(dir / "target.txt"), "new");
}

TEST(Output, PathChecksBeforeRendering) {
    const fs::path dir = testOutputDir("output_checks");
    EXPECT_EQ(errorOf([&] { requireWritableFilePath(dir, "out/"); }), "out/: is a directory");
    EXPECT_EQ(errorOf([&] { requireWritableFilePath(dir / "no" / "x.png", "no/x.png"); }),
              "no/x.png: no such folder '" + (dir / "no").string() + "'");
    EXPECT_EQ(errorOf([&] { requireWritableFilePath(dir / "x.png", "x.png"); }), "no error");
    EXPECT_EQ(errorOf([&] { requireOutputFolder(dir / "no", "--ktx-dir no"); }),
              "--ktx-dir no: no such folder");
    writeFileAtomically(dir / "file", "");
    EXPECT_EQ(errorOf([&] { requireOutputFolder(dir / "file", "--ktx-dir file"); }),
              "--ktx-dir file: not a folder");
}

}  // namespace
}  // namespace pbr

// Every reader takes its bytes through readTextFile: a folder or a device (which has no end to
// read to: /dev/zero ran a shader include out of memory) is one line naming it, not a read.
TEST(Paths, ReadTextFileTakesFilesOnly) {
    for (const auto& [path, reason] :
         std::vector<std::pair<std::string, std::string>>{{"/dev/zero", ": not a file"},
                                                          {"/tmp", ": is a directory"}}) {
        try {
            (void)pbr::readTextFile(path);
            ADD_FAILURE() << path << " was read";
        } catch (const pbr::Error& e) {
            EXPECT_EQ(std::string(e.what()).rfind(path + reason, 0), 0u) << e.what();
            EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
        }
    }
}
