// web.context_loss: WEBGL_lose_context on every exercise page. The page says the context was lost
// and draws nothing while it is; after restoreContext() it says so, has made its renderer and GL
// objects again (shaders, meshes, textures, shadow map, FBO, the volumes' buffers, the light samples'
// targets: the module's GL generation goes from 1 to 2), renders the same frame again (fixed t) and
// reports no GL or console error. Then, on W09P2c, a GL error queued before a frame (an invalid
// enum): that frame fails, its error names GL_INVALID_ENUM and the frame's passes (in the browser
// the renderer reads glGetError once a frame: each read waits for the GPU process) in the
// module's status, and the next frame draws again.
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

  {
    const { page, context, problems } = await openPage(browser, `${server.url}/w09p2c.html`);
    const ok = await page.evaluate(() => { window.penumbra.pause(); return window.penumbra.renderNow(); });
    check(ok, 'w09p2c: the frame before the queued error failed');  // the control
    const r = await page.evaluate(() => {
      document.getElementById('canvas').getContext('webgl').enable(0x1234);  // GL_INVALID_ENUM, queued
      const drawn = window.penumbra.renderNow();
      return { drawn, error: window.penumbra.state().status };
    });
    check(!r.drawn, 'w09p2c: a frame after a queued GL_INVALID_ENUM drew as if nothing were wrong');
    // (the frame's one check also takes what the objects made since the last one raised: gl::check_made)
    check(/GL_INVALID_ENUM/.test(r.error) && /the frame's passes \(.*camera.*\) or the GL objects made for them/.test(r.error),
          `w09p2c: the queued error was reported as '${r.error}'`);
    const again = await page.evaluate(() => window.penumbra.renderNow());
    check(again, 'w09p2c: the frame after the reported error failed too');
    const err = await page.evaluate(() => window.penumbra.glError());
    check(err === 0, `w09p2c: glGetError 0x${err.toString(16)} after the reported error`);
    const others = problems.filter((m) => !/GL_INVALID_ENUM/.test(m));
    check(others.length === 0, `w09p2c: ${others.join('; ')}`);
    console.log(`w09p2c: a queued GL error: the status '${r.error}'; the next frame draws`);
    await context.close();
  }
});
