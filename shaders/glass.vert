#version 300 es
// The glass rectangle; also projects each vertex with the mirrored camera for the reflection lookup.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;

uniform highp mat4 uModelViewProjection;
uniform highp mat4 uModelRelative;
uniform highp mat4 uReflectionViewProjection;
uniform mat3 uNormalMatrix;

out highp vec3 vRelPos;
out vec3 vNormal;
out vec2 vUv;
out highp vec4 vReflectionClip;

void main() {
  vRelPos = (uModelRelative * vec4(aPosition, 1.0)).xyz;
  vNormal = uNormalMatrix * aNormal;
  vUv = aUv;
  vReflectionClip = uReflectionViewProjection * vec4(aPosition, 1.0);
  gl_Position = uModelViewProjection * vec4(aPosition, 1.0);
}
