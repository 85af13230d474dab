// The course's camera `.cfg` and `iluminacao.txt` (docs/course-files.md#lighting-file) as the element loads them: fetched
// (abortable, with progress), parsed, warnings as console-ready text. Loaded on demand, in the
// same chunk as the course's parsers.
import { decodeText } from '../../loaders/decode-text';
import { warningText } from '../../loaders/load-error';
import { parseCameraCfg, type CourseCamera } from '../../loaders/course/camera-cfg';
import { parseLightingTxt, type CourseLight, type CourseMaterial } from '../../loaders/course/lighting-txt';
import { fetchBytes, type Progress } from './model-fetch';

export type CourseFileKind = 'camera' | 'lighting';

export interface LoadedCamera {
  url: string;
  camera: CourseCamera;
  warnings: string[];
}

export interface LoadedLighting {
  url: string;
  light: CourseLight;
  material: CourseMaterial;
  warnings: string[];
}

export type LoadedCourseFile<K extends CourseFileKind> = K extends 'camera' ? LoadedCamera : LoadedLighting;

export async function loadCourseFile<K extends CourseFileKind>(
  kind: K, url: string, signal: AbortSignal, onProgress: (p: Progress) => void,
): Promise<LoadedCourseFile<K>> {
  const text = decodeText(await fetchBytes(url, signal, onProgress));
  signal.throwIfAborted();
  if (kind === 'camera') {
    const { warnings, ...camera } = parseCameraCfg(text, { url });
    return { url, camera, warnings: warnings.map((w) => warningText(url, w)) } as LoadedCourseFile<K>;
  }
  const { light, material, warnings } = parseLightingTxt(text, { url });
  return { url, light, material, warnings: warnings.map((w) => warningText(url, w)) } as LoadedCourseFile<K>;
}
