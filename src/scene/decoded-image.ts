// An image's pixels as plain data, as every renderer takes them (no DOM, no GL).

/** Decoded pixels as a canvas or an image decoder gives them: RGBA8, top row first. */
export interface DecodedImage {
  width: number;
  height: number;
  data: Uint8Array | Uint8ClampedArray;
}

/**
 * The decoded images a scene names, by URL: every renderer's third argument (ARCHITECTURE.md,
 * "How a frame flows"). A material whose URL is not in it draws with the procedural texture.
 */
export type SceneImages = ReadonlyMap<string, DecodedImage>;
