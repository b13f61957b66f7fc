// The one place that includes the GLES2 headers. Only files in src/gl/ include this.
#pragma once

#include <GLES2/gl2.h>
#include <GLES2/gl2ext.h>
