// The receivers the camera sees, indexed for the one question the shadows fit asks of each caster:
// which of them can it shadow (shadow::may_shadow)? Asked receiver by receiver, that question
// costs casters x receivers, and a crowd of objects made it the whole frame's cost (docs/scale.md).
// Here the receivers sit
// in a bounding-volume hierarchy over the extents may_shadow reads, so a caster's question visits
// only the nodes that straddle its planes. The answers are may_shadow's, exactly: a node is
// passed over only where every receiver in it fails the same test, and taken whole only where
// every one passes it. No GL.
#pragma once

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "shadow/casting.h"

namespace penumbra::shadow {

// A rect of the light's window: left, right, bottom, top (empty while left > right).
using WindowSides = glm::vec4;
WindowSides empty_window();

class ReceiverIndex {
public:
    // `seen`: the receivers and their visible points; `light` as may_shadow takes it. `linear`:
    // no hierarchy, every question asked of every receiver in turn: the pairwise rule itself, which
    // the tests hold the hierarchy to.
    ReceiverIndex(std::vector<SeenReceiver> seen, const glm::vec4& light, bool linear = false);

    // Whether `caster` can shadow a point of any receiver: may_shadow, never itself when convex.
    bool shadows_any(const CasterBox& caster) const;

    // Each receiver's rect in the light's window (as window coordinates are taken: tangents x/depth,
    // y/depth for a perspective view, eye x and y for an orthographic one). false where a receiver
    // point is not in front of a perspective view's eye plane by front_eps.
    bool set_window(const glm::mat4& view, bool perspective, float front_eps);
    // `rect` cut to the rect around the receivers `caster` can shadow: each side moved in to that
    // rect's where it lies inside (set_window first). A shadow falls where both are.
    void cut_to_reach(const CasterBox& caster, WindowSides& rect) const;

    std::size_t size() const { return items_.size(); }
    const std::vector<SeenReceiver>& seen() const { return seen_; }

    // A receiver as may_shadow reads its points (casting.h: PointSpans), with its object and rect.
    struct Item {
        PointSpans spans;
        int object = -1;
        int seen = -1;  // its receiver in the `seen` the index was made from
        WindowSides rect{0.0f};
    };
    // A node: items [begin, end), its second child at `right` (the first follows it), and bounds
    // over its items of each value a test reads.
    struct Node {
        int begin = 0, end = 0, right = -1;
        glm::vec4 lo_min{0.0f}, lo_max{0.0f}, hi_min{0.0f}, hi_max{0.0f};  // x, y, z, the light's axis
        float far_min = 0.0f, far_max = 0.0f;
        int object_min = 0, object_max = 0;
        WindowSides rect{0.0f};
        bool finite = true;  // every value finite: the bounds decide for the whole node
    };

private:
    int build(int begin, int end);
    void bound(Node& n) const;
    glm::vec4 light_;
    bool linear_;
    std::vector<SeenReceiver> seen_;
    std::vector<Item> items_;
    std::vector<Node> nodes_;
};

}  // namespace penumbra::shadow
