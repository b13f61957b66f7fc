// web.ramp: the depth packing bit-exact on a third implementation, SwiftShader's WebGL 1 (the GL
// ring shows it on llvmpipe and softpipe: gl.Encodings/RampRoundTrip.*). The ramp shader exactly as
// the renderer compiles it (`penumbra shaders` writes every variant's source) draws 65,536 depths
// (256 i + (157 i mod 256)) 2^-24, exact in float32, plus 0, 1, 1 - 2^-24 and 0.5, into an RGBA8
// texture; the bytes read back must be the packing's definition, computed here with exact integer
// arithmetic rather than by a second copy of the shader's steps:
//  - rgba: the depth's 24 bits m = d 2^24, most significant byte first, then 0 (1 is kept at
//    1 - 2^-24, not wrapped to 0), on every pixel, when the context's fragment highp has float32's
//    23 bits (GLSL ES 1.00 4.5.2 asks for 16; the test says so and skips the exactness otherwise);
//  - r8: round(d 255), either byte only where d 255 lies within float rounding of a tie.
// Controls: the same comparison against the depth one step further (m + 1) must miss on every
// pixel, and truncating r8 (floor) on more than a third. Usage: node ramp.mjs PENUMBRA_CLI
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { execFileSync } from 'node:child_process';
import os from 'node:os';
import path from 'node:path';
import { runTest, check } from './harness.mjs';

const cli = process.argv[2];
const W = 256, H = 257, COUNT = 65536;
const SPECIALS = [0, 1, 1 - 2 ** -24, 0.5];

// The variants' sources as the renderer builds them.
function sources() {
  const dir = mkdtempSync(path.join(os.tmpdir(), 'penumbra-ramp-'));
  try {
    execFileSync(cli, ['shaders', '--out', dir], { stdio: 'ignore' });
    const read = (f) => readFileSync(path.join(dir, f), 'utf8');
    return { vert: read('light_depth.vert'), rgba: read('ramp_ENC_RGBA.frag'), r8: read('ramp_ENC_R8.frag') };
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
}

// In the page: each fragment shader's ramp into a W x H RGBA8 texture, read back (bottom row first).
function drawRamps({ vert, frags, W, H, COUNT, SPECIALS }) {
  const canvas = document.createElement('canvas');
  canvas.width = W;
  canvas.height = H;
  const gl = canvas.getContext('webgl', { antialias: false });
  if (!gl) return { error: 'no WebGL 1 context' };
  const highp = gl.getShaderPrecisionFormat(gl.FRAGMENT_SHADER, gl.HIGH_FLOAT).precision;
  const out = { highp, renderer: gl.getParameter(gl.RENDERER), bytes: {} };
  const tex = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, tex);
  gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA, W, H, 0, gl.RGBA, gl.UNSIGNED_BYTE, null);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
  const fb = gl.createFramebuffer();
  gl.bindFramebuffer(gl.FRAMEBUFFER, fb);
  gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, tex, 0);
  if (gl.checkFramebufferStatus(gl.FRAMEBUFFER) !== gl.FRAMEBUFFER_COMPLETE) return { error: 'incomplete framebuffer' };
  const buf = gl.createBuffer();
  gl.bindBuffer(gl.ARRAY_BUFFER, buf);
  gl.bufferData(gl.ARRAY_BUFFER, new Float32Array([-1, -1, 0, 3, -1, 0, -1, 3, 0]), gl.STATIC_DRAW);
  gl.viewport(0, 0, W, H);
  gl.disable(gl.DEPTH_TEST);
  gl.disable(gl.BLEND);
  gl.disable(gl.DITHER);
  for (const [name, frag] of Object.entries(frags)) {
    const shader = (type, src) => {
      const s = gl.createShader(type);
      gl.shaderSource(s, src);
      gl.compileShader(s);
      if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) throw new Error(`${name}: ${gl.getShaderInfoLog(s)}`);
      return s;
    };
    const p = gl.createProgram();
    gl.attachShader(p, shader(gl.VERTEX_SHADER, vert));
    gl.attachShader(p, shader(gl.FRAGMENT_SHADER, frag));
    gl.bindAttribLocation(p, 0, 'a_position');
    gl.linkProgram(p);
    if (!gl.getProgramParameter(p, gl.LINK_STATUS)) return { error: `${name}: ${gl.getProgramInfoLog(p)}` };
    gl.useProgram(p);
    gl.uniform1f(gl.getUniformLocation(p, 'u_width'), W);
    gl.uniform1f(gl.getUniformLocation(p, 'u_count'), COUNT);
    gl.uniform4f(gl.getUniformLocation(p, 'u_specials'), ...SPECIALS);
    gl.enableVertexAttribArray(0);
    gl.vertexAttribPointer(0, 3, gl.FLOAT, false, 0, 0);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    const px = new Uint8Array(W * H * 4);
    gl.readPixels(0, 0, W, H, gl.RGBA, gl.UNSIGNED_BYTE, px);
    out.bytes[name] = Array.from(px);
  }
  out.glError = gl.getError();
  return out;
}

// The 24 bits of ramp depth i (or of a special), 1 kept one quantum below.
function bits24(i) {
  if (i < COUNT) return 256 * i + ((157 * i) % 256);
  return Math.min(Math.round(SPECIALS[i - COUNT] * 2 ** 24), 2 ** 24 - 1);
}

runTest('web.ramp', async ({ browser }) => {
  const { vert, rgba, r8 } = sources();
  const page = await browser.newPage();
  const got = await page.evaluate(drawRamps, { vert, frags: { rgba, r8 }, W, H, COUNT, SPECIALS });
  check(!got.error, got.error);
  check(got.glError === 0, `GL error ${got.glError}`);
  console.log(`${got.renderer}: fragment highp ${got.highp} bits`);
  const n = COUNT + SPECIALS.length;

  if (got.highp < 23) {
    console.log(`SKIP the exact rgba bytes: this context's fragment highp keeps ${got.highp} bits (float32: 23; GLSL ES 1.00 4.5.2 asks for 16)`);
  } else {
    let mismatch = 0, control = 0;
    const px = got.bytes.rgba;
    for (let i = 0; i < n; ++i) {
      const m = bits24(i);
      const want = [m >> 16, (m >> 8) & 255, m & 255, 0];
      const wrong = [(m + 1) >> 16, ((m + 1) >> 8) & 255, (m + 1) & 255, 0];
      const same = (w) => w.every((b, k) => px[i * 4 + k] === b);
      mismatch += !same(want);
      control += !same(wrong);
    }
    console.log(`rgba: ${mismatch} of ${n} depths not packed to their 24 bits; control (one step off) misses ${control}`);
    check(mismatch === 0, `rgba: ${mismatch} depths not packed to their bits`);
    check(control === n, `the control must miss every depth: missed ${control}`);
  }

  // r8: round(d 255), d exact; within 4 units of 2^-23 of d 255 (< 256) of a tie, either byte.
  const tol = 4 * 256 * 2 ** -23;
  let mismatch = 0, ties = 0, control = 0;
  const px = got.bytes.r8;
  for (let i = 0; i < COUNT; ++i) {
    const x = (bits24(i) / 2 ** 24) * 255;  // exact in a double
    const lo = Math.floor(x - tol + 0.5), hi = Math.floor(x + tol + 0.5);
    const b = px[i * 4];
    ties += lo !== hi;
    mismatch += b < lo || b > hi || px[i * 4 + 1] !== 0 || px[i * 4 + 2] !== 0 || px[i * 4 + 3] !== 255;
    const f = Math.floor(x);
    control += f < lo || f > hi;
  }
  console.log(`r8: ${mismatch} of ${COUNT} depths not rounded to their byte (${ties} within rounding of a tie); control (floor) misses ${control}`);
  check(mismatch === 0, `r8: ${mismatch} depths not rounded to their byte`);
  check(control > COUNT / 3, `the control must miss a third: missed ${control}`);
  await page.close();
});
