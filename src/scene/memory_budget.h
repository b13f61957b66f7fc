// The memory budget: how much heap one run of a native program (penumbra, penumbra-desktop) may
// hold. Those programs count every operator new (platform/heap_accounting.cpp); the steps that
// grow with the scene (loading it, planning a frame) run inside a Guard, where an allocation that
// would pass the budget throws OverBudget, which names the step, the scene and the budget. So a
// scene too large fails with one line, never the kernel's kill. Outside a guard nothing is
// refused: a driver's own allocations (an LLVM compile in llvmpipe) must never throw. Where
// nothing counts (the pages, the tests) the budget is never reached. Plain C++; no GL.
#pragma once

#include <cstddef>
#include <new>
#include <string>

namespace penumbra::memory {

inline constexpr std::size_t kDefaultBudget = std::size_t{2} << 30;  // 2 GiB
inline constexpr const char* kBudgetVariable = "PENUMBRA_MEMORY_BUDGET";

// The budget in bytes; 0: none.
std::size_t budget();
void set_budget(std::size_t bytes);
// PENUMBRA_MEMORY_BUDGET when set and not empty ("2G", "512M", "1.5GiB", "300000000"; "0" or
// "none": no budget), else kDefaultBudget. false with `error` (one line) for a value it cannot read.
bool budget_from_env(std::string& error);
// "2G" (binary units: K, M, G, T, with or without "iB"), "1.5GiB", a byte count; false otherwise.
bool parse_size(const std::string& text, std::size_t& bytes);

// The heap the counting operator new holds now, and the most it held since reset_peak() (0
// where nothing counts).
std::size_t in_use();
std::size_t peak();
void reset_peak();

// What the run is working on, for OverBudget's message: "pile:100000 (100,001 objects, 600,002
// triangles)". Set where a scene is opened.
void set_subject(const std::string& text);

// A step whose allocations may be refused: while one is alive on this thread, an allocation
// that would take the heap past the budget throws OverBudget naming `step` ("planning the frame").
#ifdef __EMSCRIPTEN__
// The pages count nothing (their heap is the browser's to bound): a guard is nothing there, and
// this file's code stays out of their modules.
class Guard {
public:
    explicit Guard(const char*) {}
};
#else
class Guard {
public:
    explicit Guard(const char* step);
    ~Guard();
    Guard(const Guard&) = delete;
    Guard& operator=(const Guard&) = delete;

private:
    const char* outer_;
};
#endif

// Thrown by the counting operator new inside a Guard. what() is one line, made without allocating.
class OverBudget : public std::bad_alloc {
public:
    const char* what() const noexcept override;
};

// For the counting operator new: the bytes of a new block (false: refused, throw OverBudget) and
// of a freed one.
bool on_allocate(std::size_t bytes);
void on_free(std::size_t bytes);

}  // namespace penumbra::memory
