#include "gl/timer.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "gl/entry_points.h"
#include "gl/gl_headers.h"

namespace penumbra::gl {

namespace {

double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::string ms3(double ms) {
    char b[32];
    std::snprintf(b, sizeof b, "%.3f", ms);
    return b;
}

}  // namespace

double GpuFrame::total_ms() const {
    double t = 0.0;
    for (const PassTime& p : passes) t += p.ms;
    return t;
}

PassTimer::PassTimer(bool available) : available_(available) {
    if (!available_) return;
    GLint disjoint = 0;
    glGetIntegerv(GL_GPU_DISJOINT_EXT, &disjoint);  // clears what happened before this timer
}

PassTimer::~PassTimer() {
    if (!available_) return;
    if (in_pass_) entry_points().end_query(GL_TIME_ELAPSED_EXT);
    std::vector<GLuint> all = free_;
    for (const auto& q : current_.queries) all.push_back(q.second);
    for (const Frame& f : pending_)
        for (const auto& q : f.queries) all.push_back(q.second);
    if (!all.empty()) entry_points().delete_queries(static_cast<GLsizei>(all.size()), all.data());
}

std::uint32_t PassTimer::make_query() {
    if (!free_.empty()) {
        const std::uint32_t q = free_.back();
        free_.pop_back();
        return q;
    }
    GLuint q = 0;
    entry_points().gen_queries(1, &q);
    return q;
}

bool PassTimer::ready(const Frame& f) const {
    for (const auto& q : f.queries) {
        GLuint available = 0;
        entry_points().get_query_object_uiv(q.second, GL_QUERY_RESULT_AVAILABLE_EXT, &available);
        if (!available) return false;
    }
    return true;
}

// Reads the pending frames, oldest first, while they are ready (all of them with `wait`; the
// oldest at least with `at_least_one`), then asks whether the GPU's clock was disjoint meanwhile:
// if so, what was just read and what is still pending is discarded.
void PassTimer::poll(bool wait, bool at_least_one) {
    std::vector<GpuFrame> read;
    bool any = false;
    while (!pending_.empty() && (wait || at_least_one || ready(pending_.front()))) {
        at_least_one = false;
        Frame f = std::move(pending_.front());
        pending_.pop_front();
        any = true;
        GpuFrame g;
        for (const auto& [name, q] : f.queries) {
            GLuint64 ns = 0;
            entry_points().get_query_object_ui64v(q, GL_QUERY_RESULT_EXT, &ns);
            g.passes.push_back({name, static_cast<double>(ns) * 1e-6});
            free_.push_back(q);
        }
        if (f.tainted) ++discarded_;
        else read.push_back(std::move(g));
    }
    if (!any) return;
    GLint disjoint = 0;
    glGetIntegerv(GL_GPU_DISJOINT_EXT, &disjoint);
    if (disjoint) {
        discarded_ += static_cast<int>(read.size());
        read.clear();
        for (Frame& f : pending_) f.tainted = true;
        current_.tainted = true;
    }
    for (GpuFrame& g : read) done_.push_back(std::move(g));
    while (done_.size() > static_cast<size_t>(kKept)) done_.pop_front();
}

void PassTimer::drop_current() {
    if (in_pass_) entry_points().end_query(GL_TIME_ELAPSED_EXT);
    in_pass_ = false;
    // An ended query may begin again; its unread result is simply lost.
    for (const auto& q : current_.queries) free_.push_back(q.second);
    current_ = {};
    in_frame_ = false;
}

void PassTimer::begin_frame() {
    if (!available_) return;
    if (grouped_) {  // one more plan of the group's frame
        end_pass();
        return;
    }
    if (in_frame_) drop_current();
    if (!enabled_) return;
    poll(false);
    while (pending() >= kRing) poll(false, true);  // the GPU is kRing frames behind: wait for the oldest
    current_ = {};
    in_frame_ = true;
}

void PassTimer::begin_pass(const std::string& name) {
    if (!in_frame_) return;
    if (in_pass_) end_pass();
    const std::uint32_t q = make_query();
    entry_points().begin_query(GL_TIME_ELAPSED_EXT, q);
    current_.queries.emplace_back(prefix_ + name, q);
    in_pass_ = true;
}

void PassTimer::end_pass() {
    if (!in_pass_) return;
    entry_points().end_query(GL_TIME_ELAPSED_EXT);
    in_pass_ = false;
}

void PassTimer::end_frame() {
    if (grouped_) {
        end_pass();
        return;
    }
    if (!in_frame_) return;
    end_pass();
    pending_.push_back(std::move(current_));
    current_ = {};
    in_frame_ = false;
}

void PassTimer::begin_group() {
    grouped_ = false;
    begin_frame();
    grouped_ = in_frame_;
}

void PassTimer::end_group() {
    grouped_ = false;
    end_frame();
}

std::vector<GpuFrame> PassTimer::take(bool wait) {
    if (!available_) return {};
    poll(wait);
    std::vector<GpuFrame> out(std::make_move_iterator(done_.begin()), std::make_move_iterator(done_.end()));
    done_.clear();
    return out;
}

GpuSummary summarize(const std::vector<GpuFrame>& frames) {
    GpuSummary s;
    std::vector<std::string> order;
    std::vector<std::vector<double>> times;
    std::vector<double> totals;
    for (const GpuFrame& f : frames) {
        std::vector<std::pair<std::string, int>> seen;  // name, how many so far in this frame
        for (const PassTime& p : f.passes) {
            auto it = std::find_if(seen.begin(), seen.end(), [&](const auto& x) { return x.first == p.name; });
            const int n = it == seen.end() ? (seen.emplace_back(p.name, 1), 1) : ++it->second;
            const std::string key = n == 1 ? p.name : p.name + " #" + std::to_string(n);
            const auto at = std::find(order.begin(), order.end(), key);
            const size_t i = static_cast<size_t>(at - order.begin());
            if (at == order.end()) {
                order.push_back(key);
                times.emplace_back();
            }
            times[i].push_back(p.ms);
        }
        totals.push_back(f.total_ms());
    }
    for (size_t i = 0; i < order.size(); ++i)
        s.passes.push_back({order[i], median(times[i]), static_cast<int>(times[i].size())});
    s.total_ms = median(totals);
    s.frames = static_cast<int>(frames.size());
    return s;
}

std::string describe(const GpuSummary& s, bool available, int discarded) {
    if (!available) return "GPU timer: not available on this context (no EXT_disjoint_timer_query)\n";
    std::ostringstream o;
    const std::string dropped =
        discarded ? ", " + std::to_string(discarded) + " discarded for GL_GPU_DISJOINT_EXT" : std::string();
    if (s.frames == 0) {
        o << "GPU timer: no frame measured" << dropped << "\n";
        return o.str();
    }
    o << "GPU time per pass (GL_TIME_ELAPSED_EXT), median of " << s.frames << " frame(s)" << dropped << ":\n";
    size_t width = 5;
    for (const PassMedian& p : s.passes) width = std::max(width, p.name.size());
    for (const PassMedian& p : s.passes) {
        o << "  " << p.name << std::string(width - p.name.size(), ' ') << "  " << ms3(p.ms) << " ms";
        if (p.frames != s.frames) o << "  (in " << p.frames << " of " << s.frames << " frames)";
        o << "\n";
    }
    o << "  total" << std::string(width - 5, ' ') << "  " << ms3(s.total_ms) << " ms/frame GPU\n";
    return o.str();
}

std::string pass_list(const GpuSummary& s) {
    std::string out;
    for (const PassMedian& p : s.passes) out += (out.empty() ? "" : "; ") + p.name + ": " + ms3(p.ms);
    return out;
}

}  // namespace penumbra::gl
