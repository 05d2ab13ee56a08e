#version 460
// Transparent vertex shader: the same source as the prepass's, so decals lying exactly on a
// wall get the wall's depth and pass GREATER_OR_EQUAL against it.
#extension GL_GOOGLE_include_directive : require

#include "common/scene_vertex.glsl"
