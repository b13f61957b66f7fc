// Which uniforms a variant's source declares, with its #ifdef blocks resolved by the defines it
// holds: what debug builds check every Program::set against.
#include <gtest/gtest.h>

#include "gl/uniforms.h"

using penumbra::gl::declared_uniforms;

namespace {

using Names = std::set<std::string>;

TEST(DeclaredUniforms, FollowTheDefines) {
    const std::string body =
        "uniform vec4 u_always;\n"
        "#ifdef SHADOW_MAP\n"
        "uniform sampler2D u_map; // the map\n"
        "#if defined(BIAS_AUTO)\n"
        "uniform mediump vec2 u_slope, u_kernel[4];\n"
        "#else\n"
        "uniform float u_bias;\n"
        "#endif\n"
        "#elif defined(IN_SHADOW)\n"
        "uniform float u_shade;\n"
        "#endif\n"
        "#ifndef TEXTURED\n"
        "uniform vec3 u_plain;\n"
        "#endif\n"
        "float not_a_uniform_name;\n";
    EXPECT_EQ(declared_uniforms("#version 100\n" + body), (Names{"u_always", "u_plain"}));
    EXPECT_EQ(declared_uniforms("#version 100\n#define SHADOW_MAP 1\n" + body),
              (Names{"u_always", "u_map", "u_bias", "u_plain"}));
    EXPECT_EQ(declared_uniforms("#version 100\n#define SHADOW_MAP 1\n#define BIAS_AUTO 1\n#define TEXTURED 1\n" + body),
              (Names{"u_always", "u_map", "u_slope", "u_kernel"}));
    EXPECT_EQ(declared_uniforms("#version 100\n#define IN_SHADOW 1\n" + body), (Names{"u_always", "u_shade", "u_plain"}));
}

TEST(DeclaredUniforms, AnUndecidableConditionKeepsEveryBranch) {
    const std::string src =
        "#if defined(A) || defined(B)\nuniform float u_a;\n#else\nuniform float u_b;\n#endif\n"
        "#ifdef GL_FRAGMENT_PRECISION_HIGH\nuniform float u_c;\n#else\nuniform float u_d;\n#endif\n";
    EXPECT_EQ(declared_uniforms(src), (Names{"u_a", "u_b", "u_c", "u_d"}));
}

}  // namespace
