// web.pcf, on W09P2c: the 4x4 PCF checkbox changes the shadow's edge pixels and nothing else.
// At a fixed t, in the visibility view (white lit, black shadowed), with the 8-bit encoding and its
// 0.005 bias (no acne on the table). An edge pixel is one whose 4-neighbourhood holds both lit and
// shadowed pixels in the hard image; every pixel PCF changes must lie within EDGE_RADIUS pixels of
// one, and PCF must leave fractions there. The teapot's own surface is left out of the check (found
// by its colour in the colour view): with a constant bias its curved, light-facing side shadows
// itself under PCF's outer taps, +-1.5 texels away (acne, which a slope-scaled bias removes), so
// the check covers the table, where the teapot's shadow falls, and the background.
import { runTest, openPage, frameAt, compare, check } from './harness.mjs';

const T = 0.6;
const EDGE_RADIUS = 6;  // pixels: the 4x4 kernel spans +-1.5 texels of a 1024 map, about 1-3 px here

// Chebyshev distance (in pixels, capped at cap) from every pixel to the nearest edge pixel.
function edgeDistance(img, cap) {
  const { width: w, height: h, data } = img;
  const lit = (x, y) => data[4 * (y * w + x)] >= 128;
  const dist = new Uint16Array(w * h).fill(cap);
  let frontier = [];
  for (let y = 0; y < h; ++y)
    for (let x = 0; x < w; ++x) {
      const v = lit(x, y);
      if ((x > 0 && lit(x - 1, y) !== v) || (x + 1 < w && lit(x + 1, y) !== v) ||
          (y > 0 && lit(x, y - 1) !== v) || (y + 1 < h && lit(x, y + 1) !== v)) {
        dist[y * w + x] = 0;
        frontier.push(y * w + x);
      }
    }
  for (let d = 1; d < cap && frontier.length; ++d) {
    const next = [];
    for (const i of frontier) {
      const x = i % w, y = (i - x) / w;
      for (let dy = -1; dy <= 1; ++dy)
        for (let dx = -1; dx <= 1; ++dx) {
          const nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
          const j = ny * w + nx;
          if (dist[j] > d) {
            dist[j] = d;
            next.push(j);
          }
        }
    }
    frontier = next;
  }
  return dist;
}

await runTest('web.pcf', async ({ server, browser }) => {
  const { page, problems } = await openPage(browser, `${server.url}/w09p2c.html?map-view=off&encoding=r8&bias=0.005`);
  const colour = await frameAt(page, T);
  const teapot = new Uint8Array(colour.width * colour.height);
  for (let y = 0; y < colour.height; ++y)
    for (let x = 0; x < colour.width; ++x) {
      const i = 4 * (y * colour.width + x);
      const [r, g, b] = [colour.data[i], colour.data[i + 1], colour.data[i + 2]];
      if (r > 20 && r > 1.25 * g && r > 1.5 * b)  // porcelain orange, lit or not; marble is white-blue
        for (let dy = -1; dy <= 1; ++dy)
          for (let dx = -1; dx <= 1; ++dx) {
            const nx = x + dx, ny = y + dy;
            if (nx >= 0 && ny >= 0 && nx < colour.width && ny < colour.height) teapot[ny * colour.width + nx] = 1;
          }
    }
  await page.selectOption('#aov', 'visibility');
  check(!(await page.isChecked('#filter')), 'PCF starts checked');
  const hard = await frameAt(page, T);
  await page.check('#filter');
  check(new URL(page.url()).searchParams.get('filter') === 'pcf4x4', `the URL does not say filter=pcf4x4: ${page.url()}`);
  const pcf = await frameAt(page, T);

  const diff = compare(hard, pcf, 2);
  const dist = edgeDistance(hard, 255);
  let far = 0, maxDist = 0, fractions = 0, edges = 0, onTeapot = 0;
  for (let i = 0; i < diff.mask.length; ++i) {
    if (teapot[i]) {
      if (diff.mask[i]) ++onTeapot;
      continue;
    }
    if (dist[i] === 0) ++edges;
    const v = pcf.data[4 * i];
    if (v > 8 && v < 247) ++fractions;
    if (!diff.mask[i]) continue;
    maxDist = Math.max(maxDist, dist[i]);
    if (dist[i] > EDGE_RADIUS) ++far;
  }
  const changed = diff.differing - onTeapot;
  console.log(`hard -> pcf4x4 at t=${T}, off the teapot: ${changed} pixels changed, ${fractions} with PCF fractions, ` +
              `${edges} edge pixels in the hard image; farthest change ${maxDist} px from an edge ` +
              `(allowed ${EDGE_RADIUS}), ${far} beyond. On the teapot (not checked): ${onTeapot} changed`);
  check(changed > 500, `PCF changed only ${changed} pixels off the teapot`);
  check(fractions > 500, `PCF left only ${fractions} pixels between lit and shadowed`);
  check(far === 0, `${far} pixels changed farther than ${EDGE_RADIUS} px from any shadow edge (farthest ${maxDist})`);

  // And back: unchecking restores the hard image exactly.
  await page.uncheck('#filter');
  const again = await frameAt(page, T);
  check(compare(hard, again).differing === 0, 'unchecking PCF does not give the hard image back');
  check(problems.length === 0, problems.join('; '));
});
