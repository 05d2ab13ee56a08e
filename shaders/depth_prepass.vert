#version 460
// Depth prepass vertex shader: the shared invariant scene vertex shader. The opaque and the
// masked pipelines both use it, and forward and transparent compile the same source.
#extension GL_GOOGLE_include_directive : require

#include "common/scene_vertex.glsl"
