// What tools/threejs_compare.mjs compares, and the small helpers its modules share.
import path from 'node:path';

export const ROOT = path.resolve(path.dirname(new URL(import.meta.url).pathname), '../..');
export const SIZE = 512;
export const MAP = 1024;

// penumbra's W09P2c page: every encoding, hard and 4x4 PCF, the encoding's default bias.
export const OURS = [
  { id: 'rgba-hard', label: 'rgba hard', encoding: 'rgba', filter: 'hard' },
  { id: 'rgba-pcf4x4', label: 'rgba pcf4x4', encoding: 'rgba', filter: 'pcf4x4' },
  { id: 'depthtex-hard', label: 'depthtex hard', encoding: 'depthtex', filter: 'hard' },
  { id: 'depthtex-pcf4x4', label: 'depthtex pcf4x4', encoding: 'depthtex', filter: 'pcf4x4' },
  { id: 'r8-hard', label: 'r8 hard', encoding: 'r8', filter: 'hard' },
  { id: 'r8-pcf4x4', label: 'r8 pcf4x4', encoding: 'r8', filter: 'pcf4x4' },
];
// penumbra's default bias of rgba and depthtex (README: 0.0015, in window depth units), which
// three.js applies with the opposite sign (shadowCoord.z += bias; lit where z <= depth).
export const OUR_BIAS = 0.0015;
// three.js: BasicShadowMap and PCFShadowMap, each at three.js's defaults (bias 0, normalBias 0, the
// back faces into the map: shadowSide = the opposite of the material's side), with penumbra's bias
// alone, and matched (penumbra's bias, both faces into the map as penumbra draws them).
export const THREE_CONFIGS = [
  { id: 'three-basic-default', label: 'three.js BasicShadowMap, defaults', type: 'basic', bias: 0, shadowSide: 'default', vs: 'rgba-hard' },
  { id: 'three-basic-bias', label: 'three.js BasicShadowMap, bias -0.0015', type: 'basic', bias: -OUR_BIAS, shadowSide: 'default', vs: 'rgba-hard' },
  { id: 'three-basic-matched', label: 'three.js BasicShadowMap, matched', type: 'basic', bias: -OUR_BIAS, shadowSide: 'double', vs: 'rgba-hard' },
  { id: 'three-pcf-default', label: 'three.js PCFShadowMap, defaults', type: 'pcf', bias: 0, shadowSide: 'default', vs: 'rgba-pcf4x4' },
  { id: 'three-pcf-bias', label: 'three.js PCFShadowMap, bias -0.0015', type: 'pcf', bias: -OUR_BIAS, shadowSide: 'default', vs: 'rgba-pcf4x4' },
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
