// Extension entry points of the current context (inside src/gl only): looked up through the
// platform by probe_caps (gl/caps.h); null where the context has none. Emscripten links them.
#pragma once

#include "gl/gl_headers.h"

namespace penumbra::gl {

struct EntryPoints {
    PFNGLDRAWBUFFERSEXTPROC draw_buffers = nullptr;  // glDrawBuffersEXT (EXT_draw_buffers)
};
// The current context's, as the last probe_caps found them.
EntryPoints& entry_points();

}  // namespace penumbra::gl
