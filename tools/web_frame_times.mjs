// Median ms/frame of each exercise page in headless Chromium (WebGL 1 on SwiftShader), 512x512
// canvas, map size 1024, for the hard and pcf4x4 filters (W09P2c is the page with a shadow map; the
// filter does not apply to the others, which are measured once). Both motions on, so the shadow map
// (and W09P2b's FBO) is redrawn every frame.
//   a) the page's own readout: each frame drawn and waited for (a one-pixel readback: WebGL's
//      finish() only flushes in Chromium), median of the last 60
//      frames of the animation loop (requestAnimationFrame, 60 Hz);
//   b) back to back: N frames drawn by the test hook in one JavaScript loop, median of the frames.
// Each figure is the median over ROUNDS interleaved rounds; a second table gives each round's figures.
// pcf4x4 is measured with the early exit (the default) and with the full kernel (pcf-kernel=full).
// usage: node tools/web_frame_times.mjs [ROUNDS] [FRAMES] [MATCH]   (needs build-web/site; prints
// Markdown; MATCH: only the rows whose settings contain it, e.g. pcf4x4)
import { serve, launch, openPage, siteDir, waitFrames } from '../tests/web/harness.mjs';

const rounds = Number(process.argv[2] || 5);
const frames = Number(process.argv[3] || 60);
const CONFIGS = [
  { page: 'w09p1', label: 'planar (filter n/a)', query: '' },
  { page: 'w09p2a', label: 'no shadows, perspective light view (filter n/a)', query: 'projection=persp' },
  { page: 'w09p2b', label: 'FBO 1024 + camera (filter n/a)', query: 'map-size=1024' },
  { page: 'w09p2c', label: 'rgba hard, map 1024, map view on', query: 'encoding=rgba&filter=hard&map-size=1024&map-view=on' },
  { page: 'w09p2c', label: 'rgba pcf4x4 early-exit, map 1024, map view on', query: 'encoding=rgba&filter=pcf4x4&map-size=1024&map-view=on' },
  { page: 'w09p2c', label: 'rgba pcf4x4 full, map 1024, map view on', query: 'encoding=rgba&filter=pcf4x4&pcf-kernel=full&map-size=1024&map-view=on' },
  { page: 'w09p2c', label: 'r8 hard, map 1024, map view on', query: 'encoding=r8&filter=hard&map-size=1024&map-view=on' },
  { page: 'w09p2c', label: 'r8 pcf4x4 early-exit, map 1024, map view on', query: 'encoding=r8&filter=pcf4x4&map-size=1024&map-view=on' },
  { page: 'w09p2c', label: 'r8 pcf4x4 full, map 1024, map view on', query: 'encoding=r8&filter=pcf4x4&pcf-kernel=full&map-size=1024&map-view=on' },
].filter((c) => !process.argv[4] || c.label.includes(process.argv[4]));
const median = (v) => { const s = [...v].sort((a, b) => a - b); const n = s.length; return n % 2 ? s[(n - 1) / 2] : (s[n / 2 - 1] + s[n / 2]) / 2; };

const server = await serve(siteDir());
const browser = await launch();
const results = CONFIGS.map(() => ({ readout: [], loop: [] }));
let renderer = '';
for (let r = 0; r < rounds; ++r) {
  for (const [i, c] of CONFIGS.entries()) {
    const { page, context } = await openPage(browser, `${server.url}/${c.page}.html?${c.query}`);
    await waitFrames(page, 70);
    const s = await page.evaluate(() => window.penumbra.state());
    renderer = s.renderer;
    if (s.width !== 512 || s.height !== 512) throw new Error(`canvas ${s.width}x${s.height}`);
    results[i].readout.push(s.ms);
    const loop = await page.evaluate((n) => {
      window.penumbra.pause();
      const out = [];
      for (let k = 0; k < n; ++k) {
        window.penumbra.setTime(k / 60);  // the light and the teapot move: the map is redrawn
        const t0 = performance.now();
        window.penumbra.renderNow();
        out.push(performance.now() - t0);
      }
      return out;
    }, frames);
    results[i].loop.push(median(loop));
    await context.close();
  }
  console.error(`round ${r + 1}/${rounds} done`);
}
await browser.close();
await server.close();
console.log(`Headless Chromium (${renderer}, SwiftShader), 512x512 canvas; median over ${rounds} rounds.\n`);
console.log('| page | settings | readout ms/frame (rAF loop, median of 60) | back to back ms/frame (median of ' + frames + ') |');
console.log('|---|---|---|---|');
for (const [i, c] of CONFIGS.entries())
  console.log(`| ${c.page} | ${c.label} | ${median(results[i].readout).toFixed(2)} | ${median(results[i].loop).toFixed(2)} |`);
console.log('\nEach round, readout / back to back ms/frame:\n');
console.log('| page | settings | ' + results[0].loop.map((_, r) => `round ${r + 1}`).join(' | ') + ' |');
console.log('|---|---|' + results[0].loop.map(() => '---|').join(''));
for (const [i, c] of CONFIGS.entries())
  console.log(`| ${c.page} | ${c.label} | ` +
              results[i].loop.map((l, r) => `${results[i].readout[r].toFixed(2)} / ${l.toFixed(2)}`).join(' | ') + ' |');
