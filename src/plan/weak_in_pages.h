// What a browser page's module leaves out: a page links only the code its exercise can reach
// (web/CMakeLists.txt builds one module per page), and a reference that would pull in code every
// page does not need is weak there.
#pragma once

// Marks a redeclaration of a function in the file that reaches it only when some other part of
// the program names it (techniques.cpp's technique modules, the frame shapes' forward.cpp, the
// shadow map's layouts, the shader lab's splice): weak in the browser, where wasm-ld resolves a
// weak function that no linked object defines to a null address; an ordinary reference elsewhere.
// Such a function is read through a returned pointer (`&f`), null-checked, never called directly.
#ifdef __EMSCRIPTEN__
#define PENUMBRA_WEAK_IN_PAGES __attribute__((weak))
#else
#define PENUMBRA_WEAK_IN_PAGES
#endif
