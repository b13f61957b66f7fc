// web.context_loss: WEBGL_lose_context on every exercise page. The page says the context was lost
// and draws nothing while it is; after restoreContext() it says so, has made its renderer and GL
// objects again (shaders, meshes, textures, shadow map, FBO, the volumes' buffers, the light samples'
// targets: the module's GL generation goes from 1 to 2), renders the same frame again (fixed t) and
// reports no GL or console error.
import { runTest, openPage, frameAt, compare, check, PAGES } from './harness.mjs';

const T = 0.6;
const QUERY = { w09p1: '', w09p2a: '', w09p2b: '', w09p2c: 'encoding=rgba&filter=pcf4x4',
                volumes: 'eye=in-shadow&volume-method=auto&show-volumes=on',
                soft: 'area-samples=4&area-per-frame=0&aov=visibility' };

await runTest('web.context_loss', async ({ server, browser }) => {
  for (const p of PAGES) {
    const { page, context, problems } = await openPage(browser, `${server.url}/${p}.html?${QUERY[p]}`);
    const before = await frameAt(page, T);
    check((await page.evaluate(() => window.penumbra.state())).generation === 1, `${p}: not on its first context`);

    await page.evaluate(() => {
      window.__lose = document.getElementById('canvas').getContext('webgl').getExtension('WEBGL_lose_context');
      window.__lose.loseContext();
    });
    await page.waitForFunction(() => /lost/i.test(document.getElementById('status').textContent), null, { timeout: 10000 });
    const lost = await page.evaluate(() => window.penumbra.state());
    check(lost.lost, `${p}: the module does not know its context is lost`);
    const n0 = await page.evaluate(() => window.penumbra.frameCount());
    await page.waitForTimeout(300);
    const n1 = await page.evaluate(() => window.penumbra.frameCount());
    check(n1 === n0, `${p}: ${n1 - n0} frames drawn on a lost context`);
    const lostStatus = await page.textContent('#status');

    await page.evaluate(() => window.__lose.restoreContext());
    await page.waitForFunction(() => /restored/i.test(document.getElementById('status').textContent), null, { timeout: 10000 });
    const restored = await page.evaluate(() => window.penumbra.state());
    check(!restored.lost && restored.generation === 2, `${p}: after the restore: lost ${restored.lost}, generation ${restored.generation}`);
    const after = await frameAt(page, T);
    const d = compare(before, after);
    check(d.differing === 0, `${p}: the frame after the restore differs from the one before in ${d.differing} pixels (max ${d.max})`);
    // The loop runs again.
    await page.evaluate(() => window.penumbra.resume());
    const m0 = await page.evaluate(() => window.penumbra.frameCount());
    await page.waitForFunction((m) => window.penumbra.frameCount() > m + 3, m0, { timeout: 10000 });
    const err = await page.evaluate(() => window.penumbra.glError());
    check(err === 0, `${p}: glGetError 0x${err.toString(16)} after the restore`);
    check(problems.length === 0, `${p}: ${problems.join('; ')}`);
    console.log(`${p}: '${lostStatus}' -> '${await page.textContent('#status')}'; same frame after the restore`);
    await context.close();
  }
});
