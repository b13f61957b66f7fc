// What tools/threejs_compare.mjs compares, and the small helpers its modules share.
import path from 'node:path';

export const ROOT = path.resolve(path.dirname(new URL(import.meta.url).pathname), '../..');
export const SIZE = 512;
export const MAP = 1024;

// penumbra's W09P2c page. Each row's options go into the page's URL (and are set again before it is
// timed); what a row leaves out is the page's default. 'rgba-hard' and 'rgba-pcf4x4' are the
// defaults (bias auto, the shadows fit, faces auto, PCF's early exit, map 1024); 'rgba-hard-tight'
// is the default before issue 37 (the tight light frustum, which three.js's rows are given); the
// 'sheet' rows are the settings before issue 9 (the sheet's bias, both faces, the frustum fitted
// around the whole scene, the full PCF kernel); the 'matched' row is what three.js's matched rows
// are given (the sheet's bias, both faces, the tight frustum three.js is fitted to as well), to
// check pixel by pixel that both renderers see the same map.
const BEFORE = { bias: 'sheet', 'map-faces': 'both', 'light-fit': 'scene', 'pcf-kernel': 'full' };
export let OURS = [
  { id: 'rgba-hard', label: 'rgba hard, defaults', encoding: 'rgba', filter: 'hard', map: 1024 },
  { id: 'rgba-hard-512', label: 'rgba hard, defaults, map 512', encoding: 'rgba', filter: 'hard', map: 512 },
  { id: 'rgba-hard-2048', label: 'rgba hard, defaults, map 2048', encoding: 'rgba', filter: 'hard', map: 2048 },
  { id: 'rgba-pcf4x4', label: 'rgba pcf4x4, defaults', encoding: 'rgba', filter: 'pcf4x4', map: 1024 },
  { id: 'rgba-pcf4x4-512', label: 'rgba pcf4x4, defaults, map 512', encoding: 'rgba', filter: 'pcf4x4', map: 512 },
  { id: 'rgba-pcf4x4-2048', label: 'rgba pcf4x4, defaults, map 2048', encoding: 'rgba', filter: 'pcf4x4', map: 2048 },
  { id: 'depthtex-hard', label: 'depthtex hard, defaults', encoding: 'depthtex', filter: 'hard', map: 1024 },
  { id: 'depthtex-hard-512', label: 'depthtex hard, defaults, map 512', encoding: 'depthtex', filter: 'hard', map: 512 },
  { id: 'depthtex-pcf4x4', label: 'depthtex pcf4x4, defaults', encoding: 'depthtex', filter: 'pcf4x4', map: 1024 },
  { id: 'depthtex-pcf4x4-512', label: 'depthtex pcf4x4, defaults, map 512', encoding: 'depthtex', filter: 'pcf4x4', map: 512 },
  { id: 'rgba-hard-tight', label: 'rgba hard, tight fit (the default before issue 37)', encoding: 'rgba', filter: 'hard', map: 1024, 'light-fit': 'tight' },
  { id: 'rgba-hard-sheet', label: 'rgba hard, before (sheet bias, scene fit)', encoding: 'rgba', filter: 'hard', map: 1024, ...BEFORE },
  { id: 'rgba-pcf4x4-sheet', label: 'rgba pcf4x4, before (sheet bias, scene fit, full kernel)', encoding: 'rgba', filter: 'pcf4x4', map: 1024, ...BEFORE },
  { id: 'depthtex-hard-matched', label: 'depthtex hard, matched to three.js (sheet bias, both faces)', encoding: 'depthtex', filter: 'hard', map: 1024, ...BEFORE, 'light-fit': 'tight' },
];
// The library's defaults of the options a row may set (src/plan/option_table.cpp); a page reports an
// option it has no control for only when it differs from its default.
export const OUR_DEFAULTS = { bias: 'auto', 'map-faces': 'auto', 'light-fit': 'shadows', 'pcf-kernel': 'early-exit' };
// The W09P2c page's own defaults where they differ from the library's (examples/exercises/w09p2c.cpp:
// the course's map is the tight fit, the table in it); what its state reports when it leaves an option out.
export const PAGE_DEFAULTS = { ...OUR_DEFAULTS, 'light-fit': 'tight' };
// The page options of a row, in URL order.
export const oursOptions = (c) => {
  const o = { encoding: c.encoding, filter: c.filter, 'map-size': String(c.map) };
  for (const [k, v] of Object.entries(OUR_DEFAULTS)) o[k] = c[k] ?? v;
  return o;
};
// The sheet's bias of rgba and depthtex (docs/usage.md: 0.0015, in window depth units), which
// three.js applies with the opposite sign (shadowCoord.z += bias; lit where z <= depth).
export const OUR_BIAS = 0.0015;
// three.js: BasicShadowMap and PCFShadowMap, each at three.js's defaults (bias 0, normalBias 0, the
// back faces into the map: shadowSide = the opposite of the material's side), and matched (the
// sheet's bias, both faces into the map). Both are given penumbra's tight light frustum
// (tests/threejs/compare.js fits it as src/shadow/light_frustum.cpp does).
// What --quick renders of penumbra's rows (web.threejs): those the checks and ratios read (the
// defaults, their depthtex twins, the row matched to three.js's), not the doc's other sizes and
// befores.
const QUICK = ['rgba-hard', 'rgba-pcf4x4', 'depthtex-hard', 'depthtex-pcf4x4', 'depthtex-hard-matched'];
export function quickRows() {
  OURS = OURS.filter((c) => QUICK.includes(c.id));
}

export const THREE_CONFIGS = [
  { id: 'three-basic-default', label: 'three.js BasicShadowMap, defaults', type: 'basic', bias: 0, shadowSide: 'default', vs: 'rgba-hard' },
  { id: 'three-basic-matched', label: 'three.js BasicShadowMap, matched', type: 'basic', bias: -OUR_BIAS, shadowSide: 'double', vs: 'rgba-hard' },
  { id: 'three-pcf-default', label: 'three.js PCFShadowMap, defaults', type: 'pcf', bias: 0, shadowSide: 'default', vs: 'rgba-pcf4x4' },
  { id: 'three-pcf-matched', label: 'three.js PCFShadowMap, matched', type: 'pcf', bias: -OUR_BIAS, shadowSide: 'double', vs: 'rgba-pcf4x4' },
];
export const threeOptions = (c, material) => ({ shadowType: c.type, bias: c.bias, normalBias: 0, shadowSide: c.shadowSide,
                                                material, mapSize: MAP, radius: 1 });

export const median = (v) => {
  if (!v.length) return NaN;
  const s = [...v].sort((a, b) => a - b);
  const n = s.length;
  return n % 2 ? s[(n - 1) / 2] : (s[n / 2 - 1] + s[n / 2]) / 2;
};
export const mean = (v) => v.reduce((a, b) => a + b, 0) / v.length;
export const tname = (t) => t.toFixed(2);
export const log = (s) => process.stderr.write(`threejs_compare: ${s}\n`);
export const f2 = (x) => (x === null || x === undefined || Number.isNaN(x) ? 'n/a' : x.toFixed(2));
