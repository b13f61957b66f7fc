// CPU milliseconds per frame (user + system of all Chromium's processes, read from /proc) on W09P2c
// with pcf4x4 under the early exit and the full kernel (and rgba hard for scale), N frames drawn back
// to back by the test hook, the light moving, interleaved rounds in alternating order. CPU time is
// less sensitive than wall time to other load on the machine (it still inflates under contention).
// usage: node tools/web_pcf_kernel_cpu.mjs [ROUNDS] [FRAMES]   (needs build-web/site; Linux /proc;
// prints one JSON object {configs, out: per config, per round {cpu, wall} ms per frame})
import { readFileSync, readdirSync } from 'node:fs';
import { serve, launch, openPage, siteDir, waitFrames } from '../tests/web/harness.mjs';
const rounds = Number(process.argv[2] || 5), frames = Number(process.argv[3] || 60);
const HZ = 100;  // USER_HZ: /proc/PID/stat counts CPU time in 1/100 s

// CPU seconds used so far by every process descended from this one (the browser and its children).
function tree() {
  const parent = new Map();
  for (const d of readdirSync('/proc')) {
    if (!/^\d+$/.test(d)) continue;
    try { const s = readFileSync(`/proc/${d}/stat`, 'utf8'); const f = s.slice(s.lastIndexOf(')') + 2).split(' ');
      parent.set(Number(d), { ppid: Number(f[1]), cpu: (Number(f[11]) + Number(f[12])) / HZ }); } catch {}
  }
  const mine = new Set([process.pid]); let grew = true;
  while (grew) { grew = false; for (const [p, v] of parent) if (!mine.has(p) && mine.has(v.ppid)) { mine.add(p); grew = true; } }
  let cpu = 0; for (const p of mine) if (p !== process.pid) cpu += parent.get(p)?.cpu || 0;
  return cpu;
}

// The map view is off: the frame is the shadow pass and the camera pass only.
const CONFIGS = [
  { label: 'rgba early-exit', q: 'encoding=rgba&filter=pcf4x4' },
  { label: 'rgba full', q: 'encoding=rgba&filter=pcf4x4&pcf-kernel=full' },
  { label: 'r8 early-exit', q: 'encoding=r8&filter=pcf4x4' },
  { label: 'r8 full', q: 'encoding=r8&filter=pcf4x4&pcf-kernel=full' },
  { label: 'rgba hard', q: 'encoding=rgba&filter=hard' },
];
const server = await serve(siteDir());
const browser = await launch();
const out = CONFIGS.map(() => []);
for (let r = 0; r < rounds; ++r) {
  const order = r % 2 ? [...CONFIGS.keys()].reverse() : [...CONFIGS.keys()];
  for (const i of order) {
    const c = CONFIGS[i];
    const { page, context } = await openPage(browser, `${server.url}/w09p2c.html?${c.q}&map-size=1024&map-view=off`);
    await waitFrames(page, 20);
    await page.evaluate(() => window.penumbra.pause());
    await page.evaluate(() => { for (let k = 0; k < 5; ++k) { window.penumbra.setTime(k / 60); window.penumbra.renderNow(); } });
    const c0 = tree(); const t0 = Date.now();
    await page.evaluate((n) => { for (let k = 0; k < n; ++k) { window.penumbra.setTime(k / 60); window.penumbra.renderNow(); } }, frames);
    const c1 = tree(); const t1 = Date.now();
    out[i].push({ cpu: (c1 - c0) * 1000 / frames, wall: (t1 - t0) / frames });
    await context.close();
  }
  console.error(`round ${r + 1} ` + CONFIGS.map((c, i) => `${c.label}: ${out[i][r].cpu.toFixed(1)} cpu-ms ${out[i][r].wall.toFixed(1)} ms`).join('; '));
}
await browser.close(); await server.close();
console.log(JSON.stringify({ configs: CONFIGS.map((c) => c.label), out }));
