// web.url: settings changed with the pages' controls are written to the URL and survive a reload
// (the module and the controls come back in the same state), on W09P2c (bias=auto and
// precision=mediump, chosen with the keyboard, among them), W09P2a and W09P2b; a bad
// URL value is reported in the status line and ignored, not a console error.
import { runTest, openPage, check } from './harness.mjs';

async function reloadAndRead(page) {
  await page.reload({ waitUntil: 'load' });
  await page.evaluate(() => window.penumbra.ready);
  return page.evaluate(() => window.penumbra.state());
}

await runTest('web.url', async ({ server, browser }) => {
  {
    const { page, context, problems } = await openPage(browser, `${server.url}/w09p2c.html`);
    await page.selectOption('#encoding', 'r8');
    await page.check('#filter');
    await page.check('#bias-fixed');
    await page.fill('#bias', '0.003');
    await page.dispatchEvent('#bias', 'change');
    await page.selectOption('#map-size', '2048');
    await page.selectOption('#aov', 'visibility');
    await page.uncheck('#map-view');
    await page.click('#light');
    const want = { encoding: 'r8', filter: 'pcf4x4', bias: '0.003', 'map-size': '2048', aov: 'visibility',
                   'map-view': 'off', light: 'off', jump: 'on' };
    const params = new URL(page.url()).searchParams;
    for (const [k, v] of Object.entries(want)) check(params.get(k) === v, `URL ${page.url()}: ${k} is not ${v}`);
    const s = await reloadAndRead(page);
    for (const [k, v] of Object.entries(want)) check(s.options[k] === v, `after reload ${k} = ${s.options[k]}, not ${v}`);
    check((await page.inputValue('#encoding')) === 'r8', 'the encoding select lost r8');
    check(await page.isChecked('#filter'), 'the PCF box lost its tick');
    check(!(await page.isChecked('#bias-auto')) && (await page.inputValue('#bias')) === '0.003', 'the bias field lost 0.003');
    check((await page.inputValue('#map-size')) === '2048', 'the map size select lost 2048');
    check((await page.inputValue('#aov')) === 'visibility', 'the view select lost visibility');
    check(!(await page.isChecked('#map-view')), 'the shadow map view box came back ticked');
    check((await page.getAttribute('#light', 'aria-pressed')) === 'false', 'the light button came back on');
    check(problems.length === 0, problems.join('; '));
    console.log(`w09p2c: ${page.url()} restored`);
    await context.close();
  }
  {
    // bias=sheet and precision=mediump, chosen with the keyboard: the bias radios move with the
    // arrow keys, the precision select with the arrow keys once focused.
    const { page, context, problems } = await openPage(browser, `${server.url}/w09p2c.html`);
    check(await page.isChecked('#bias-auto'), 'w09p2c: the bias does not start on auto');
    check(/slope/.test(await page.textContent('label:has(#bias-auto)')), 'w09p2c: the auto choice does not mention the slope');
    await page.focus('#bias-auto');
    await page.keyboard.press('ArrowDown');
    check(await page.isChecked('#bias-sheet'), "w09p2c: ArrowDown from the auto radio did not choose the sheet's constant");
    await page.focus('#precision');
    await page.keyboard.press('ArrowDown');
    check((await page.inputValue('#precision')) === 'mediump', 'w09p2c: ArrowDown on the precision select did not pick mediump');
    const params = new URL(page.url()).searchParams;
    check(params.get('bias') === 'sheet' && params.get('precision') === 'mediump', `w09p2c: URL ${page.url()}`);
    let s = await reloadAndRead(page);
    check(s.options.bias === 'sheet' && s.options.precision === 'mediump', `w09p2c: ${JSON.stringify(s.options)} after reload`);
    check(await page.isChecked('#bias-sheet') && !(await page.isChecked('#bias-auto')), 'w09p2c: the sheet radio lost its check');
    check(await page.isDisabled('#bias'), "w09p2c: the number box is enabled with the sheet's bias");
    check((await page.inputValue('#precision')) === 'mediump', 'w09p2c: the precision select lost mediump');
    check((await page.inputValue('#bias')) === '0.0015', `w09p2c: the number box shows ${await page.inputValue('#bias')}, not the sheet's 0.0015`);
    // A fixed value from the sheet mode: the box starts from the sheet's constant and is kept.
    await page.check('#bias-fixed');
    check(!(await page.isDisabled('#bias')), 'w09p2c: the number box stays disabled for a fixed bias');
    await page.fill('#bias', '0.002');
    await page.dispatchEvent('#bias', 'change');
    s = await reloadAndRead(page);
    check(s.options.bias === '0.002' && s.options.precision === 'mediump', `w09p2c: ${JSON.stringify(s.options)} after reload`);
    check(await page.isChecked('#bias-fixed') && (await page.inputValue('#bias')) === '0.002', 'w09p2c: the fixed bias was lost');
    // And the URL alone sets both (a link).
    await context.close();
    const { page: linked, context: linkedContext, problems: linkProblems } = await openPage(browser, `${server.url}/w09p2c.html?bias=auto&precision=mediump&encoding=r8`);
    s = await linked.evaluate(() => window.penumbra.state());
    check(s.options.bias === 'auto' && s.options.precision === 'mediump' && s.options.encoding === 'r8',
          `w09p2c: a link gave ${JSON.stringify(s.options)}`);
    check(await linked.isChecked('#bias-auto') && (await linked.inputValue('#precision')) === 'mediump',
          'w09p2c: a link with bias=auto&precision=mediump did not set the controls');
    check(problems.length === 0 && linkProblems.length === 0, problems.concat(linkProblems).join('; '));
    console.log(`w09p2c: bias=auto, precision=mediump restored (${linked.url()})`);
    await linkedContext.close();
  }
  {
    const { page, context, problems } = await openPage(browser, `${server.url}/w09p2a.html`);
    await page.check('input[name="projection"][value="ortho"]');
    const s = await reloadAndRead(page);
    check(s.options.projection === 'ortho', `w09p2a: projection ${s.options.projection} after reload`);
    check(await page.isChecked('input[name="projection"][value="ortho"]'), 'w09p2a: the ortho radio lost its check');
    check(problems.length === 0, problems.join('; '));
    console.log(`w09p2a: ${page.url()} restored`);
    await context.close();
  }
  {
    const { page, context, problems } = await openPage(browser, `${server.url}/w09p2b.html`);
    await page.selectOption('#fbo-view', 'camera');
    await page.selectOption('#map-size', '512');
    const s = await reloadAndRead(page);
    check(s.options['fbo-view'] === 'camera' && s.options['map-size'] === '512',
          `w09p2b: ${JSON.stringify(s.options)} after reload`);
    check((await page.inputValue('#fbo-view')) === 'camera', 'w09p2b: the FBO select lost camera');
    check(problems.length === 0, problems.join('; '));
    console.log(`w09p2b: ${page.url()} restored`);
    await context.close();
  }
  {
    // A bad value: said in the status line, the rest still applied, no console error.
    const { page, context, problems } = await openPage(browser, `${server.url}/w09p2c.html?encoding=r16&filter=pcf4x4`);
    const s = await page.evaluate(() => window.penumbra.state());
    check(s.options.filter === 'pcf4x4' && s.options.encoding === 'rgba', `bad URL: ${JSON.stringify(s.options)}`);
    const note = await page.textContent('#note');
    check(/r16/.test(note) && (await page.isVisible('#note')), `the note does not mention the bad value: '${note}'`);
    check(!new URL(page.url()).search.includes('r16'), 'the bad value stayed in the URL');
    check(problems.length === 0, problems.join('; '));
    await context.close();
  }
  {
    // Numbers as the module reads them in the browser (JavaScript's Number() behind the C++'s
    // own check of the text, src/plan/options.cpp read_number): the forms people type, 20
    // significant digits, and what is not a number here although C's strtod reads it.
    const { page, context, problems } = await openPage(browser, `${server.url}/w09p2c.html`);
    const set = (v) => page.evaluate((x) => window.penumbra.setOption('bias', x), v);
    const bias = async () => (await page.evaluate(() => window.penumbra.state())).options.bias;
    for (const [text, want] of [['.0025', '0.0025'], ['25e-4', '0.0025'], ['+2.5E-3', '0.0025'],
                                ['0.0030000000000000001', '0.003'], ['0.004', '0.004']]) {
      const err = await set(text);
      check(err === '', `bias=${text} refused: ${err}`);
      check((await bias()) === want, `bias=${text} reads as ${await bias()}, not ${want}`);
    }
    for (const [text, why] of [['nan', /finite number/], ['-inf', /finite number/], ['1e999', /finite number/],
                               ['0x1p-8', /not a number/], [' 0.002', /not a number/], ['0.002 ', /not a number/],
                               ['1e', /not a number/], ['.', /not a number/]]) {
      const err = await set(text);
      check(why.test(err), `bias='${text}': '${err}', want ${why}`);
      check((await bias()) === '0.004', `bias='${text}' changed the bias to ${await bias()}`);
    }
    check(problems.length === 0, problems.join('; '));
    console.log('w09p2c: numbers read as natively');
    await context.close();
  }
});
