// threejs_compare's scores: every visibility image scored against the same ground truth by
// `penumbra truth --score --json`, one value per score column (the table in
// src/measure/score_columns.cpp), and the checks --check applies to them.
import { readFileSync } from 'node:fs';
import { PNG } from 'pngjs';
import { OURS, SIZE, THREE_CONFIGS, log, mean, median } from './config.mjs';
import { histogram, imageDiff } from './images.mjs';
import { score } from './penumbra_cli.mjs';

// Each column's mean over several scores (a configuration over the times), over those that have
// it; null where none has it (the area-light error: there is no area-light truth here).
export function meanScore(columns, scores) {
  const out = {};
  for (const c of columns) {
    const v = scores.map((s) => s[c.key]).filter((x) => x !== null && x !== undefined);
    out[c.key] = v.length ? mean(v) : null;
  }
  return out;
}

// Scores every image, with the well-formedness checks: returns {rows, failures, agreement}.
// rows: one per configuration: {kind, id, label, c, per: [{t, score, hist}], score (the mean over
// the times), ms, msRounds, msStandard, ratio, ratioDepthtex}.
export function scoreRows(o, columns, m, cameraCheck) {
  const { images, ms, problems, threeInfo } = m;
  log('scoring against the ground truth (penumbra truth --score --json)');
  const rows = [];
  const failures = [...problems];
  for (const [kind, list] of [['ours', OURS], ['three', THREE_CONFIGS]]) {
    for (const c of list) {
      const per = o.times.map((t) => {
        const file = images[c.id][t];
        const s = score(o, columns, t, file);
        const h = histogram(PNG.sync.read(readFileSync(file)));
        if (h.lit === h.n || h.dark === h.n) failures.push(`${c.id} at t=${t}: the visibility image is all ${h.lit === h.n ? 'lit' : 'dark'}`);
        if (h.dark + h.grey < 0.01 * h.n) failures.push(`${c.id} at t=${t}: no shadow (${h.dark + h.grey} px)`);
        if (h.lit < 0.1 * h.n) failures.push(`${c.id} at t=${t}: nearly all dark (${h.lit} px lit)`);
        for (const col of columns) {
          const v = s[col.key];
          if (v === null ? !col.optional : !(Number.isFinite(v) && v >= 0 && (!col.key.endsWith('_pct') || v <= 100)))
            failures.push(`${c.id} at t=${t}: ${col.key} ${v} out of range`);
        }
        if (Math.abs(s.false_shadow_pct + s.false_lit_pct - s.error_pct) > 0.01) failures.push(`${c.id} at t=${t}: error != false shadow + false lit`);
        if (!(s.valid_pixels > 0.2 * SIZE * SIZE)) failures.push(`${c.id} at t=${t}: only ${s.valid_pixels} valid pixels`);
        if (!(s.error_pct < 50)) failures.push(`${c.id} at t=${t}: error ${s.error_pct} %: the frames do not match`);
        return { t, score: s, hist: h };
      });
      rows.push({
        kind, id: c.id, label: c.label, c, per,
        score: meanScore(columns, per.map((p) => p.score)),
        ms: median(ms[c.id]), msRounds: ms[c.id],
        msStandard: ms[`${c.id}-standard`] ? median(ms[`${c.id}-standard`]) : null,
      });
    }
  }
  const byId = Object.fromEntries(rows.map((r) => [r.id, r]));
  for (const r of rows) {
    if (r.kind !== 'three') continue;
    // The median over the rounds of each round's ratio (both sides measured in the same round).
    const ratio = (other) => median(r.msRounds.map((v, i) => v / byId[other].msRounds[i]));
    r.ratio = ratio(r.c.vs);
    r.ratioDepthtex = ratio(r.c.vs.replace('rgba', 'depthtex'));
  }
  for (const r of rows) {
    if (r.kind !== 'ours') continue;
    // Ours against three.js at its defaults with the same kind of filter, in the same rounds; and
    // whether ours is at equal or lower error (and, for PCF, mean absolute error).
    const three = byId[r.c.filter === 'hard' ? 'three-basic-default' : 'three-pcf-default'];
    if (!three) continue;
    r.vsThree = three.id;
    r.ratioThree = median(r.msRounds.map((v, i) => v / three.msRounds[i]));
    r.notWorse = r.score.error_pct <= three.score.error_pct + 1e-9 &&
                 (r.c.filter === 'hard' || r.score.mae_pct <= three.score.mae_pct + 1e-9);
  }
  for (const cc of cameraCheck) {
    // The glTF holds the matrices as float32, as penumbra does; a pixel or two on an edge may round the other way.
    if (cc.differing > 1e-4 * SIZE * SIZE) failures.push(`the exported glTF at t=${cc.t} renders ${cc.differing} px differently from the built-in scene`);
    if (Math.abs(cc.teapot.error_pct - cc.gltf.error_pct) > 0.01 || cc.teapot.valid_pixels !== cc.gltf.valid_pixels)
      failures.push(`the exported glTF at t=${cc.t} scores ${cc.gltf.error_pct} % against the built-in scene's ${cc.teapot.error_pct} %`);
  }
  if (threeInfo && !threeInfo.webgl2) failures.push('three.js did not get a WebGL 2 context');
  // With penumbra's frustum, bias and faces, three.js's one-tap map must see what penumbra's does:
  // pixel by pixel, the matched BasicShadowMap against penumbra's hard filter at the same settings
  // (the PCF kernels differ, and no other row of penumbra's shares three.js's settings).
  const pairs = [['three-basic-matched', 'depthtex-hard-matched']];
  const agreement = pairs.map(([a, b]) => ({ a, b, per: o.times.map((t) => ({ t, ...imageDiff(images[a][t], images[b][t]) })) }));
  for (const p of agreement[0].per)
    if (p.fraction > 0.01) failures.push(`three.js matched BasicShadowMap and penumbra depthtex hard differ in ${(100 * p.fraction).toFixed(2)} % of the pixels at t=${p.t}`);
  return { rows, failures, agreement };
}
