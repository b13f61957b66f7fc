// Screenshots of the web site in headless Chromium (SwiftShader WebGL): the index, each exercise
// page at its defaults and a few settings, at a fixed t (paused) so they can be compared.
// usage: node tools/web_screenshots.mjs [OUT_DIR] [T]   (default out/web-screens, t = 0.6)
import { mkdirSync } from 'node:fs';
import path from 'node:path';
import { serve, launch, openPage, siteDir } from '../tests/web/harness.mjs';

const out = process.argv[2] || 'out/web-screens';
const t = Number(process.argv[3] || 0.6);
const SHOTS = [
  ['index', 'index.html'],
  ['w09p1', 'w09p1.html'],
  ['w09p2a', 'w09p2a.html'],
  ['w09p2a-ortho', 'w09p2a.html?projection=ortho'],
  ['w09p2b', 'w09p2b.html'],
  ['w09p2b-camera', 'w09p2b.html?fbo-view=camera'],
  ['w09p2c', 'w09p2c.html'],
  ['w09p2c-r8-pcf4x4', 'w09p2c.html?encoding=r8&filter=pcf4x4'],
  ['w09p2c-r8-bias0.0015-visibility', 'w09p2c.html?encoding=r8&bias=0.0015&aov=visibility'],
  ['w09p2c-pcf4x4-visibility', 'w09p2c.html?filter=pcf4x4&aov=visibility'],
  ['w09p2c-bias-auto-pcf4x4-visibility', 'w09p2c.html?filter=pcf4x4&bias=auto&aov=visibility'],
  ['w09p2c-bias-auto', 'w09p2c.html?bias=auto'],
  ['w09p2c-mediump', 'w09p2c.html?precision=mediump'],
  ['w09p2c-bias0.0002-visibility', 'w09p2c.html?bias=0.0002&aov=visibility'],
  ['w09p2c-mediump-bias0.0002-visibility', 'w09p2c.html?precision=mediump&bias=0.0002&aov=visibility'],
];
mkdirSync(out, { recursive: true });
const server = await serve(siteDir());
const browser = await launch();
for (const [name, url] of SHOTS) {
  const isIndex = name === 'index';
  const { page, context, problems } = await openPage(browser, `${server.url}/${url}`, { waitReady: !isIndex });
  if (!isIndex) {
    await page.evaluate((time) => { window.penumbra.pause(); window.penumbra.setTime(time); window.penumbra.renderNow(); }, t);
    await page.waitForTimeout(600);  // the readouts poll every 250 ms
  }
  const file = path.join(out, `${name}.png`);
  await page.screenshot({ path: file, fullPage: true });
  console.log(`${file}${problems.length ? '  PROBLEMS: ' + problems.join('; ') : ''}`);
  await context.close();
}
await browser.close();
await server.close();
