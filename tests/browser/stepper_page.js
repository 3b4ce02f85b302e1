// Browser test of `mpr step INPUT --html DIR`: Debian's chromium, headless,
// driven by playwright-core, opens the page from a file:// URL and checks
// what a user sees: no console errors, one tree entry per pass, keyboard
// stepping that changes the views, and a click on a pixel that shows the
// very lines `mpr step INPUT --pixel X,Y` prints. Saves a screenshot.
//
// node stepper_page.js MPR SOURCE_DIR INPUT OUT_DIR [X,Y ...]
//   INPUT is relative to SOURCE_DIR; the screenshot is OUT_DIR/<input name>.png.
//   Each X,Y is a pixel to click (window coordinates); by default the centre.
'use strict';
const { chromium } = require('playwright-core');
const { execFileSync } = require('child_process');
const assert = require('assert');
const fs = require('fs');
const os = require('os');
const path = require('path');
const { pathToFileURL } = require('url');

const [mpr, source, input, outDir, ...pixelArgs] = process.argv.slice(2);
const name = path.basename(input).replace(/\.[^.]*$/, '');
const started = Date.now();
const log = (...a) => console.log('[' + ((Date.now() - started) / 1000).toFixed(1) + ' s]', ...a);

function run(...args) {
  return execFileSync(mpr, args, { cwd: source, encoding: 'utf8', maxBuffer: 1 << 28, stdio: ['ignore', 'pipe', 'pipe'] });
}

async function main() {
  const work = fs.mkdtempSync(path.join(os.tmpdir(), 'mpr-browser-'));
  let context;
  try {
    const passCount = run('step', input).trim().split('\n').length;
    const pageDir = path.join(work, 'page');
    log(run('step', input, '--html', pageDir).trim());
    context = await chromium.launchPersistentContext(path.join(work, 'profile'), {
      executablePath: '/usr/bin/chromium',
      headless: true,
      args: ['--headless', '--no-sandbox', '--disable-gpu', '--no-first-run', '--disable-background-networking',
             '--disable-component-update', '--disable-sync'],
      viewport: { width: 1600, height: 1000 },
    });
    const page = context.pages()[0] || (await context.newPage());
    const problems = [];
    page.on('console', (m) => { if (m.type() === 'error' || m.type() === 'warning') problems.push(m.type() + ': ' + m.text()); });
    page.on('pageerror', (e) => problems.push('page error: ' + e.message));
    page.on('requestfailed', (r) => problems.push('request failed: ' + r.url()));

    await page.goto(pathToFileURL(path.join(pageDir, 'index.html')).href);
    const shown = (value) => page.waitForSelector('body[data-shown="' + value + '"]', { timeout: 30000 });
    await shown('0:after');
    log('page loaded');

    // One tree entry per pass of the recording.
    assert.strictEqual(await page.locator('#tree li.pass').count(), passCount, 'tree entries vs `mpr step` passes');

    // Stepping with the keyboard changes the views; stepping back restores them.
    const views = () => page.evaluate(() => Array.from(document.querySelectorAll('#views canvas'), (c) => {
      const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
      let h = 0;
      for (let i = 0; i < d.length; ++i) h = (h * 31 + d[i]) >>> 0;
      return h;
    }));
    const first = await views();
    let changedAt = -1;
    for (let p = 1; p < passCount && changedAt < 0; ++p) {
      await page.keyboard.press(p % 2 ? 'ArrowDown' : 'j');
      await shown(p + ':after');
      if (JSON.stringify(await views()) !== JSON.stringify(first)) changedAt = p;
    }
    assert.ok(changedAt > 0, 'no pass changed any view');
    log('stepping to pass ' + changedAt + ' changed the views');
    await page.keyboard.press('Home');
    await shown('0:after');
    assert.deepStrictEqual(await views(), first, 'back at pass 0 the views are as they were');
    await page.keyboard.press('b');
    await shown('0:before');
    await page.keyboard.press('b');
    await shown('0:after');

    // Clicking a pixel shows the same history as `mpr step INPUT --pixel X,Y`.
    const [W, H] = await page.evaluate(() => [window.MPR_STEP.width, window.MPR_STEP.height]);
    const pixels = pixelArgs.length ? pixelArgs.map((a) => a.split(',').map(Number)) : [[W >> 1, H >> 1]];
    const last = passCount - 1;
    await page.keyboard.press('End');
    await shown(last + ':after');
    await page.keyboard.press('z');  // large views: one frame pixel is at least one screen pixel
    for (const [x, y] of pixels) {
      await page.locator('#view-stencil').scrollIntoViewIfNeeded();
      const box = await page.locator('#view-stencil').boundingBox();
      // Mouse events land on whole CSS pixels: the first one inside the frame pixel.
      const sx = box.width / W, sy = box.height / H;
      assert.ok(sx >= 1 && sy >= 1, 'large views draw a frame pixel on at least one screen pixel');
      await page.mouse.click(Math.ceil(box.x + x * sx + 0.01), Math.ceil(box.y + (H - 1 - y) * sy + 0.01));
      await page.waitForSelector('body[data-pixel="' + x + ',' + y + ':' + last + ':after"]', { timeout: 30000 });
      const [px, py] = [x, y];
      const cli = run('step', input, '--pixel', px + ',' + py).replace(/\n$/, '').split('\n');
      const history = await page.locator('#history').textContent();
      const value = await page.locator('#pixel-value').textContent();
      assert.strictEqual(history, cli.slice(1, -1).join('\n'), 'history of pixel ' + px + ',' + py + ' at the last pass');
      assert.strictEqual('final: ' + value, cli[cli.length - 1], 'value of pixel ' + px + ',' + py);
      // Up to a middle pass: the CLI's lines of passes 0 .. mid only.
      const mid = Math.floor(last / 2);
      await page.locator('#tree li.pass[data-pass="' + mid + '"]').click();
      await page.waitForSelector('body[data-pixel="' + px + ',' + py + ':' + mid + ':after"]', { timeout: 30000 });
      const upTo = [];
      let pass = -1;
      for (const line of cli.slice(1, -1)) {
        const m = /^pass (\d+) "/.exec(line);
        if (m) pass = Number(m[1]);
        if (pass <= mid) upTo.push(line);
      }
      assert.strictEqual(await page.locator('#history').textContent(), upTo.join('\n'), 'history up to pass ' + mid);
      await page.keyboard.press('End');
      await shown(last + ':after');
      log('pixel ' + px + ',' + py + ': ' + (cli.length - 2) + ' history lines, the same as --pixel');
    }

    await page.keyboard.press('z');
    // A screenshot at the deepest shadow-volume pass (or the last pass), the last pixel selected.
    const showcase = await page.evaluate(() => {
      let best = -1, depth = -1;
      window.MPR_STEP.passes.forEach((p, i) => {
        const d = p.label.split(' > ').length;
        if (/make_all_shadows/.test(p.label) && d > depth) { best = i; depth = d; }
      });
      return best >= 0 ? best : window.MPR_STEP.passes.length - 1;
    });
    await page.locator('#tree li.pass[data-pass="' + showcase + '"]').click();
    await shown(showcase + ':after');
    fs.mkdirSync(outDir, { recursive: true });
    const shot = path.join(outDir, name + '.png');
    await page.screenshot({ path: shot });
    log('screenshot ' + shot);

    assert.deepStrictEqual(problems, [], 'console errors or warnings');
    log('ok');
  } finally {
    if (context) await context.close();
    fs.rmSync(work, { recursive: true, force: true });
  }
}

main().catch((e) => {
  console.error('FAIL: ' + (e && e.stack ? e.stack : e));
  process.exit(1);
});
