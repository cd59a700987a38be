// OpenGL 4.5 core declarations. The entry points come from the vendor-neutral libOpenGL
// (EGL build) or from libOSMesa (OSMesa build); no hand-written loader.
#pragma once

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/gl.h>
#include <GL/glext.h>
