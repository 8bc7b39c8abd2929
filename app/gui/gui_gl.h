// The GL the GUI itself calls (framebuffers, blits, read-back): core-profile prototypes, resolved by
// linking libGL (GLVND exports every core entry point). The renderer loads its own table instead.
// Include this before any header that includes GL/glcorearb.h (its include guard would hide the prototypes).
#pragma once
#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/glcorearb.h>
