// The native programs' operator new and delete: malloc and free, each block's usable size counted
// (scene/memory_budget.h), and an allocation inside a memory::Guard refused past the budget with
// memory::OverBudget. Linked into penumbra and penumbra-desktop only: a library must not replace a
// program's allocator, and the pages have the browser's own limits.
#include <malloc.h>

#include <cstdlib>
#include <new>

#include "scene/memory_budget.h"

namespace {

void* counted(std::size_t size, std::size_t align) {
    if (size == 0) size = 1;
    void* p = nullptr;
    if (align <= alignof(std::max_align_t)) p = std::malloc(size);
    else if (posix_memalign(&p, align, size) != 0) p = nullptr;
    if (!p) throw std::bad_alloc();
    if (!penumbra::memory::on_allocate(malloc_usable_size(p))) {
        std::free(p);
        throw penumbra::memory::OverBudget();
    }
    return p;
}

void* counted_nothrow(std::size_t size, std::size_t align) noexcept {
    try {
        return counted(size, align);
    } catch (...) {
        return nullptr;
    }
}

void release(void* p) noexcept {
    if (!p) return;
    penumbra::memory::on_free(malloc_usable_size(p));
    std::free(p);
}

}  // namespace

void* operator new(std::size_t n) { return counted(n, 0); }
void* operator new[](std::size_t n) { return counted(n, 0); }
void* operator new(std::size_t n, std::align_val_t a) { return counted(n, static_cast<std::size_t>(a)); }
void* operator new[](std::size_t n, std::align_val_t a) { return counted(n, static_cast<std::size_t>(a)); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept { return counted_nothrow(n, 0); }
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept { return counted_nothrow(n, 0); }
void* operator new(std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
    return counted_nothrow(n, static_cast<std::size_t>(a));
}
void* operator new[](std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
    return counted_nothrow(n, static_cast<std::size_t>(a));
}

void operator delete(void* p) noexcept { release(p); }
void operator delete[](void* p) noexcept { release(p); }
void operator delete(void* p, std::size_t) noexcept { release(p); }
void operator delete[](void* p, std::size_t) noexcept { release(p); }
void operator delete(void* p, std::align_val_t) noexcept { release(p); }
void operator delete[](void* p, std::align_val_t) noexcept { release(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { release(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { release(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { release(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { release(p); }
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept { release(p); }
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept { release(p); }
