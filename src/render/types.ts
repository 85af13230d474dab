// The frame's state and reports live in frame/types.ts (plain data both renderers share); the
// renderer's callers may keep importing them from here.
export type * from '../frame/types';
