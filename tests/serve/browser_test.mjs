// End-to-end test of `penumbra serve` in a real headless browser (issue #10): Debian's
// chromium driven by playwright-core (installed into web/node_modules by scripts/setup).
// It starts the server on a free loopback port, loads the page, drags a control point of
// the polar editor and checks that the view changes and that the weights the API reports
// changed as Dobashi 1995 eq. (21) predicts, aims the lamp by clicking the floor (the ID
// buffer, section 4.2) and checks its axis, and takes screenshots. Every wait is on an
// explicit signal from the page (document.body.dataset.ready, window.penumbra.busy).
//
// Environment: PENUMBRA_BINARY (the built penumbra), PENUMBRA_SOURCE_DIR, PENUMBRA_TEST_OUTPUT
// (where screenshots go), PENUMBRA_CHROMIUM (default /usr/bin/chromium),
// PENUMBRA_SERVE_ARGS (extra arguments for serve, e.g. to time a larger mesh).

import {spawn} from 'node:child_process';
import {createRequire} from 'node:module';
import {existsSync, mkdirSync, writeFileSync} from 'node:fs';
import path from 'node:path';
import {fileURLToPath} from 'node:url';
import assert from 'node:assert/strict';

const here = path.dirname(fileURLToPath(import.meta.url));
const sourceDir = process.env.PENUMBRA_SOURCE_DIR || path.resolve(here, '../..');
const binary = process.env.PENUMBRA_BINARY || path.join(sourceDir, 'build/penumbra');
const outputDir = process.env.PENUMBRA_TEST_OUTPUT || path.join(sourceDir, 'out');
const chromiumPath = process.env.PENUMBRA_CHROMIUM || '/usr/bin/chromium';
const scene = path.join(sourceDir, 'fixtures/scenes/serve-room.json');

function fail(message) {
  console.error(`browser_test: ${message}`);
  process.exit(1);
}

const webPackage = path.join(sourceDir, 'web/package.json');
let chromium;
try {
  ({chromium} = createRequire(webPackage)('playwright-core'));
} catch (error) {
  fail(`playwright-core is not installed in web/node_modules (run scripts/setup): ${error.message}`);
}
if (!existsSync(chromiumPath)) fail(`no chromium at ${chromiumPath} (run scripts/setup)`);
if (!existsSync(binary)) fail(`no penumbra binary at ${binary}`);

// === The server: `penumbra serve` on port 0, its URL read from its first line.

function startServer() {
  const extra = (process.env.PENUMBRA_SERVE_ARGS || '').split(' ').filter(Boolean);
  const child = spawn(binary, ['serve', scene, '--port', '0', ...extra], {stdio: ['ignore', 'pipe', 'pipe']});
  let stderr = '';
  child.stderr.on('data', (chunk) => (stderr += chunk));
  return new Promise((resolve, reject) => {
    let stdout = '';
    const timer = setTimeout(() => reject(new Error(`serve did not start in 300 s: ${stderr}`)), 300000);
    child.stdout.on('data', (chunk) => {
      stdout += chunk;
      const match = stdout.match(/http:\/\/127\.0\.0\.1:(\d+)\//);
      if (match) {
        clearTimeout(timer);
        resolve({child, url: match[0]});
      }
    });
    child.on('exit', (code) => {
      clearTimeout(timer);
      reject(new Error(`serve exited with ${code}: ${stderr}`));
    });
  });
}

// P_0(x) .. P_n(x) by Bonnet's recurrence (the test's own, not the page's or the library's).
function legendre(n, x) {
  const p = [1, x];
  for (let l = 1; l < n; ++l) p.push(((2 * l + 1) * x * p[l] - l * p[l - 1]) / (l + 1));
  return p.slice(0, n + 1);
}

async function getJson(url) {
  const response = await fetch(url);
  assert.equal(response.status, 200, `GET ${url}`);
  return response.json();
}

// waits until the page has no request in flight and has drawn more relit frames than frames.
async function settled(page, frames) {
  await page.waitForFunction(
      (before) => window.penumbra.busy === 0 && window.penumbra.relitFrames > before, frames,
      {timeout: 60000});
}

async function main() {
  mkdirSync(outputDir, {recursive: true});
  const {child, url} = await startServer();
  const browser = await chromium.launch({
    executablePath: chromiumPath,
    headless: true,
    // WebGL 2 without a GPU: ANGLE on SwiftShader
    args: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist', '--no-sandbox'],
  });
  const problems = [];
  try {
    const page = await browser.newPage({viewport: {width: 1280, height: 800}, deviceScaleFactor: 1});
    page.on('pageerror', (error) => problems.push(`page error: ${error.message}`));
    page.on('console', (message) => {
      if (message.type() === 'error') problems.push(`console error: ${message.text()}`);
    });
    await page.goto(url);
    await page.waitForFunction(() => document.body.dataset.ready === 'true', null, {timeout: 120000});
    // The scene was given by its absolute path: the page names the file only.
    assert.equal(await page.textContent('#scene-name'), path.basename(scene));
    assert.deepEqual(problems, []);
    const view = page.locator('#view');

    // --- Drag a control point of the downlight (section 4.1)
    await page.evaluate(() => window.penumbra.selectLamp('downlight'));
    const lamp = 'downlight';
    const before = await getJson(`${url}api/lights/${lamp}`);
    const viewBefore = await view.screenshot();
    const k = 3;  // 30 degrees
    const gamma = (before.controls.angles_deg[k] * Math.PI) / 180;
    const [x0, y0] = await page.evaluate((index) => window.penumbra.controlPointClientPosition(index), k);
    const frames = await page.evaluate(() => window.penumbra.relitFrames);
    await page.mouse.move(x0, y0);
    await page.mouse.down();
    for (let step = 1; step <= 6; ++step)  // outward along the point's ray: more candela
      await page.mouse.move(x0 + step * 10 * Math.sin(gamma), y0 + step * 10 * Math.cos(gamma));
    await page.mouse.up();
    await settled(page, frames);
    const after = await getJson(`${url}api/lights/${lamp}`);
    const viewAfter = await view.screenshot();
    assert.ok(!viewBefore.equals(viewAfter), 'the view did not change after the drag');

    // Only control point k moved, outward.
    const oldI = before.controls.candela[k], newI = after.controls.candela[k];
    assert.ok(newI > oldI + 1, `control point ${k} did not move out: ${oldI} -> ${newI}`);
    before.controls.candela.forEach((value, i) => {
      if (i !== k) assert.equal(after.controls.candela[i], value, `control point ${i} moved`);
    });
    // Eq. (21): w_l += (2l + 1) / 2 t_k (I_new - I_old) P_l(cos gamma_k) sin(gamma_k) dgamma.
    const M = before.controls.candela.length - 1;
    const dGamma = Math.PI / M, t = k === 0 || k === M ? 0.5 : 1;
    const p = legendre(before.weights.length - 1, Math.cos(gamma));
    const scale = Math.max(...before.weights.map(Math.abs));
    before.weights.forEach((w, l) => {
      const expected = w + ((2 * l + 1) / 2) * t * (newI - oldI) * p[l] * Math.sin(gamma) * dGamma;
      assert.ok(Math.abs(after.weights[l] - expected) <= 1e-9 * scale,
                `w_${l}: ${after.weights[l]} != ${expected} (eq. 21)`);
    });
    const latency = await page.evaluate(() => [window.penumbra.lastLatencyMs, window.penumbra.lastServerMs]);
    console.log(`drag: I(${before.controls.angles_deg[k]} deg) ${oldI.toFixed(1)} -> ${newI.toFixed(1)} cd; ` +
                `edit -> frame ${latency[0].toFixed(1)} ms (server relight ${latency[1].toFixed(2)} ms)`);

    // --- Aim the lamp by clicking the floor (section 4.2)
    const target = [1.0, 1.0, 0.0];
    const click = await page.evaluate((p) => window.penumbra.worldToClient(p), target);
    assert.ok(click, 'the floor point is behind the eye');
    const picked = await page.evaluate(([x, y]) => window.penumbra.pickClient(x, y), click);
    assert.ok(picked, 'nothing under the floor point');
    const pickedLux = await getJson(`${url}api/lux?patch=${picked.patch}`);
    assert.equal(pickedLux.object, 'floor', 'the ID buffer did not find the floor');
    const aimFrames = await page.evaluate(() => window.penumbra.relitFrames);
    await page.click('#aim');
    await page.mouse.click(click[0], click[1]);
    await settled(page, aimFrames);
    const aimed = await getJson(`${url}api/lights/${lamp}`);
    // The axis from the lamp must meet the floor (z = 0) at the clicked point, to within
    // the size of a pixel there (a few millimetres).
    const [px, py, pz] = aimed.position, [ax, ay, az] = aimed.axis;
    assert.ok(az < 0, 'the lamp does not point down');
    const s = -pz / az;
    const hit = [px + s * ax, py + s * ay];
    const miss = Math.hypot(hit[0] - target[0], hit[1] - target[1]);
    assert.ok(miss < 0.02, `the lamp aims at (${hit}), ${miss} m from the clicked (${target})`);
    console.log(`aim: clicked floor patch ${picked.patch}; axis meets the floor ${(miss * 1000).toFixed(1)} mm from the point`);

    // --- Screenshots: the relit room, then with the isolux overlay
    await page.mouse.move(click[0] + 40, click[1] - 30);
    await page.waitForFunction(() => !document.getElementById('cursor-lux').hidden, null, {timeout: 10000});
    await page.screenshot({path: path.join(outputDir, 'serve-e2e-relit.png')});
    await page.click('#isolux');
    await page.mouse.move(click[0] + 40, click[1] - 30);
    await page.waitForFunction(() => !document.getElementById('cursor-lux').hidden, null, {timeout: 10000});
    const label = await page.textContent('#cursor-lux');
    assert.match(label, /lx/);
    const screenshot = path.join(outputDir, 'serve-e2e.png');
    await page.screenshot({path: screenshot});
    console.log(`screenshot ${screenshot}; cursor shows "${label}"`);

    // --- Latency over repeated edits (median), section "Speed" of docs/serve.md
    const latencies = [];
    for (let i = 0; i < 15; ++i) {
      const before = await page.evaluate(() => window.penumbra.relitFrames);
      const [x, y] = await page.evaluate((index) => window.penumbra.controlPointClientPosition(index), 2);
      await page.mouse.move(x, y);
      await page.mouse.down();
      await page.mouse.move(x + (i % 2 ? -8 : 8) * Math.sin(Math.PI / 9), y + (i % 2 ? -8 : 8) * Math.cos(Math.PI / 9));
      await page.mouse.up();
      await settled(page, before);
      latencies.push(await page.evaluate(() => window.penumbra.lastLatencyMs));
      if (process.env.PENUMBRA_VERBOSE)
        console.log(JSON.stringify(await page.evaluate(() => window.penumbra.lastBreakdown)));
    }
    latencies.sort((a, b) => a - b);
    const sceneInfo = await getJson(`${url}api/scene`);
    console.log(`edit -> frame over 15 drags, ${sceneInfo.patches} patches: median ${latencies[7].toFixed(1)} ms, ` +
                `max ${latencies[14].toFixed(1)} ms`);
    assert.deepEqual(problems, []);
  } finally {
    await browser.close();
    child.kill('SIGTERM');
  }
  console.log('browser_test: passed');
}

main().catch((error) => fail(error.stack || String(error)));
