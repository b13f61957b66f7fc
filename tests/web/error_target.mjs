// web.error_target, on W09P2c: the "error target" select (max-error). Off, no choice and the readout
// hidden; on, the readout says the map chosen and its predicted error, the URL keeps the target, a
// tighter target chooses a larger map (the control: the target changes the choice) predicted with
// less error; the time budget and the error target are one at a time, the page saying which went
// off; a target from the URL is taken. The drawn map is checked on the desktop (desktop.error-target:
// the same app code), the model against the truth by the CLI's tests and the bench.
import { runTest, openPage, waitFrames, check } from './harness.mjs';

const state = (page) => page.evaluate(() => window.penumbra.state());
const readout = async (page) => ({ hidden: await page.isHidden('#error-row'), text: await page.textContent('#error-target') });

// Waits (frame by frame, up to `frames`) until the state's errorTarget satisfies `want`.
async function waitChoice(page, want, frames) {
  for (let i = 0; i < frames; i += 5) {
    const s = await state(page);
    if (s.errorTarget && want(s.errorTarget)) return s.errorTarget;
    await waitFrames(page, 5);
  }
  return (await state(page)).errorTarget;
}

await runTest('web.error_target', async ({ server, browser }) => {
  const { page, context, problems } = await openPage(browser, `${server.url}/w09p2c.html`);
  check((await page.inputValue('#max-error')) === '0', `the select starts at ${await page.inputValue('#max-error')}`);
  await waitFrames(page, 3);
  check((await state(page)).errorTarget === null, 'a choice while off');
  check((await readout(page)).hidden, 'the readout shows while off');

  // 0.2 %: the choice, the URL, the readout.
  await page.selectOption('#max-error', '0.2');
  check(new URL(page.url()).searchParams.get('max-error') === '0.2', `the URL does not keep max-error=0.2: ${page.url()}`);
  const loose = await waitChoice(page, (c) => c.mapSize !== null, 20);
  const m = loose && loose.mapSize;
  check(m >= 128 && m <= 4096 && (m & (m - 1)) === 0, `map ${m} is not a power of two in [128, 4096]: ${JSON.stringify(loose)}`);
  // The line's prediction is the state's, printed to 3 decimals.
  const said = loose && new RegExp('^max-error 0\\.200 %: (depthtex|rgba) hard ' + m + ', predicted ([0-9.]+) %').exec(loose.why);
  check(said && loose.predictedErrorPct > 0 && Math.abs(+said[2] - loose.predictedErrorPct) <= 0.0005, JSON.stringify(loose));
  await page.waitForFunction(() => !document.getElementById('error-row').hidden &&
    document.getElementById('error-target').textContent.startsWith('max-error 0.200 %: '), null, { timeout: 10000 })
    .catch(() => {});
  const shown = await readout(page);
  check(!shown.hidden && shown.text === loose.why, `the readout: ${JSON.stringify(shown)}`);

  // 0.025 %: a larger map, predicted with less error (where the context offers more than one).
  await page.selectOption('#max-error', '0.025');
  const tight = await waitChoice(page, (c) => c.why.startsWith('max-error 0.025 %'), 20);
  if ((await state(page)).maxMapSize > 128)
    check(tight && tight.mapSize > m && tight.predictedErrorPct < loose.predictedErrorPct,
          `0.025 %: ${JSON.stringify(tight)} against 0.2 %: ${JSON.stringify(loose)}`);

  // One at a time: the budget turns the target off, and says so.
  await page.selectOption('#budget-ms', '16');
  await waitFrames(page, 2);
  check((await page.inputValue('#max-error')) === '0', `the target's select with a budget: ${await page.inputValue('#max-error')}`);
  check(/max-error off/.test(await page.textContent('#note')), `the note: ${await page.textContent('#note')}`);
  const url = new URL(page.url()).searchParams;
  check(url.get('budget-ms') === '16' && url.get('max-error') === '0', `the URL: ${page.url()}`);
  check((await state(page)).errorTarget === null, 'a choice with the target off');
  await page.waitForSelector('#error-row', { state: 'hidden', timeout: 10000 }).catch(() => {});
  check((await readout(page)).hidden, 'the readout stays after the target is off');
  await page.selectOption('#max-error', '0.1');
  await waitFrames(page, 2);
  check((await page.inputValue('#budget-ms')) === '0', `the budget's select with a target: ${await page.inputValue('#budget-ms')}`);
  check(/budget-ms off/.test(await page.textContent('#note')), `the note: ${await page.textContent('#note')}`);
  check(problems.length === 0, problems.join('; '));
  await context.close();

  // From the URL: the select shows it, a choice is made.
  const again = await openPage(browser, `${server.url}/w09p2c.html?max-error=0.05`);
  check((await again.page.inputValue('#max-error')) === '0.05', `the select after a load: ${await again.page.inputValue('#max-error')}`);
  const loaded = await waitChoice(again.page, (c) => c.mapSize !== null, 20);
  check(loaded && loaded.why.startsWith('max-error 0.050 %: '), `from the URL: ${JSON.stringify(loaded)}`);
  check(again.problems.length === 0, again.problems.join('; '));
  await again.context.close();
});
