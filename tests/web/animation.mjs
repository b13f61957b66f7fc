// web.light and web.jump (argument: light | jump), on W09P1 with the page's real buttons:
// while the control is on, two readbacks some frames apart differ; switched off (from the
// keyboard: focus and Space), they are equal (jump: once the teapot has landed). The other
// motion is switched off first (a click; for web.light the teapot is let land first), so the
// difference belongs to the control under test.
import { runTest, openPage, waitFrames, readPixels, compare, check } from './harness.mjs';

const which = process.argv[2];
if (which !== 'light' && which !== 'jump') throw new Error('usage: animation.mjs light|jump');
const other = which === 'light' ? 'jump' : 'light';
const FRAMES_APART = 12;

// Waits (at most 20 s) until two readbacks FRAMES_APART frames apart agree.
async function waitStill(page, what) {
  const deadline = Date.now() + 20000;
  let before = await readPixels(page);
  for (;;) {
    await waitFrames(page, FRAMES_APART);
    const after = await readPixels(page);
    if (compare(before, after).differing === 0) return;
    check(Date.now() < deadline, `${what}: the picture still changes 20 s later`);
    before = after;
  }
}

await runTest(`web.${which}`, async ({ server, browser }) => {
  const { page, problems } = await openPage(browser, `${server.url}/w09p1.html`);
  await page.click(`#${other}`);
  check((await page.getAttribute(`#${other}`, 'aria-pressed')) === 'false', `the ${other} button did not switch off`);
  await waitFrames(page, 2);
  if (other === 'jump') {
    // Jump off lets the teapot finish its bounce (up to 1.5 s of the page's clock), which would
    // count as the light's motion below: stop the light too until the picture holds still, then
    // start it again.
    await page.click('#light');
    await waitStill(page, 'jump off');
    await page.click('#light');
    check((await page.getAttribute('#light', 'aria-pressed')) === 'true', 'the light button did not switch on again');
    await waitFrames(page, 2);
  }

  const a = await readPixels(page);
  await waitFrames(page, FRAMES_APART);
  const b = await readPixels(page);
  const moving = compare(a, b);
  check(moving.differing > 100, `${which} on: only ${moving.differing} pixels changed in ${FRAMES_APART} frames`);

  // Off, from the keyboard.
  await page.focus(`#${which}`);
  await page.keyboard.press('Space');
  check((await page.getAttribute(`#${which}`, 'aria-pressed')) === 'false', `Space on the ${which} button did not switch it off`);
  const state = await page.evaluate(() => window.penumbra.state());
  check(state.options[which] === 'off', `the module's ${which} is '${state.options[which]}'`);
  check(new URL(page.url()).searchParams.get(which) === 'off', `the URL does not say ${which}=off: ${page.url()}`);
  await waitFrames(page, 2);
  // Jump off lets the teapot finish its bounce and rest on the table (at most one 1.5 s bounce
  // of the page's clock); wait until two readbacks agree, then hold it to the same test as light.
  if (which === 'jump') await waitStill(page, 'jump off');
  const c = await readPixels(page);
  await waitFrames(page, FRAMES_APART);
  const d = await readPixels(page);
  const frozen = compare(c, d);
  check(frozen.differing === 0, `${which} off: ${frozen.differing} pixels still changed in ${FRAMES_APART} frames`);
  check(problems.length === 0, problems.join('; '));
  console.log(`${which} on: ${moving.differing} pixels changed over ${FRAMES_APART} frames; off: ${frozen.differing}`);
});
