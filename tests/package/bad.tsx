// Consumer test (scripts/check-package.mjs): each line marked BAD must be a type error.
import 'glass-plane-scene/react';

export const bad = (
  <>
    <glass-plane-scene fresnel="fresnel" /> {/* BAD */}
    <glass-plane-scene renderer="gpu" /> {/* BAD */}
    <glass-plane-scene projection="fisheye" /> {/* BAD */}
    <glass-plane-scene debug-view="normals" /> {/* BAD */}
    <glass-plane-scene shading="smooth" /> {/* BAD */}
    <glass-plane-scene samples={3} /> {/* BAD */}
    <glass-plane-scene transparency="half" /> {/* BAD */}
    <glass-object mapping="planar" /> {/* BAD */}
    <glass-object shape="torus" /> {/* BAD */}
  </>
);
