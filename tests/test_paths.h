// Where the tests read their data and goldens and write their outputs: the folders baked in at
// build time (the PENUMBRA_TEST_DATA, PENUMBRA_GOLDEN_DIR and PENUMBRA_TEST_OUT definitions of
// tests/CMakeLists.txt), each overridden by the environment variable of the same name when it is
// set and not empty, so that the binaries run from a bundle unpacked elsewhere (scripts/bundle.sh,
// docs/gpu.md).
#pragma once

#include <cstdlib>
#include <string>

namespace penumbra::test {

// $NAME when set and not empty, else `built_in`.
inline std::string path_from_env(const char* name, const char* built_in) {
    const char* v = std::getenv(name);
    return v && *v ? std::string(v) : std::string(built_in);
}

#ifdef PENUMBRA_TEST_DATA
// tests/data (scenes, glTF files).
inline std::string test_data_dir() { return path_from_env("PENUMBRA_TEST_DATA", PENUMBRA_TEST_DATA); }
#endif
#ifdef PENUMBRA_GOLDEN_DIR
// tests/golden (the reference images).
inline std::string golden_dir() { return path_from_env("PENUMBRA_GOLDEN_DIR", PENUMBRA_GOLDEN_DIR); }
#endif
#ifdef PENUMBRA_TEST_OUT
// build/test-output (what a failing comparison leaves to look at).
inline std::string test_out_dir() { return path_from_env("PENUMBRA_TEST_OUT", PENUMBRA_TEST_OUT); }
#endif

}  // namespace penumbra::test
