// What a texture read covers (docs/refinement.md#footprints), shared by the glass and every material (prepended after the
// #defines, to both stages): a pixel, or 1/side of one in a strata frame, whose reads are over its stratum. The screen
// derivatives are scaled, not the level biased: the GPU filters these textures anisotropically, and a bias of −log2(side)
// moves the level only (the taps still span the pixel along a slant: the glass far away 41.0 dB after ten frames, 53.0).
precision highp float;
uniform float uFootprint;

/** `map` at uv, read over uFootprint of a pixel (in the vertex stage, where nothing calls it: level 0). */
vec4 mapRead(sampler2D map, vec2 uv) {
#ifdef FRAGMENT_STAGE
  if (uFootprint == 1.0) return texture(map, uv);
  return textureGrad(map, uv, dFdx(uv) * uFootprint, dFdy(uv) * uFootprint);
#else
  return textureLod(map, uv, 0.0);
#endif
}
