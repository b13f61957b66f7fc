// Scenes of many objects that share one small mesh, made in code at any size: what the planner's
// cost is measured and tested on (penumbra bench --scale, tests/cli_scale.sh). By name, as
// --scene takes them:
//   pile:N[:LIGHT]    N pyramids heaped in a 3 x 0.3 strip on a ground, seen whole from the front:
//                     every caster near every receiver, where a per-pair list grows with N squared;
//   forest:N[:LIGHT]  N pyramids on a square grid 0.3 apart on a ground, seen from its edge out to
//                     the horizon: each shadows only its neighbours;
// LIGHT: point (default: the pile's from the right, the forest's behind the camera, up high), spot
// (the same place, aimed at the middle, a 60 degree half-angle cone) or sun (a directional light
// 35 degrees up). The pyramids are 0.2 wide and 0.35 tall.
#pragma once

#include <string>

#include "scene/scene.h"

namespace penumbra::scene {

enum class ScaleLayout { Pile, Forest };

struct ScaleSpec {
    ScaleLayout layout = ScaleLayout::Pile;
    int count = 1000;
    LightType light = LightType::Point;
};

// The most pyramids a named scale scene may have: far past the benchmark's 100,000, well short of
// what would not fit in memory (about 1 KB an object, planned and drawn).
inline constexpr int kMaxScaleCount = 2000000;

// Whether `name` names a scale scene ("pile:" or "forest:" first); then `spec` is filled, or
// `error` (one line) says what is wrong with the rest of it.
bool is_scale_name(const std::string& name);
bool parse_scale_name(const std::string& name, ScaleSpec& spec, std::string& error);
std::string scale_name(const ScaleSpec& spec);  // "pile:1000" ("pile:1000:sun" for another light)

// The scene: one pyramid mesh (closed, convex) shared by every node, one ground quad under them,
// a camera that sees the whole layout, the light the spec names. Deterministic (a fixed LCG).
Scene make_scale_scene(const ScaleSpec& spec);

}  // namespace penumbra::scene
