// web.layout: the exercise pages as a student opens them, on a laptop (800x700) and a phone
// (390x844 at a device pixel ratio of 3), every page:
// - 800x700: the canvas and the first control inside the viewport without scrolling; the same page
//   widened to 1280x720: the controls beside the canvas, not below it, the backing store following;
// - 390x844: nothing wider than the viewport (no sideways scroll);
// - the canvas's backing store is its CSS size x devicePixelRatio, capped at 2048 a side (and the
//   page says so), as the picture readout states;
// - the first frame's time is shown and printed;
// then, on W09P2c: values off a control's list or out of range from the URL and the controls are
// changed to one offered or refused, with a note naming the option and the value used, the control
// showing the value in effect; the note clears with the next good change; and the readouts while
// the context is lost (no ms figure, a note over the canvas) and after it is restored ("restored",
// then "running", the note gone).
// Screenshots of every page at both sizes go to OUT_DIR (argument 1) for a person to look at (the
// phone's whole page in CSS pixels, 390 wide: the layout is what they show, and the 1170-wide
// capture cost the test about 12 s).
import { mkdirSync } from 'node:fs';
import path from 'node:path';
import { runTest, openPage, check, PAGES } from './harness.mjs';

const OUT = process.argv[2] || 'test-output/web/layout';
mkdirSync(OUT, { recursive: true });

const LAPTOP = { viewport: { width: 800, height: 700 }, scale: 1 };
const PHONE = { viewport: { width: 390, height: 844 }, scale: 3 };
const WIDE = { viewport: { width: 1280, height: 720 }, scale: 1 };

// Where the canvas and the first control are, the page's scroll size, and the backing store.
async function measure(page) {
  return page.evaluate(() => {
    const box = (el) => { const r = el.getBoundingClientRect(); return { left: r.left, top: r.top, right: r.right, bottom: r.bottom, width: r.width, height: r.height }; };
    const canvas = document.getElementById('canvas');
    const first = document.querySelector('#controls [data-option], #controls input, #controls select, #controls button');
    // Anything reaching past the viewport's right edge (the page's own scroll width says it too).
    const wide = [...document.querySelectorAll('body *')].filter((el) => el.getBoundingClientRect().right > innerWidth + 0.5)
      .map((el) => el.tagName.toLowerCase() + (el.id ? '#' + el.id : '')).slice(0, 5);
    return {
      canvas: box(canvas), first: box(first), firstName: first.id || first.dataset.option,
      panel: box(document.getElementById('controls')),
      store: { width: canvas.width, height: canvas.height }, dpr: devicePixelRatio,
      scrollWidth: document.documentElement.scrollWidth, innerWidth, innerHeight, wide,
      picture: document.getElementById('picture').textContent,
      firstFrame: document.getElementById('first-frame').textContent,
      ready: document.getElementById('ready').textContent,
    };
  });
}

function expectedStore(css, dpr) {
  let w = Math.round(css.width * dpr), h = Math.round(css.height * dpr);
  const k = Math.min(1, 2048 / Math.max(w, h));
  return { width: Math.max(1, Math.floor(w * k)), height: Math.max(1, Math.floor(h * k)), capped: k < 1 };
}

function checkStore(p, m, what) {
  const want = expectedStore(m.canvas, m.dpr);
  check(Math.abs(m.store.width - want.width) <= 1 && Math.abs(m.store.height - want.height) <= 1,
        `${p} ${what}: backing store ${m.store.width}x${m.store.height}, CSS ${m.canvas.width}x${m.canvas.height} at ${m.dpr}x wants ${want.width}x${want.height}`);
  check(m.picture.startsWith(`${m.store.width} x ${m.store.height} pixels`), `${p} ${what}: the picture readout says '${m.picture}'`);
  check(want.capped === /capped at 2048/.test(m.picture), `${p} ${what}: the readout '${m.picture}' and the cap disagree`);
}

// The page measured once its backing store has followed a resize (the ResizeObserver's callback
// runs after the layout): polled for at most 5 s; checkStore then says what is wrong.
async function settledStore(page) {
  for (let i = 0; ; ++i) {
    const m = await measure(page);
    const want = expectedStore(m.canvas, m.dpr);
    if ((Math.abs(m.store.width - want.width) <= 1 && Math.abs(m.store.height - want.height) <= 1 &&
         m.picture.startsWith(`${m.store.width} x ${m.store.height} pixels`)) || i === 50) return m;
    await page.waitForTimeout(100);
  }
}

async function open(browser, url, how) {
  const r = await openPage(browser, url, { fixedCanvas: false, ...how });
  // The first frame is drawn, and its time shown.
  await r.page.waitForFunction(() => window.penumbra.firstFrameMs() !== null, null, { timeout: 60000 });
  return r;
}

await runTest('web.layout', async ({ server, browser }) => {
  const firstFrames = [];
  for (const p of PAGES) {
    {
      const { page, context, problems } = await open(browser, `${server.url}/${p}.html`, LAPTOP);
      const m = await measure(page);
      check(m.canvas.top >= 0 && m.canvas.bottom <= m.innerHeight + 0.5 && m.canvas.right <= m.innerWidth + 0.5,
            `${p} 800x700: the canvas ${JSON.stringify(m.canvas)} is not inside the viewport`);
      check(m.canvas.width >= 300, `${p} 800x700: the canvas is only ${m.canvas.width} px wide`);
      check(m.first.top >= 0 && m.first.bottom <= m.innerHeight + 0.5 && m.first.right <= m.innerWidth + 0.5,
            `${p} 800x700: the first control (${m.firstName}) ${JSON.stringify(m.first)} is not inside the viewport`);
      check(m.panel.left >= m.canvas.right - 0.5, `${p} 800x700: the controls are not beside the canvas`);
      check(m.scrollWidth <= m.innerWidth, `${p} 800x700: the page is ${m.scrollWidth} px wide (${m.wide.join(', ')})`);
      checkStore(p, m, '800x700');
      check(/^\d+ ms$/.test(m.firstFrame), `${p}: the first frame readout says '${m.firstFrame}'`);
      check(/^\d+ ms$/.test(m.ready), `${p}: the ready readout says '${m.ready}'`);
      const ms = await page.evaluate(() => window.penumbra.firstFrameMs());
      firstFrames.push(`${p} ${Math.round(ms)} ms`);
      await page.screenshot({ path: path.join(OUT, `${p}-800x700.png`) });
      check(problems.length === 0, `${p} 800x700: ${problems.join('; ')}`);
      console.log(`${p} 800x700: canvas ${m.canvas.width}x${m.canvas.height} at (${m.canvas.left},${m.canvas.top}), ` +
                  `first control ${m.firstName} ends at y=${m.first.bottom.toFixed(0)}; first frame ${m.firstFrame}`);
      // The same page widened to 1280x720 (the window resized: the layout is the stylesheet's, the
      // one a page opened at that size gets, without a third load of every page).
      await page.setViewportSize(WIDE.viewport);
      await page.waitForFunction((w) => innerWidth === w, WIDE.viewport.width, { timeout: 10000 });
      const w = await settledStore(page);
      check(w.panel.left >= w.canvas.right - 0.5 && w.panel.top < w.canvas.bottom,
            `${p} 1280x720: the controls ${JSON.stringify(w.panel)} are not beside the canvas ${JSON.stringify(w.canvas)}`);
      check(w.panel.bottom <= w.innerHeight + 0.5, `${p} 1280x720: the controls end at y=${w.panel.bottom} (they scroll inside)`);
      checkStore(p, w, '1280x720 (resized from 800x700)');
      await context.close();
    }
    {
      const { page, context, problems } = await open(browser, `${server.url}/${p}.html`, PHONE);
      const m = await measure(page);
      check(m.scrollWidth <= m.innerWidth, `${p} 390x844: the page is ${m.scrollWidth} px wide (${m.wide.join(', ')})`);
      check(m.wide.length === 0, `${p} 390x844: wider than the viewport: ${m.wide.join(', ')}`);
      check(m.canvas.right <= m.innerWidth + 0.5 && m.canvas.width >= 300, `${p} 390x844: the canvas ${JSON.stringify(m.canvas)}`);
      checkStore(p, m, '390x844 at 3x');
      check(m.store.width > 2 * m.canvas.width, `${p} 390x844: the backing store ${m.store.width} px for ${m.canvas.width} CSS px at 3x`);
      await page.screenshot({ path: path.join(OUT, `${p}-390x844.png`), fullPage: true, scale: 'css' });
      check(problems.length === 0, `${p} 390x844: ${problems.join('; ')}`);
      console.log(`${p} 390x844 at 3x: canvas ${m.canvas.width} CSS px, backing store ${m.store.width}x${m.store.height}; page ${m.scrollWidth} px wide`);
      await context.close();
    }
  }
  console.log(`first frame (navigation start to the first frame drawn, one load each, 800x700): ${firstFrames.join(', ')}`);

  // The cap: a 464-pixel canvas at 5x would want 2320 pixels a side.
  {
    const { page, context } = await open(browser, `${server.url}/w09p2c.html`, { viewport: { width: 800, height: 700 }, scale: 5 });
    const m = await measure(page);
    checkStore('w09p2c', m, '800x700 at 5x');
    check(Math.max(m.store.width, m.store.height) === 2048, `w09p2c at 5x: backing store ${m.store.width}x${m.store.height}, not capped at 2048`);
    console.log(`w09p2c 800x700 at 5x: '${m.picture}'`);
    await context.close();
  }

  // Values off the lists or out of range, from a link and from the controls.
  {
    const { page, context, problems } = await open(browser, `${server.url}/w09p2c.html?map-size=3000&filter=pcf2x2&bias=2&encoding=r8`, LAPTOP);
    let s = await page.evaluate(() => window.penumbra.state());
    const note = await page.textContent('#note');
    check(await page.isVisible('#note'), 'w09p2c: no note for the bad link');
    check(/map-size=3000/.test(note) && /using 4096/.test(note), `w09p2c: the note does not say map-size=3000 became 4096: '${note}'`);
    check(/filter=pcf2x2/.test(note) && /bias/.test(note), `w09p2c: the note does not name pcf2x2 and the bias: '${note}'`);
    check(s.mapSize === 4096 && s.options['map-size'] === '4096' && (await page.inputValue('#map-size')) === '4096',
          `w09p2c: map-size=3000 gave ${s.mapSize}, the select shows '${await page.inputValue('#map-size')}'`);
    check(s.options.filter === 'hard' && !(await page.isChecked('#filter')), `w09p2c: filter=pcf2x2 gave ${s.options.filter}`);
    check(s.options.encoding === 'r8', 'w09p2c: the good value of the link was not applied');
    check(new URL(page.url()).searchParams.get('map-size') === '4096', `w09p2c: the URL ${page.url()} does not keep the size in effect`);
    console.log(`w09p2c link: note '${note}'`);
    // A good change clears it.
    await page.selectOption('#encoding', 'rgba');
    check(!(await page.isVisible('#note')), `w09p2c: the link's note outlived a good change: '${await page.textContent('#note')}'`);
    // A control's out-of-range value: refused, said, the box back to the value in effect.
    await page.check('#bias-fixed');
    await page.fill('#bias', '5');
    await page.dispatchEvent('#bias', 'change');
    s = await page.evaluate(() => window.penumbra.state());
    const biasNote = await page.textContent('#note');
    check(/bias/.test(biasNote) && /5/.test(biasNote), `w09p2c: bias 5 gave the note '${biasNote}'`);
    check(s.options.bias !== '5', `w09p2c: bias 5 was taken (${s.options.bias})`);
    check(Math.abs(Number(await page.inputValue('#bias')) - s.bias) < 1e-6, `w09p2c: the bias box shows ${await page.inputValue('#bias')}, the bias in effect is ${s.bias}`);
    // The next change's note replaces it; a good one clears it.
    await page.evaluate(() => window.penumbra.setOption('map-size', '3000'));
    check(/map-size=3000/.test(await page.textContent('#note')) && !/bias/.test(await page.textContent('#note')),
          `w09p2c: the note is '${await page.textContent('#note')}'`);
    await page.evaluate(() => window.penumbra.setOption('map-size', '512'));
    check(!(await page.isVisible('#note')), 'w09p2c: the note outlived a good change');
    check(problems.length === 0, problems.join('; '));
    await context.close();
  }

  // The readouts while the context is lost and after it is restored.
  {
    const { page, context, problems } = await open(browser, `${server.url}/w09p2c.html`, LAPTOP);
    await page.waitForFunction(() => /ms\/frame/.test(document.getElementById('ms').textContent), null, { timeout: 30000 });
    await page.evaluate(() => {
      window.__lose = document.getElementById('canvas').getContext('webgl').getExtension('WEBGL_lose_context');
      window.__lose.loseContext();
    });
    await page.waitForFunction(() => /lost/i.test(document.getElementById('status').textContent), null, { timeout: 10000 });
    await page.waitForFunction(() => !/ms\/frame/.test(document.getElementById('ms').textContent), null, { timeout: 5000 });
    const lostMs = await page.textContent('#ms');
    await page.waitForFunction(() => !document.getElementById('lost').hidden, null, { timeout: 5000 });
    const over = await page.evaluate(() => {
      const a = document.getElementById('lost').getBoundingClientRect(), c = document.getElementById('canvas').getBoundingClientRect();
      return Math.abs(a.left - c.left) < 1 && Math.abs(a.top - c.top) < 1 && Math.abs(a.width - c.width) < 1 && Math.abs(a.height - c.height) < 1;
    });
    check(over, 'w09p2c: the lost-context overlay does not cover the canvas');
    await page.screenshot({ path: path.join(OUT, 'w09p2c-context-lost-800x700.png') });
    await page.evaluate(() => window.__lose.restoreContext());
    await page.waitForFunction(() => /restored/i.test(document.getElementById('status').textContent), null, { timeout: 10000 });
    const restored = await page.textContent('#status');
    await page.waitForFunction(() => document.getElementById('status').textContent === 'running', null, { timeout: 20000 });
    check(await page.evaluate(() => document.getElementById('lost').hidden), 'w09p2c: the lost-context overlay stays after the restore');
    await page.waitForFunction(() => /ms\/frame/.test(document.getElementById('ms').textContent), null, { timeout: 20000 });
    check(problems.length === 0, problems.join('; '));
    console.log(`w09p2c context loss: ms '${lostMs}' while lost; '${restored}', then 'running', ms '${await page.textContent('#ms')}'`);
    await context.close();
  }
});
