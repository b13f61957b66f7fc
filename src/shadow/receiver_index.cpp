#include "shadow/receiver_index.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace penumbra::shadow {

namespace {

constexpr int kLeafSize = 4;
// The pages draw only their own scenes, a few hundred objects at most, where asking receiver by
// receiver costs nothing and the hierarchy's code would cost each page's download (docs/payload.md).
// The answers are the same either way (the unit tests hold the two to each other).
#ifdef __EMSCRIPTEN__
constexpr bool kLinearOnly = true;
#else
constexpr bool kLinearOnly = false;
#endif

// The nodes a query has still to visit. The hierarchy splits its items in halves, so its depth is
// about log2(n / kLeafSize) and a depth-first walk holds at most one node a level more: 64 hold
// any count of receivers there can be.
struct Stack {
    int at[64];
    int size = 0;
    void push(int n) { at[size++] = n; }
    int pop() { return at[--size]; }
    bool empty() const { return size == 0; }
};
constexpr float kBig = std::numeric_limits<float>::max();

bool finite4(const glm::vec4& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

// Grows `r` by `s` (both left, right, bottom, top).
void grow(WindowSides& r, const WindowSides& s) {
    r = {std::min(r.x, s.x), std::max(r.y, s.y), std::min(r.z, s.z), std::max(r.w, s.w)};
}

// Whether the caster can shadow the receiver: may_shadow, never itself when convex.
bool passes(const CasterBox& caster, const CasterSpans& c, const ReceiverIndex::Item& r) {
    return !(caster.convex && r.object == caster.object) && may_shadow(c, r.spans);
}

// Every receiver of the node fails one of may_shadow's tests: its bound is on the failing side.
bool none_pass(const CasterSpans& c, const ReceiverIndex::Node& n) {
    if (!n.finite) return false;
    for (int i = 0; i < c.axes; ++i)
        if (separated_above(c, i, n.lo_min[i]) || separated_below(c, i, n.hi_max[i])) return true;
    return nearer_than_caster(c, n.far_max);
}

// Every receiver of the node passes every test (and none is the convex caster itself).
bool all_pass(const CasterBox& caster, const CasterSpans& c, const ReceiverIndex::Node& n) {
    if (!n.finite) return false;
    if (caster.convex && caster.object >= n.object_min && caster.object <= n.object_max) return false;
    for (int i = 0; i < c.axes; ++i)
        if (separated_above(c, i, n.lo_max[i]) || separated_below(c, i, n.hi_min[i])) return false;
    return !nearer_than_caster(c, n.far_min);
}

// Whether a rect can still move a side of the reach found so far: a side is settled once the
// reach lies beyond the caster's own rect there (the cut keeps the caster's side).
bool could_widen(const WindowSides& found, const WindowSides& caster, const WindowSides& r) {
    return (found.x > caster.x && r.x < found.x) || (found.y < caster.y && r.y > found.y) ||
           (found.z > caster.z && r.z < found.z) || (found.w < caster.w && r.w > found.w);
}

}  // namespace

WindowSides empty_window() { return {kBig, -kBig, kBig, -kBig}; }

ReceiverIndex::ReceiverIndex(std::vector<SeenReceiver> seen, const glm::vec4& light, bool linear)
    : light_(light), linear_(linear || kLinearOnly), seen_(std::move(seen)) {
    // A receiver with no visible point can be shadowed by nothing (may_shadow: false).
    for (size_t k = 0; k < seen_.size(); ++k)
        if (!seen_[k].points.empty())
            items_.push_back({point_spans(seen_[k].points, light), seen_[k].object, static_cast<int>(k), empty_window()});
    if (linear_ || kLinearOnly || items_.empty()) return;
    // The items in Morton order of their centres (10 bits an axis over the centres' box; a centre
    // that is not finite counts as 0), then split in halves by count: one sort, and each node's
    // items are neighbours in space and in memory.
    const auto centre = [](const Item& it, int a) {
        const float c = 0.5f * it.spans.lo[a] + 0.5f * it.spans.hi[a];
        return std::isfinite(c) ? c : 0.0f;
    };
    glm::vec3 lo(kBig), hi(-kBig);
    for (const Item& it : items_)
        for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], centre(it, a)), hi[a] = std::max(hi[a], centre(it, a));
    const auto spread = [](std::uint64_t v) {  // 10 bits to every third of 30
        v = (v | (v << 16)) & 0x030000FFull;
        v = (v | (v << 8)) & 0x0300F00Full;
        v = (v | (v << 4)) & 0x030C30C3ull;
        return (v | (v << 2)) & 0x09249249ull;
    };
    std::vector<std::uint64_t> keys(items_.size());
    for (size_t i = 0; i < items_.size(); ++i) {
        std::uint64_t code = 0;
        for (int a = 0; a < 3; ++a) {
            const float extent = hi[a] - lo[a];
            const float t = extent > 0.0f && std::isfinite(extent) ? (centre(items_[i], a) - lo[a]) / extent : 0.0f;
            code |= spread(static_cast<std::uint64_t>(std::clamp(t, 0.0f, 1.0f) * 1023.0f)) << a;
        }
        keys[i] = (code << 32) | i;  // the index keeps the order strict
    }
    std::sort(keys.begin(), keys.end());
    std::vector<Item> ordered;
    ordered.reserve(items_.size());
    for (std::uint64_t k : keys) ordered.push_back(items_[k & 0xFFFFFFFFull]);
    items_ = std::move(ordered);
    nodes_.reserve(2 * items_.size() / kLeafSize + 2);
    build(0, static_cast<int>(items_.size()));
}

void ReceiverIndex::bound(Node& n) const {
    n.lo_min = n.hi_min = glm::vec4(kBig);
    n.lo_max = n.hi_max = glm::vec4(-kBig);
    n.far_min = kBig;
    n.far_max = -kBig;
    n.object_min = std::numeric_limits<int>::max();
    n.object_max = std::numeric_limits<int>::min();
    n.finite = true;
    for (int i = n.begin; i < n.end; ++i) {
        const Item& it = items_[static_cast<size_t>(i)];
        n.finite = n.finite && finite4(it.spans.lo) && finite4(it.spans.hi) && std::isfinite(it.spans.farthest);
        n.lo_min = glm::min(n.lo_min, it.spans.lo);
        n.lo_max = glm::max(n.lo_max, it.spans.lo);
        n.hi_min = glm::min(n.hi_min, it.spans.hi);
        n.hi_max = glm::max(n.hi_max, it.spans.hi);
        n.far_min = std::min(n.far_min, it.spans.farthest);
        n.far_max = std::max(n.far_max, it.spans.farthest);
        n.object_min = std::min(n.object_min, it.object);
        n.object_max = std::max(n.object_max, it.object);
    }
}

// Nodes in depth-first order, each node's first child right after it: the items' range split in
// halves, down to kLeafSize a leaf; a node's bounds are its leaf's items' or its children's. O(n).
int ReceiverIndex::build(int begin, int end) {
    const int at = static_cast<int>(nodes_.size());
    nodes_.push_back({});
    Node n;
    n.begin = begin;
    n.end = end;
    if (end - begin <= kLeafSize) {
        bound(n);
    } else {
        const int mid = begin + (end - begin) / 2;
        build(begin, mid);
        n.right = build(mid, end);
        // The union of the children's bounds (a node with a value that is not finite is never
        // decided by its bounds, so theirs may be anything).
        const Node& a = nodes_[static_cast<size_t>(at) + 1];
        const Node& b = nodes_[static_cast<size_t>(n.right)];
        n.lo_min = glm::min(a.lo_min, b.lo_min);
        n.lo_max = glm::max(a.lo_max, b.lo_max);
        n.hi_min = glm::min(a.hi_min, b.hi_min);
        n.hi_max = glm::max(a.hi_max, b.hi_max);
        n.far_min = std::min(a.far_min, b.far_min);
        n.far_max = std::max(a.far_max, b.far_max);
        n.object_min = std::min(a.object_min, b.object_min);
        n.object_max = std::max(a.object_max, b.object_max);
        n.finite = a.finite && b.finite;
    }
    nodes_[static_cast<size_t>(at)] = n;
    return at;
}

bool ReceiverIndex::shadows_any(const CasterBox& caster) const {
    if (caster.bounds.empty() || items_.empty()) return false;
    const CasterSpans c = caster_spans(caster.bounds, light_);
    if (linear_ || kLinearOnly)
        return std::any_of(items_.begin(), items_.end(), [&](const Item& r) { return passes(caster, c, r); });
    Stack stack;
    stack.push(0);
    while (!stack.empty()) {
        const int self = stack.pop();
        const Node& n = nodes_[static_cast<size_t>(self)];
        if (none_pass(c, n)) continue;
        if (all_pass(caster, c, n)) return true;
        if (n.right < 0) {
            for (int i = n.begin; i < n.end; ++i)
                if (passes(caster, c, items_[static_cast<size_t>(i)])) return true;
            continue;
        }
        stack.push(n.right);
        stack.push(self + 1);
    }
    return false;
}

bool ReceiverIndex::set_window(const glm::mat4& view, bool perspective, float front_eps) {
    for (Item& it : items_) {
        it.rect = empty_window();
        for (const glm::vec3& p : seen_[static_cast<size_t>(it.seen)].points) {
            const glm::vec3 e = glm::vec3(view * glm::vec4(p, 1.0f));
            glm::vec2 t(e);
            if (perspective) {
                if (!(-e.z > front_eps)) return false;
                t /= -e.z;
            }
            grow(it.rect, {t.x, t.x, t.y, t.y});
        }
    }
    // Bottom up: a node's children come after it.
    for (size_t k = nodes_.size(); k-- > 0;) {
        Node& n = nodes_[k];
        n.rect = empty_window();
        if (n.right < 0) {
            for (int i = n.begin; i < n.end; ++i) grow(n.rect, items_[static_cast<size_t>(i)].rect);
        } else {
            grow(n.rect, nodes_[k + 1].rect);
            grow(n.rect, nodes_[static_cast<size_t>(n.right)].rect);
        }
    }
    return true;
}

void ReceiverIndex::cut_to_reach(const CasterBox& caster, WindowSides& rect) const {
    WindowSides found = empty_window();
    if (!caster.bounds.empty() && !items_.empty()) {
        const CasterSpans c = caster_spans(caster.bounds, light_);
        if (linear_ || kLinearOnly) {
            for (const Item& r : items_)
                if (passes(caster, c, r)) grow(found, r.rect);
        } else {
            Stack stack;
            stack.push(0);
            while (!stack.empty()) {
                const int self = stack.pop();
                const Node& n = nodes_[static_cast<size_t>(self)];
                if (!could_widen(found, rect, n.rect) || none_pass(c, n)) continue;
                if (all_pass(caster, c, n)) {
                    grow(found, n.rect);
                    continue;
                }
                if (n.right < 0) {
                    for (int i = n.begin; i < n.end; ++i) {
                        const Item& r = items_[static_cast<size_t>(i)];
                        if (could_widen(found, rect, r.rect) && passes(caster, c, r)) grow(found, r.rect);
                    }
                    continue;
                }
                // The child with the wider rect first: a receiver under the whole view (a ground)
                // settles every side at once.
                const Node& a = nodes_[static_cast<size_t>(self + 1)];
                const Node& b = nodes_[static_cast<size_t>(n.right)];
                const bool a_wider = (a.rect.y - a.rect.x) + (a.rect.w - a.rect.z) >= (b.rect.y - b.rect.x) + (b.rect.w - b.rect.z);
                stack.push(a_wider ? n.right : self + 1);
                stack.push(a_wider ? self + 1 : n.right);
            }
        }
    }
    rect = {std::max(rect.x, found.x), std::min(rect.y, found.y), std::max(rect.z, found.z), std::min(rect.w, found.w)};
}

}  // namespace penumbra::shadow
