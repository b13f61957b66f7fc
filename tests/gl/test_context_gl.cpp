// Which implementation the GL ring runs on. The softpipe parts of the ring (tests/CMakeLists.txt)
// set PENUMBRA_EXPECT_RENDERER=softpipe beside GALLIUM_DRIVER=softpipe: were the variable ignored
// (another EGL device, another driver), they would run on llvmpipe again and prove nothing, so
// this test fails then.
#include "gl_fixture.h"

#include <cstdlib>

using namespace penumbra;

namespace {

class ContextGl : public test::GlTest {};

TEST_F(ContextGl, IsTheImplementationAskedFor) {
    const char* expected = std::getenv("PENUMBRA_EXPECT_RENDERER");
    RecordProperty("gl_renderer", renderer->caps().renderer);
    if (!expected || !*expected) GTEST_SKIP() << "PENUMBRA_EXPECT_RENDERER not set; running on " << renderer->caps().renderer;
    EXPECT_NE(renderer->caps().renderer.find(expected), std::string::npos)
        << "asked for " << expected << ", running on " << renderer->caps().renderer;
}

}  // namespace
