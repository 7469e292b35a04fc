// OpenGL entry points for the renderer: GLVND's libOpenGL with the core-profile prototypes
// (DESIGN §7). The same symbols serve an EGL context (off-screen) and a GLFW window, so no
// loader is needed. A file that also includes GLFW must define GLFW_INCLUDE_NONE first.
#pragma once

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/glcorearb.h>
