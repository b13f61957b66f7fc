#include "scene/memory_budget.h"

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace penumbra::memory {

namespace {

std::atomic<std::size_t> g_budget{kDefaultBudget};
std::atomic<std::size_t> g_live{0};
std::atomic<std::size_t> g_peak{0};
thread_local const char* t_step = nullptr;

// What a refusal reports, kept without allocating (the heap is at its budget when they are set).
char g_subject[256] = "";
thread_local const char* t_refused_step = "";
thread_local std::size_t t_refused_need = 0;

// "2.0 GiB" into `out`.
void describe_into(std::size_t bytes, char* out, std::size_t size) {
    const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB"};
    double v = static_cast<double>(bytes);
    int u = 0;
    while (v >= 1024.0 && u < 4) {
        v /= 1024.0;
        ++u;
    }
    if (u == 0) std::snprintf(out, size, "%zu B", bytes);
    else std::snprintf(out, size, v < 10.0 ? "%.1f %s" : "%.0f %s", v, units[u]);
}

// Each thread keeps what it allocated and freed since its last flush and adds it to the shared
// count once it passes 64 KiB either way: an atomic add on every allocation slowed every
// allocating step. The shared count, and the peak, are so within 64 KiB a thread of the truth.
constexpr std::ptrdiff_t kFlush = 64 << 10;
thread_local std::ptrdiff_t t_pending = 0;

void flush() {
    const std::size_t live = g_live.fetch_add(static_cast<std::size_t>(t_pending), std::memory_order_relaxed) +
                             static_cast<std::size_t>(t_pending);
    t_pending = 0;
    for (std::size_t top = g_peak.load(std::memory_order_relaxed);
         live > top && !g_peak.compare_exchange_weak(top, live, std::memory_order_relaxed);) {
    }
}

}  // namespace

std::size_t budget() { return g_budget.load(std::memory_order_relaxed); }
void set_budget(std::size_t bytes) { g_budget.store(bytes, std::memory_order_relaxed); }
std::size_t in_use() { return g_live.load(std::memory_order_relaxed) + static_cast<std::size_t>(t_pending); }
std::size_t peak() {
    flush();  // this thread's own bytes first
    return g_peak.load(std::memory_order_relaxed);
}
void reset_peak() {
    flush();
    g_peak.store(g_live.load(std::memory_order_relaxed), std::memory_order_relaxed);
}

bool parse_size(const std::string& text, std::size_t& bytes) {
    // Digits, an optional fraction, an optional binary unit (K, M, G, T; then "iB", "B" or nothing).
    size_t i = 0;
    double whole = 0.0, scale = 1.0;
    bool digits = false;
    while (i < text.size() && text[i] >= '0' && text[i] <= '9') whole = whole * 10.0 + (text[i++] - '0'), digits = true;
    if (i < text.size() && text[i] == '.') {
        ++i;
        double place = 0.1;
        while (i < text.size() && text[i] >= '0' && text[i] <= '9') whole += place * (text[i++] - '0'), place /= 10.0, digits = true;
    }
    if (!digits) return false;
    std::string unit = text.substr(i);
    for (char& c : unit) c = static_cast<char>(c >= 'a' && c <= 'z' ? c - 'a' + 'A' : c);
    const char* prefixes = "KMGT";
    if (!unit.empty() && std::strchr(prefixes, unit[0])) {
        for (const char* p = prefixes; *p; ++p) {
            scale *= 1024.0;
            if (*p == unit[0]) break;
        }
        unit.erase(0, 1);
        if (unit == "IB" || unit == "B") unit.clear();
    } else if (unit == "B") {
        unit.clear();
    }
    if (!unit.empty()) return false;
    const double v = whole * scale;
    if (!(v < 1.8e19)) return false;
    bytes = static_cast<std::size_t>(v);
    return true;
}

bool budget_from_env(std::string& error) {
    const char* v = std::getenv(kBudgetVariable);
    if (!v || !*v) {
        set_budget(kDefaultBudget);
        return true;
    }
    const std::string text(v);
    std::size_t bytes = 0;
    if (text == "none" || (parse_size(text, bytes) && bytes == 0)) {
        set_budget(0);
        return true;
    }
    if (!parse_size(text, bytes) || bytes < (std::size_t{1} << 20)) {
        error = std::string(kBudgetVariable) + "=" + text +
                ": not a memory size of at least 1M (a byte count, or with K, M, G or T: 2G, 512M, 1.5GiB; 0 or none: no budget)";
        return false;
    }
    set_budget(bytes);
    return true;
}

void set_subject(const std::string& text) { std::snprintf(g_subject, sizeof g_subject, "%s", text.c_str()); }

#ifndef __EMSCRIPTEN__
Guard::Guard(const char* step) : outer_(t_step) { t_step = step; }
Guard::~Guard() { t_step = outer_; }
#endif

const char* OverBudget::what() const noexcept {
    static thread_local char message[640];
    char limit[32], need[32];
    describe_into(budget(), limit, sizeof limit);
    describe_into(t_refused_need, need, sizeof need);
    std::snprintf(message, sizeof message,
                  "%s%s%s%s needs more than the memory budget of %s (refused at %s); set %s to raise it",
                  t_refused_step, g_subject[0] ? " (" : "", g_subject, g_subject[0] ? ")" : "", limit, need,
                  kBudgetVariable);
    return message;
}

bool on_allocate(std::size_t bytes) {
    const std::size_t limit = budget();
    if (t_step && limit) {
        const std::size_t live = g_live.load(std::memory_order_relaxed) + static_cast<std::size_t>(t_pending) + bytes;
        if (live > limit) {
            t_refused_step = t_step;
            t_refused_need = live;
            return false;
        }
    }
    t_pending += static_cast<std::ptrdiff_t>(bytes);
    if (t_pending > kFlush) flush();
    return true;
}

void on_free(std::size_t bytes) {
    t_pending -= static_cast<std::ptrdiff_t>(bytes);
    if (t_pending < -kFlush) flush();
}

}  // namespace penumbra::memory
