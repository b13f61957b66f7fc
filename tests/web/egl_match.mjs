// web.egl_match: the same frame (fixed t, same settings, 512x512) from the browser (WebGL 1 on
// SwiftShader) and from headless EGL (`penumbra render`, Mesa llvmpipe) agree: the mean absolute
// difference (max over RGB, in 8-bit levels) is at most MAX_MEAN and at most MAX_FRACTION of the
// pixels differ by more than LEVELS. Rasterisers round differently at silhouette edges and in the
// marble's mipmap selection; a wrong matrix, encoding or bias would move whole regions.
// usage: egl_match.mjs PENUMBRA_CLI OUT_DIR
import { execFileSync } from 'node:child_process';
import { mkdirSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { PNG } from 'pngjs';
import { runTest, openPage, frameAt, compare, check, savePng } from './harness.mjs';

const [cli, outDir] = process.argv.slice(2);
if (!cli || !outDir) throw new Error('usage: egl_match.mjs PENUMBRA_CLI OUT_DIR');
const T = 0.6;
const MAX_MEAN = 1.5;
const LEVELS = 16;
const MAX_FRACTION = 0.005;

// W09P2c's page keeps the course's map, the table in it (its default light-fit=tight); the
// command line's default is the shadows fit, so its cases say tight.
const CASES = [
  { name: 'w09p2c-rgba-hard', page: 'w09p2c', query: 'map-view=off&encoding=rgba&filter=hard&bias=sheet',
    args: ['--light-fit', 'tight', '--encoding', 'rgba', '--filter', 'hard'] },
  { name: 'w09p2c-r8-pcf4x4', page: 'w09p2c', query: 'map-view=off&encoding=r8&filter=pcf4x4&bias=sheet',
    args: ['--light-fit', 'tight', '--encoding', 'r8', '--filter', 'pcf4x4'] },
  { name: 'w09p2c-depthtex-visibility', page: 'w09p2c', query: 'map-view=off&encoding=depthtex&filter=hard&aov=visibility',
    args: ['--light-fit', 'tight', '--encoding', 'depthtex', '--filter', 'hard', '--aov', 'visibility'] },
  { name: 'w09p2c-auto-mediump-pcf4x4-visibility', page: 'w09p2c',
    query: 'map-view=off&encoding=rgba&filter=pcf4x4&bias=auto&precision=mediump&aov=visibility',
    args: ['--light-fit', 'tight', '--encoding', 'rgba', '--filter', 'pcf4x4', '--bias', 'auto', '--precision', 'mediump', '--aov', 'visibility'] },
  { name: 'w09p1-planar', page: 'w09p1', query: '', args: ['--technique', 'planar'] },
];

await runTest('web.egl_match', async ({ server, browser }) => {
  mkdirSync(outDir, { recursive: true });
  const failures = [];
  for (const c of CASES) {
    const eglFile = path.join(outDir, `${c.name}.egl.png`);
    execFileSync(cli, ['render', '--time', String(T), '--size', '512x512', '--map-size', '1024', ...c.args, '--out', eglFile]);
    const ref = PNG.sync.read(readFileSync(eglFile));
    const { page, context, problems } = await openPage(browser, `${server.url}/${c.page}.html?${c.query}`);
    const px = await frameAt(page, T);
    savePng(px, path.join(outDir, `${c.name}.browser.png`));
    const d = compare(px, { width: ref.width, height: ref.height, data: ref.data }, LEVELS);
    const line = `${c.name}: mean |diff| ${d.mean.toFixed(3)} levels (max ${d.max}), ` +
                 `${(100 * d.fraction).toFixed(3)}% of pixels differ by > ${LEVELS}`;
    console.log(line);
    if (d.mean > MAX_MEAN || d.fraction > MAX_FRACTION)
      failures.push(`${line}; allowed mean ${MAX_MEAN}, ${100 * MAX_FRACTION}% (images in ${outDir})`);
    if (problems.length) failures.push(`${c.name}: ${problems.join('; ')}`);
    await context.close();
  }
  check(failures.length === 0, failures.join('\n'));
});
