// What the element's message part says for each failure (docs/element.md#failure-behaviour), in a chunk of its own that
// Failure fetches when something fails: a page that draws never loads it.
import type { ErrorType } from './types';

export const FAILURE_MESSAGES: Record<ErrorType, string> = {
  'webgl2-unavailable': 'WebGL2 is not available here, so the glass scene cannot be shown.',
  shader: 'The glass scene could not be drawn: a shader failed to compile.',
  'context-lost': 'The graphics context was lost; waiting for it to come back.',
  load: 'The glass scene could not be loaded.',
};
