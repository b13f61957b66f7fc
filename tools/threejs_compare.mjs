#!/usr/bin/env node
// three.js side by side (issue 4, item 5): the course scene, exported by `penumbra export` at fixed
// times, rendered by three.js (GLTFLoader, WebGL 2; tests/threejs/compare.html) and by penumbra's
// own web build (W09P2c, WebGL 1; build-web/site) in the same headless Chromium, at the same canvas
// size and shadow-map size; both visibility images scored against the same Embree ground truth
// (`penumbra truth --score --json`, one key per column of the score table), both timed the same way
// (median ms/frame, each frame followed by a one-pixel readback). Prints a Markdown table and writes
// docs/threejs.md. The parts are in tools/threejs_compare/ (config, penumbra_cli, browser, scores,
// report, images).
//
// It builds nothing: it needs build/penumbra (export, truth, render), build-web/site and
// node_modules (npm ci: playwright-core, pngjs, three).
//
// usage: node tools/threejs_compare.mjs [--times 0,0.6,2.25,7] [--frames 30] [--rounds 5]
//          [--out-dir out/threejs] [--doc docs/threejs.md | --no-doc] [--cli build/penumbra]
//          [--quick] [--check] [--from-json out/threejs/results.json]
//   --quick   t = 0.6 only, 5 frames, 1 round, penumbra's default rows and the matched one only,
//             no doc and a short table (what the web.threejs test runs)
//   --check   exit 1 unless every output is well formed: scores in range, every visibility image
//             neither all lit nor all dark, the exported camera scoring as penumbra's own, three.js's
//             matched BasicShadowMap within 1 % of the pixels of penumbra's hard filter (never a timing)
//   --from-json  measure nothing: print the table and write the doc again from an earlier run
import { execFileSync } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { siteDir, CHROMIUM } from '../tests/web/harness.mjs';
import { ROOT, log, quickRows } from './threejs_compare/config.mjs';
import { measureInBrowser } from './threejs_compare/browser.mjs';
import { checkCamera, exportScenes, scoreColumns } from './threejs_compare/penumbra_cli.mjs';
import { markdown, writeCsv } from './threejs_compare/report.mjs';
import { scoreRows } from './threejs_compare/scores.mjs';

// ---- options ------------------------------------------------------------------------------------
function usage(message) {
  console.error(`threejs_compare: ${message} (see --help)`);
  process.exit(2);
}

function parseArgs(argv) {
  const o = { times: [0, 0.6, 2.25, 7], frames: 30, rounds: 5, outDir: path.join(ROOT, 'out/threejs'),
              doc: path.join(ROOT, 'docs/threejs.md'), cli: path.join(ROOT, 'build/penumbra'), check: false, quick: false };
  for (let i = 0; i < argv.length; ++i) {
    const a = argv[i];
    const next = () => {
      if (i + 1 >= argv.length) usage(`${a} needs a value`);
      return argv[++i];
    };
    if (a === '--times') o.times = next().split(',').map(Number);
    else if (a === '--frames') o.frames = Number(next());
    else if (a === '--rounds') o.rounds = Number(next());
    else if (a === '--out-dir') o.outDir = path.resolve(next());
    else if (a === '--doc') o.doc = path.resolve(next());
    else if (a === '--no-doc') o.doc = null;
    else if (a === '--cli') o.cli = path.resolve(next());
    else if (a === '--check') o.check = true;
    else if (a === '--from-json') o.fromJson = path.resolve(next());
    else if (a === '--quick') { o.quick = true; o.times = [0.6]; o.frames = 5; o.rounds = 1; o.doc = null; quickRows(); }
    else if (a === '-h' || a === '--help') {
      const lines = readFileSync(new URL(import.meta.url), 'utf8').split('\n').slice(1);
      const end = lines.findIndex((l) => !l.startsWith('//'));
      console.log(lines.slice(0, end).map((l) => l.slice(3)).join('\n'));
      process.exit(0);
    } else usage(`unknown option ${a}`);
  }
  if (!o.times.length || o.times.some((t) => !Number.isFinite(t))) usage('--times: numbers, comma-separated');
  if (!(o.frames >= 1) || !(o.rounds >= 1)) usage('--frames and --rounds must be >= 1');
  return o;
}

// ---- the run --------------------------------------------------------------------------------------
async function main() {
  const o = parseArgs(process.argv.slice(2));
  if (o.fromJson) {
    // Measure nothing: the table and the doc again from an earlier run's results.json.
    const j = JSON.parse(readFileSync(o.fromJson, 'utf8'));
    if (!j.columns) usage(`--from-json ${o.fromJson}: no score columns (written before truth --score --json); run the comparison again`);
    const md = markdown(j.options, j.env, j.columns, j.rows, j.cameraCheck, j.frustum, j.threeSummary, j.agreement);
    console.log(md.table);
    if (o.doc) writeFileSync(o.doc, md.doc);
    return;
  }
  const started = Date.now();
  const loadBefore = os.loadavg()[0];
  for (const need of [o.cli, path.join(ROOT, 'node_modules/three/build/three.module.js')])
    if (!existsSync(need)) throw new Error(`${need} is missing (build/penumbra: cmake --build --preset ci; three: npm ci)`);
  const site = siteDir();
  const dataDir = path.join(o.outDir, 'data');
  const imgDir = path.join(o.outDir, 'images');
  for (const d of [dataDir, imgDir]) mkdirSync(d, { recursive: true });
  const threePkg = JSON.parse(readFileSync(path.join(ROOT, 'node_modules/three/package.json'), 'utf8'));
  const columns = scoreColumns(o.cli);

  // 1. The scenes, 2. the exported camera against penumbra's own (penumbra_cli.mjs).
  const frames = exportScenes(o, dataDir);
  const cameraCheck = checkCamera(o, columns, dataDir, imgDir);
  // 3. The browser: visibility images, then timing (browser.mjs).
  const m = await measureInBrowser(o, site, dataDir, imgDir, frames, started);
  // 4. Scores against the same ground truth (scores.mjs).
  const { rows, failures, agreement } = scoreRows(o, columns, m, cameraCheck);
  const { frustum, threeSummary, threeInfo, oursRenderer } = m;

  // 5. Outputs (report.mjs).
  const env = {
    date: new Date().toISOString().slice(0, 10), cores: os.cpus().length, cpu: os.cpus()[0]?.model || '?',
    chromium: execFileSync(CHROMIUM, ['--version'], { encoding: 'utf8', stdio: ['ignore', 'pipe', 'ignore'] }).trim(), oursRenderer, threeInfo,
    threeVersion: threePkg.version, seconds: Math.round((Date.now() - started) / 1000),
    load: [loadBefore, os.loadavg()[0]],
  };
  writeFileSync(path.join(o.outDir, 'results.json'),
                JSON.stringify({ options: o, env, columns, frustum, threeSummary, cameraCheck, agreement, rows, failures }, null, 1));
  writeCsv(path.join(o.outDir, 'results.csv'), columns, rows, env);
  // The doc's findings name rows --quick does not render: it prints each row's error and time.
  const md = o.quick ? null : markdown(o, env, columns, rows, cameraCheck, frustum, threeSummary, agreement);
  if (md) console.log(md.table);
  else for (const r of rows) console.log(`${r.id.padEnd(22)} error ${r.score.error_pct.toFixed(3)} %  ${r.ms.toFixed(1)} ms/frame`);
  if (o.doc) {
    writeFileSync(o.doc, md.doc);
    log(`wrote ${path.relative(ROOT, o.doc)}`);
  }
  log(`wrote ${path.relative(ROOT, o.outDir)}/results.{json,csv} and images/ in ${env.seconds} s`);
  if (failures.length) {
    log(`problems:\n  ${failures.join('\n  ')}`);
    if (o.check) process.exitCode = 1;
  } else if (o.check) {
    console.log(`PASS threejs_compare --check: ${rows.length} renderings x ${o.times.length} frame(s) well formed, the exported camera scores as penumbra's own`);
  }
}

main().catch((e) => {
  console.error(`threejs_compare: ${e.stack || e}`);
  process.exitCode = 1;
});
