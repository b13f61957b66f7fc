// The one place that includes the GLES2 headers. Only files in src/gl/ include this.
#pragma once

#ifdef __EMSCRIPTEN__
#define GL_GLEXT_PROTOTYPES 1  // the extensions' entry points (glDrawBuffersEXT), which Emscripten exports
#endif
#include <GLES2/gl2.h>
#include <GLES2/gl2ext.h>
