#version 460
// Forward vertex shader: the same source as the prepass's (common/scene_vertex.glsl), so an
// EQUAL depth test matches bit for bit. NON_INVARIANT=1 is the invariant=off experiment.
#extension GL_GOOGLE_include_directive : require

#include "common/scene_vertex.glsl"
