// The sheet's answer (02561 W09) as snippets, its classic mistakes and the lab's starter skeleton
// (plan/snippets.h): the text a student is compared with; and a student's text cut to one function
// (snippet_only) and its functions' names.
#include <algorithm>
#include <cctype>

#include "plan/snippets.h"

namespace penumbra::render {

// The sheet's answer, one function at a time (02561 W09: "Drawing depth and considering numerical
// precision", "Shadow mapping in the fragment shader", "Percentage-closer filtering").
std::string sheet_answer_fn(SnippetFn f, shadow::Encoding e) {
    const bool r8 = e == shadow::Encoding::R8;
    switch (f) {
        case SnippetFn::PackDepth:
            if (r8)
                return "// The depth as red: 8 bits.\n"
                       "vec4 packDepth(float z) {\n"
                       "    return vec4(z, 0.0, 0.0, 0.0);\n"
                       "}\n";
            return "// Bit-shift packing: each channel holds the next 8 bits of the depth.\n"
                   "vec4 packDepth(float z) {\n"
                   "    const vec4 bitShift = vec4(1.0, 256.0, 256.0 * 256.0, 256.0 * 256.0 * 256.0);\n"
                   "    const vec4 bitMask = vec4(1.0 / 256.0, 1.0 / 256.0, 1.0 / 256.0, 0.0);\n"
                   "    vec4 rgbaDepth = fract(z * bitShift);\n"
                   "    rgbaDepth -= rgbaDepth.gbaa * bitMask;\n"
                   "    return rgbaDepth;\n"
                   "}\n";
        case SnippetFn::UnpackDepth:
            if (r8)
                return "float unpackDepth(const in vec4 rgbaDepth) {\n"
                       "    return rgbaDepth.r;\n"
                       "}\n";
            return "float unpackDepth(const in vec4 rgbaDepth) {\n"
                   "    const vec4 bitShift = vec4(1.0, 1.0 / 256.0, 1.0 / (256.0 * 256.0), 1.0 / (256.0 * 256.0 * 256.0));\n"
                   "    return dot(rgbaDepth, bitShift);\n"
                   "}\n";
        case SnippetFn::ShadowTest:
            return "// 1.0 where the light reaches, 0.0 in shadow: in shadow if zLight > depth + bias.\n"
                   "float shadowTest(float zLight, float depth, float bias) {\n"
                   "    return zLight > depth + bias ? 0.0 : 1.0;\n"
                   "}\n";
        case SnippetFn::OffsetLookup:
            return "// One tap of the 4x4 kernel: offset in texels, texmapscale = (1/width, 1/height).\n"
                   "vec4 offset_lookup(sampler2D map, vec3 shadowCoord, vec2 offset) {\n"
                   "    return texture2D(map, shadowCoord.xy + offset * texmapscale);\n"
                   "}\n";
    }
    return "";
}

std::string sheet_answer(shadow::Encoding e) {
    std::string out = e == shadow::Encoding::R8
                          ? "// The sheet's answer (02561 W09), 8-bit shadow map: bias 0.005 = 2^-8 + e.\n"
                          : "// The sheet's answer (02561 W09), bit-shift packing: bias 0.0015 = 2^-10 + e.\n";
    for (SnippetFn f : kAllSnippetFns) out += "\n" + sheet_answer_fn(f, e);
    return out;
}

std::string snippet_skeleton() {
    return "// The shader lab: write the sheet's functions (02561 W09). A function left out is the\n"
           "// sheet's answer's. This skeleton compiles and draws no shadow.\n"
           "\n"
           "// The light's depth gl_FragCoord.z in [0, 1], written into the RGBA8 shadow map.\n"
           "vec4 packDepth(float z) {\n"
           "    return vec4(0.0);\n"
           "}\n"
           "\n"
           "// The depth back from the map's texel.\n"
           "float unpackDepth(const in vec4 rgbaDepth) {\n"
           "    return 1.0;\n"
           "}\n"
           "\n"
           "// 1.0 where the light reaches the point at depth zLight, 0.0 in shadow.\n"
           "float shadowTest(float zLight, float depth, float bias) {\n"
           "    return 1.0;\n"
           "}\n"
           "\n"
           "// The map's texel `offset` texels from shadowCoord.xy (texmapscale: 1/width, 1/height).\n"
           "vec4 offset_lookup(sampler2D map, vec3 shadowCoord, vec2 offset) {\n"
           "    return texture2D(map, shadowCoord.xy);\n"
           "}\n";
}

std::vector<SnippetMistake> snippet_mistakes(shadow::Encoding e) {
    const bool r8 = e == shadow::Encoding::R8;
    std::vector<SnippetMistake> out;
    out.push_back({"no-bias",
                   "No bias: the surface shadows itself in stripes (shadow acne). Compare with depth + bias: the "
                   "stored depth is rounded, so a lit surface reads as slightly behind itself.",
                   "float shadowTest(float zLight, float depth, float bias) {\n    return zLight > depth ? 0.0 : 1.0;\n}\n"});
    out.push_back({"wrong-way",
                   "The comparison the wrong way round: lit and shadow are swapped, the shadows lit and the lit "
                   "surfaces dark. shadowTest returns 0.0 (shadow) where the point is farther from the light than "
                   "the map's depth: zLight > depth + bias ? 0.0 : 1.0.",
                   "float shadowTest(float zLight, float depth, float bias) {\n"
                   "    return zLight > depth + bias ? 1.0 : 0.0;\n}\n"});
    out.push_back({"bias-wrong-side",
                   "The bias on the wrong side: zLight + bias > depth puts in shadow every surface as far from the "
                   "light as the map's depth, so the lit surfaces go dark. The bias lets a lit point be a little "
                   "farther than the stored depth: zLight > depth + bias.",
                   "float shadowTest(float zLight, float depth, float bias) {\n"
                   "    return zLight + bias > depth ? 0.0 : 1.0;\n}\n"});
    if (!r8) {
        out.push_back({"8-bit-threshold",
                       "The 8-bit threshold 0.005 (the red-channel answer's bias) with bit-shift packing: the packed depth is good to 2^-10, so the "
                       "sheet's bias is 0.0015. 0.005 pulls each shadow back from where its caster meets the receiver.",
                       "float shadowTest(float zLight, float depth, float bias) {\n"
                       "    return zLight > depth + 0.005 ? 0.0 : 1.0;\n}\n"});
        out.push_back({"red-only",
                       "Only the red channel unpacked: with bit-shift packing red holds the depth's first 8 bits; "
                       "unpackDepth must add the other channels, each 256 times smaller.",
                       "float unpackDepth(const in vec4 rgbaDepth) {\n    return rgbaDepth.r;\n}\n"});
        out.push_back({"unpack-reversed",
                       "The unpack weights in the wrong order: packDepth puts the depth's first 8 bits in red, so red "
                       "weighs 1 and each next channel 256 times less: dot(rgbaDepth, vec4(1.0, 1.0 / 256.0, "
                       "1.0 / (256.0 * 256.0), 1.0 / (256.0 * 256.0 * 256.0))).",
                       "float unpackDepth(const in vec4 rgbaDepth) {\n"
                       "    const vec4 bitShift = vec4(1.0 / (256.0 * 256.0 * 256.0), 1.0 / (256.0 * 256.0), 1.0 / 256.0, 1.0);\n"
                       "    return dot(rgbaDepth, bitShift);\n}\n"});
    }
    out.push_back({"detached",
                   "A bias so large that the shadow detaches from its caster (peter-panning): the bias should be "
                   "just over the stored depth's precision.",
                   "float shadowTest(float zLight, float depth, float bias) {\n"
                   "    return zLight > depth + 0.05 ? 0.0 : 1.0;\n}\n"});
    out.push_back({"no-texmapscale",
                   "Offsets without texmapscale: the offset is in texels, the texture coordinates in [0, 1]; "
                   "multiply the offset by texmapscale = (1/width, 1/height).",
                   "vec4 offset_lookup(sampler2D map, vec3 shadowCoord, vec2 offset) {\n"
                   "    return texture2D(map, shadowCoord.xy + offset);\n}\n"});
    return out;
}

std::string snippet_names(const std::vector<SnippetFn>& fns) {
    std::string out;
    for (SnippetFn f : kAllSnippetFns)
        if (std::find(fns.begin(), fns.end(), f) != fns.end())
            out += (out.empty() ? "" : " ") + std::string(snippet_name(f));
    return out;
}

std::string snippet_only(std::string_view text, SnippetFn keep) {
    const SnippetScan scan = scan_snippets(text);
    std::vector<std::string_view> renamed;
    for (SnippetFn f : scan.defines)
        if (f != keep) renamed.push_back(snippet_name(f));
    const auto head = [](char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; };
    const auto tail = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    std::string out;
    out.reserve(text.size() + 64);
    enum { Code, Line, Block } state = Code;
    for (size_t i = 0; i < text.size();) {
        const char c = text[i];
        const char next = i + 1 < text.size() ? text[i + 1] : '\0';
        if (state == Code && c == '/' && (next == '/' || next == '*')) {
            state = next == '/' ? Line : Block;
            out += text.substr(i, 2);
            i += 2;
        } else if (state == Code && (head(c) || std::isdigit(static_cast<unsigned char>(c)))) {
            // A name (renamed where it is another contract function's), or a number with its suffix.
            size_t j = i;
            while (j < text.size() && (tail(text[j]) || (!head(c) && text[j] == '.'))) ++j;
            const std::string_view word = text.substr(i, j - i);
            out += word;
            if (head(c) && std::find(renamed.begin(), renamed.end(), word) != renamed.end()) out += "_notChecked";
            i = j;
        } else if (state == Block && c == '*' && next == '/') {
            state = Code;
            out += "*/";
            i += 2;
        } else {
            if (state == Line && c == '\n') state = Code;
            out += c;
            ++i;
        }
    }
    return out;
}

}  // namespace penumbra::render
