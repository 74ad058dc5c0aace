#pragma once
// The folders and files of the build and the checkout that the tests use (the samples' folder,
// the goldens, the test output, ...). Each is compiled in (tests/CMakeLists.txt) and read, where
// it exists, from test-paths.txt beside the test program, which the build writes with its own:
// the sanitizer build links the test programs the Release build compiled (they are not
// instrumented either way) and points them at its own samples and its own checkout so.
#include <string>

namespace pbr::test {

// The value of `name` ("PBR_GOLDEN_DIR") in test-paths.txt beside this program, else `compiled`.
std::string buildPath(const char* name, const char* compiled);

}  // namespace pbr::test

// PBR_PATH(PBR_GOLDEN_DIR): that path, as buildPath finds it.
#define PBR_PATH(NAME) ::pbr::test::buildPath(#NAME, NAME)
