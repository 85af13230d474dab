// The course's file loaders (docs/course-files.md) in one import, for the element and the worker that
// will use them: text in, typed arrays and plain data out, LoadError with url and line.
export { parseByu, type ByuResult } from './byu';
export { parseByuMesh, courseVertexNormals, type ByuMeshResult } from './byu-mesh';
export { parseByuBezier, netLength, MAX_BEZIER_DEGREE, type BezierOrder, type ByuBezierResult } from './byu-bezier';
export { parseCameraCfg, type CameraCfgResult, type CourseCamera } from './camera-cfg';
export { parseLightingTxt, type LightingTxtResult, type CourseLight, type CourseMaterial } from './lighting-txt';
export { sniffCourse, type CourseFormat } from './sniff-course';
export { courseBasis, courseView, courseProject, courseDepthRange, courseViewProjection } from '../../math/course-camera';
export { coursePhong } from '../../math/course-phong';
