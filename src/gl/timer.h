// GPU time per pass: EXT_disjoint_timer_query's GL_TIME_ELAPSED_EXT queries, one begin/end around
// each pass of a frame that draws (only one such query may be active at a time: passes are timed
// one after another, never nested). The results are read later without waiting for the GPU: a
// frame's queries stay pending in a small ring until they are available (polled when a later frame
// begins), or until take(true) waits for them at the end of a run. The frames read at a time when
// GL_GPU_DISJOINT_EXT is set (the GPU's clock jumped: a power state, a reset) are discarded, and so
// are those still pending then. WebGL 1 exposes the same extension as EXT_disjoint_timer_query.
#pragma once

#include <cstdint>
#include <deque>
#include <string>
#include <utility>
#include <vector>

namespace penumbra::gl {

struct PassTime {
    std::string name;  // the pass's (render::Pass::name)
    double ms = 0.0;   // GPU time between its begin and its end
};

// One frame's GPU times: each timed pass, in the order they ran (a skipped pass has none).
struct GpuFrame {
    std::vector<PassTime> passes;
    double total_ms() const;
};

class PassTimer {
public:
    // `available`: the context has EXT_disjoint_timer_query with a non-zero TIME_ELAPSED counter
    // and its entry points (Caps::timer_query, gl/entry_points.h). Unavailable, every call is a no-op.
    explicit PassTimer(bool available = false);
    ~PassTimer();
    PassTimer(const PassTimer&) = delete;
    PassTimer& operator=(const PassTimer&) = delete;

    bool available() const { return available_; }
    // Off until enabled (a frame then makes no query); switch it between frames.
    void enable(bool on) { enabled_ = on; }
    bool enabled() const { return enabled_ && available_; }

    // The renderer's hook: a frame begins, each pass that draws is bracketed, the frame ends. A
    // frame begun while the last one never ended (a pass threw) drops the unfinished one.
    void begin_frame();
    void begin_pass(const std::string& name);
    void end_pass();
    void end_frame();

    // Several renderer frames timed as one (an app's frame that draws two plans, each through
    // Renderer::run): between begin_group and end_group, begin_frame and end_frame only end the
    // pass timed. begin_group starts the frame as begin_frame does (dropping an unfinished one: a
    // group whose plan threw), end_group ends it. An app that groups its frames groups each one.
    void begin_group();
    void end_group();
    // Put before the names of the passes begun from now on ("texture: " + "camera"); "" for none.
    void set_prefix(std::string prefix) { prefix_ = std::move(prefix); }

    // The frames whose results have arrived since the last take, oldest first, without waiting;
    // with `wait`, every frame still pending too (glGetQueryObject waits for the GPU).
    std::vector<GpuFrame> take(bool wait = false);
    int pending() const { return static_cast<int>(pending_.size()); }
    int discarded() const { return discarded_; }  // frames dropped for GL_GPU_DISJOINT_EXT

    // Frames left pending before begin_frame waits for the oldest (the GPU is that far behind).
    static constexpr int kRing = 4;
    // Frames kept for take(); older ones are dropped when nobody takes them (a page left running).
    static constexpr int kKept = 1024;

private:
    struct Frame {
        std::vector<std::pair<std::string, std::uint32_t>> queries;  // pass name, query
        bool tainted = false;  // a disjoint event was seen while it was pending
    };
    std::uint32_t make_query();
    bool ready(const Frame& f) const;
    void poll(bool wait, bool at_least_one = false);
    void drop_current();

    bool available_ = false;
    bool enabled_ = false;
    bool in_frame_ = false;
    bool in_pass_ = false;
    bool grouped_ = false;  // in a group: the renderer's frames join the group's
    std::string prefix_;
    Frame current_;
    std::deque<Frame> pending_;
    std::deque<GpuFrame> done_;
    std::vector<std::uint32_t> free_;  // queries whose results were read, for reuse
    int discarded_ = 0;
};

// ---- several frames at once: what render -v and bench report ------------------------------------

struct PassMedian {
    std::string name;  // a pass's name; the second pass of the same name in a frame is "name #2"
    double ms = 0.0;   // the median over the frames it ran in
    int frames = 0;    // how many of them
};
struct GpuSummary {
    std::vector<PassMedian> passes;  // in the order they first ran
    double total_ms = 0.0;           // the median of the frames' totals
    int frames = 0;                  // frames measured (0: none: no timer, or all discarded)
};
GpuSummary summarize(const std::vector<GpuFrame>& frames);

// The summary for people, one pass a line after a heading; "GPU timer: not available on this
// context" when `available` is false, and a line saying so when no frame was measured.
std::string describe(const GpuSummary& s, bool available, int discarded = 0);
// "shadow-map: 0.412; camera: 1.203" (ms, 3 decimals): the bench's per-pass cell.
std::string pass_list(const GpuSummary& s);

}  // namespace penumbra::gl
