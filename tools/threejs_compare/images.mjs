// PNG helpers of threejs_compare: saving a read-back canvas, a visibility image's histogram, and
// the difference between two visibility images.
import { readFileSync, writeFileSync } from 'node:fs';
import { PNG } from 'pngjs';

export function savePng(px, file) {
  const png = new PNG({ width: px.width, height: px.height });
  png.data = Buffer.from(px.data);
  writeFileSync(file, PNG.sync.write(png));
}

// Lit, dark and in-between pixels of a visibility image (red channel, 255 lit).
export function histogram(px) {
  let lit = 0, dark = 0, grey = 0;
  for (let i = 0; i < px.width * px.height; ++i) {
    const v = px.data[4 * i];
    if (v >= 250) ++lit; else if (v <= 5) ++dark; else ++grey;
  }
  return { lit, dark, grey, n: px.width * px.height };
}

// Two visibility images (red channel): the fraction of pixels more than 8 levels apart, the mean |difference|.
export function imageDiff(fileA, fileB) {
  const a = PNG.sync.read(readFileSync(fileA));
  const b = PNG.sync.read(readFileSync(fileB));
  let differing = 0, sum = 0;
  const n = a.width * a.height;
  for (let i = 0; i < n; ++i) {
    const d = Math.abs(a.data[4 * i] - b.data[4 * i]);
    sum += d;
    if (d > 8) ++differing;
  }
  return { differing, fraction: differing / n, meanLevels: sum / n };
}
