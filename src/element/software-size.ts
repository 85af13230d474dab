/** Largest side of a software frame (the CPU's cost grows with the pixels; 4096 is a 4K canvas's side). */
export const SOFTWARE_MAX_SIZE = 4096;
