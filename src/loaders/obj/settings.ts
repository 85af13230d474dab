// The statements that name things or set what the next faces are drawn with: o, g, s, usemtl,
// mtllib; any other keyword is a warning, once per keyword.
import { addUnique, splitGroups, splitMtllib } from './names';
import { FLAT } from './raw';
import { shown, type Warnings } from '../warnings';

/** Smoothing slot before any `s`: files that never say `s` (scans) are meant to be smooth. */
const DEFAULT_SMOOTH = 0;

/** Statements read and deliberately not drawn, reported once each without "unknown". */
const UNSUPPORTED = new Set(['l', 'p', 'vp', 'curv', 'curv2', 'surf', 'cstype', 'deg', 'bmat', 'step', 'parm',
  'trim', 'hole', 'scrv', 'sp', 'end', 'con', 'mg', 'bevel', 'c_interp', 'd_interp', 'lod', 'usemap', 'maplib',
  'shadow_obj', 'trace_obj', 'ctech', 'stech', 'call', 'csh']);

/** The names read so far, and the material and smoothing slot the next faces get. */
export class Settings {
  readonly materials: (string | null)[] = [null];
  readonly objects: string[] = [];
  readonly groupNames: string[] = [];
  readonly mtllibs: string[] = [];
  /** Slot in `materials`. */
  material = 0;
  /** FLAT, or a slot per `s` name. */
  smooth = DEFAULT_SMOOTH;
  private readonly materialSlot = new Map<string, number>();
  private readonly smoothSlot = new Map<string, number>();
  private readonly seenObjects = new Set<string>();
  private readonly seenGroups = new Set<string>();
  private readonly seenLibs = new Set<string>();

  /** The statement of `keyword`, the cursor past its blanks. */
  statement(keyword: string, sc: { restOfLine(): string }, line: number, warnings: Warnings): void {
    switch (keyword) {
      case 'o':
        addUnique(this.objects, this.seenObjects, [sc.restOfLine()]);
        break;
      case 'g':
        addUnique(this.groupNames, this.seenGroups, splitGroups(sc.restOfLine()));
        break;
      case 's': {
        const arg = sc.restOfLine().toLowerCase();
        if (arg === 'off' || arg === '0' || arg === '') this.smooth = FLAT;
        else {
          if (!this.smoothSlot.has(arg)) this.smoothSlot.set(arg, this.smoothSlot.size + 1);
          this.smooth = this.smoothSlot.get(arg)!;
        }
        break;
      }
      case 'usemtl': {
        const name = sc.restOfLine();
        if (!this.materialSlot.has(name)) {
          this.materialSlot.set(name, this.materials.length);
          this.materials.push(name);
        }
        this.material = this.materialSlot.get(name)!;
        break;
      }
      case 'mtllib':
        addUnique(this.mtllibs, this.seenLibs, splitMtllib(sc.restOfLine()));
        break;
      default:
        if (UNSUPPORTED.has(keyword)) warnings.addOncePerKeyword(keyword, line, `${shown(keyword)} statements are not supported; ignored`);
        else warnings.addOncePerKeyword(keyword.slice(0, 64), line, `unknown statement ${shown(keyword)}; ignored`);
    }
  }
}
