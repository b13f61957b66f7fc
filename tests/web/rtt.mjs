// web.w09p2b_rtt: W09P2b's render to texture, by a framebuffer object and by drawing in the canvas
// and copying it out (glCopyTexImage2D). The radio switches to the copy and the URL says so; the
// copy's frame equals the FBO's at the same texture size (mean <= 1 level, <= 0.5% of the pixels
// off by more than 16); asked for a texture larger than the canvas, the copy uses the largest that
// fits, the page says so beside the canvas and the frame is that size's; the choice survives a
// reload; no console or GL error. Prints each way's frame time (median of the page's last 60
// frames; SwiftShader: a figure, never a check).
import { mkdirSync } from 'node:fs';
import path from 'node:path';
import { runTest, openPage, frameAt, compare, check, glErrors, setOptions, savePng, waitFrames } from './harness.mjs';

const outDir = process.argv[2] || 'test-output/web/rtt';
const T = 0.6;

async function msPerFrame(page) {
  await page.evaluate(() => window.penumbra.resume());
  await waitFrames(page, 70);
  return page.evaluate(() => window.penumbra.state().ms);
}

await runTest('web.w09p2b_rtt', async ({ server, browser }) => {
  mkdirSync(outDir, { recursive: true });
  const { page, problems } = await openPage(browser, `${server.url}/w09p2b.html?map-size=512`);
  let s = await page.evaluate(() => window.penumbra.state());
  check(s.options.rtt === 'fbo', `rtt starts at ${s.options.rtt}, not fbo`);
  const fbo = await frameAt(page, T);
  savePng(fbo, path.join(outDir, 'fbo-512.png'));

  await page.check('input[data-option="rtt"][value="copy"]');
  s = await page.evaluate(() => window.penumbra.state());
  check(s.options.rtt === 'copy', `the radio did not set rtt=copy: ${s.query}`);
  check(/(^|&)rtt=copy(&|$)/.test(new URL(page.url()).search.slice(1)), `the URL has no rtt=copy: ${page.url()}`);
  const copy = await frameAt(page, T);
  savePng(copy, path.join(outDir, 'copy-512.png'));
  let d = compare(copy, fbo, 16);
  check(d.mean <= 1.0 && d.fraction <= 0.005, `copy against FBO at 512: mean ${d.mean.toFixed(3)}, ${d.differing} px > 16`);
  check((await page.locator('#frame-note').isHidden()), 'a frame note shows while the copy fits the canvas');
  console.log(`copy against FBO, 512x512 texture: mean ${d.mean.toFixed(3)}, ${d.differing} px > 16`);

  // Larger than the 512-pixel canvas: 512 used, and said.
  await page.selectOption('select[data-option="map-size"]', '1024');
  const clamped = await frameAt(page, T);
  await page.waitForFunction(() => !document.getElementById('frame-note').hidden, null, { timeout: 10000 });
  const note = await page.textContent('#frame-note');
  check(/no larger than the window's 512 pixels: 512x512 instead of 1024x1024/.test(note), `the frame note: '${note}'`);
  d = compare(clamped, copy, 0);
  check(d.max === 0, `the clamped copy's frame differs from the 512 copy's (max ${d.max})`);

  // The choice survives a reload.
  await page.reload({ waitUntil: 'load' });
  await page.evaluate(() => window.penumbra.ready);
  s = await page.evaluate(() => window.penumbra.state());
  check(s.options.rtt === 'copy' && s.options['map-size'] === '1024', `after a reload: ${s.query}`);

  // The cost of each way, as the page measures it (512x512 texture, the canvas 512x512).
  await setOptions(page, { 'map-size': '512', rtt: 'fbo' });
  const fboMs = await msPerFrame(page);
  await setOptions(page, { rtt: 'copy' });
  const copyMs = await msPerFrame(page);
  console.log(`frame time (SwiftShader, median of the last 60 frames): fbo ${fboMs.toFixed(2)} ms, copy ${copyMs.toFixed(2)} ms`);

  const errors = await glErrors(page);
  check(errors.length === 0, `GL errors: ${errors.join(', ')}`);
  check(problems.length === 0, problems.join('\n'));
});
