// The children's names, and the event a child fires when its part of the scene changes: what the
// scene element needs of its children before their chunk (children/child-elements.ts) has loaded.
export const OBJECT_TAG = 'glass-object';
export const LIGHT_TAG = 'glass-light';
export const CHILD_CHANGE = 'glass-plane-scene-child-change';
