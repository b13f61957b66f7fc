// Extension entry points of the current context (inside src/gl only): looked up through the
// platform by probe_caps (gl/caps.h); null where the context has none. Emscripten links them.
#pragma once

#include "gl/gl_headers.h"

namespace penumbra::gl {

struct EntryPoints {
    PFNGLDRAWBUFFERSEXTPROC draw_buffers = nullptr;  // glDrawBuffersEXT (EXT_draw_buffers)
    // EXT_disjoint_timer_query (gl/timer.h): all of them, or none.
    PFNGLGENQUERIESEXTPROC gen_queries = nullptr;
    PFNGLDELETEQUERIESEXTPROC delete_queries = nullptr;
    PFNGLBEGINQUERYEXTPROC begin_query = nullptr;
    PFNGLENDQUERYEXTPROC end_query = nullptr;
    PFNGLGETQUERYIVEXTPROC get_query_iv = nullptr;
    PFNGLGETQUERYOBJECTUIVEXTPROC get_query_object_uiv = nullptr;
    PFNGLGETQUERYOBJECTUI64VEXTPROC get_query_object_ui64v = nullptr;
};
// The current context's, as the last probe_caps found them.
EntryPoints& entry_points();

}  // namespace penumbra::gl
