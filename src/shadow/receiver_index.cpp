#include "shadow/receiver_index.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace penumbra::shadow {

namespace {

constexpr int kLeafSize = 4;

// The nodes a query has still to visit. The hierarchy splits at medians, so its depth is about
// log2(n / kLeafSize) and a depth-first walk holds at most one node a level: 64 levels hold any
// count of receivers there can be.
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
    : light_(light), linear_(linear), seen_(std::move(seen)) {
    // A receiver with no visible point can be shadowed by nothing (may_shadow: false).
    for (size_t k = 0; k < seen_.size(); ++k)
        if (!seen_[k].points.empty())
            items_.push_back({point_spans(seen_[k].points, light), seen_[k].object, static_cast<int>(k), empty_window()});
    if (!linear_ && !items_.empty()) {
        nodes_.reserve(2 * items_.size() / kLeafSize + 2);
        build(0, static_cast<int>(items_.size()));
    }
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

// Nodes in depth-first order, each node's first child right after it: items split at the median
// of their centres along the widest axis, down to kLeafSize a leaf. O(n log n).
int ReceiverIndex::build(int begin, int end) {
    const int at = static_cast<int>(nodes_.size());
    nodes_.push_back({});
    Node n;
    n.begin = begin;
    n.end = end;
    bound(n);
    if (end - begin > kLeafSize) {
        // The centre along each world axis; a value that is not finite sorts as 0, so the order stays strict.
        auto centre = [](const Item& it, int axis) {
            const float c = 0.5f * it.spans.lo[axis] + 0.5f * it.spans.hi[axis];
            return std::isfinite(c) ? c : 0.0f;
        };
        glm::vec3 lo(kBig), hi(-kBig);
        for (int i = begin; i < end; ++i)
            for (int a = 0; a < 3; ++a) {
                lo[a] = std::min(lo[a], centre(items_[static_cast<size_t>(i)], a));
                hi[a] = std::max(hi[a], centre(items_[static_cast<size_t>(i)], a));
            }
        const glm::vec3 extent = hi - lo;
        const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
        const int mid = begin + (end - begin) / 2;
        std::nth_element(items_.begin() + begin, items_.begin() + mid, items_.begin() + end,
                         [&](const Item& a, const Item& b) { return centre(a, axis) < centre(b, axis); });
        build(begin, mid);
        n.right = build(mid, end);
    }
    nodes_[static_cast<size_t>(at)] = n;
    return at;
}

bool ReceiverIndex::shadows_any(const CasterBox& caster) const {
    if (caster.bounds.empty() || items_.empty()) return false;
    const CasterSpans c = caster_spans(caster.bounds, light_);
    if (linear_)
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
        if (linear_) {
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
