#version 300 es
// Opaque objects. Positions are relative to the eye (float64-composed on the CPU) so a
// camera far from the origin keeps its precision. CLIP_PLANE: reflection pass only.
// SHADING_PHONG lights per fragment; SHADING_GOURAUD per vertex, interpolated;
// SHADING_FLAT once per triangle, from its face normal at its centroid: flat meshes carry both
// on each of a triangle's three vertices (src/scene/geometry/flat.ts), so all three agree.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;
#ifdef SHADING_FLAT
layout(location = 3) in vec3 aCentroid;
#endif
#ifdef NORMAL_MAP
layout(location = 4) in vec4 aTangent; // xyz along u, w the bitangent's side (docs/gltf.md#the-normal-map)
out vec4 vTangent;
#endif
#ifdef VERTEX_COLORS
layout(location = 5) in vec3 aColor; // multiplies a glTF material's base colour (docs/gltf.md#vertex-colours)
out vec3 vColor;
#endif

uniform highp mat4 uModelViewProjection;
uniform highp mat4 uModelRelative;
uniform mat3 uNormalMatrix;
#ifdef CLIP_PLANE
uniform highp vec4 uClipPlane;
#endif

out vec2 vUv;
#ifndef MAPPING_UV
out vec3 vObjPos;     // object space, for the computed texture mappings (standard.frag)
out vec3 vObjNormal;
#endif
#if defined(SHADING_PHONG)
out highp vec3 vRelPos;
out vec3 vNormal;
#elif defined(SHADING_FLAT)
flat out vec3 vLightA;
flat out vec3 vLightS;
#else
out vec3 vLightA;
out vec3 vLightS;
#endif
#if defined(CLIP_PLANE) && !defined(CLIP_DISTANCE)
out highp float vClipDistance;
#endif

void main() {
  vec4 rel = uModelRelative * vec4(aPosition, 1.0);
  vUv = aUv;
#ifndef MAPPING_UV
  vObjPos = aPosition;
  vObjNormal = aNormal;
#endif
#if defined(SHADING_PHONG)
  vRelPos = rel.xyz;
  vNormal = uNormalMatrix * aNormal;
#ifdef NORMAL_MAP
  vTangent = vec4(mat3(uModelRelative) * aTangent.xyz, aTangent.w);
#endif
#ifdef VERTEX_COLORS
  vColor = aColor;
#endif
#elif defined(SHADING_FLAT)
  vec3 faceCentre = (uModelRelative * vec4(aCentroid, 1.0)).xyz; // "centroid" is a GLSL ES 3.0 keyword
  vec3 v = viewVector(faceCentre);
  blinnPhong(facing(normalize(uNormalMatrix * aNormal), v), v, faceCentre, vLightA, vLightS);
#else
  vec3 v = viewVector(rel.xyz);
  blinnPhong(facing(normalize(uNormalMatrix * aNormal), v), v, rel.xyz, vLightA, vLightS);
#endif
#ifdef CLIP_PLANE
  float clipDistance = dot(uClipPlane, vec4(rel.xyz, 1.0));
#ifdef CLIP_DISTANCE
  gl_ClipDistance[0] = clipDistance;
#else
  vClipDistance = clipDistance;
#endif
#endif
  gl_Position = uModelViewProjection * vec4(aPosition, 1.0);
}
