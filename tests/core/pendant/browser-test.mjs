// The pendant page in a real browser: headless chromium (puppeteer-core) at 390x844 against
// `stepcom --sim --pendant 127.0.0.1:0 --pendant-allow-jog`. It reads both positions by their
// accessible names while motor 1 moves, holds "Motor 1 forward" and sees the motor run, lets go
// and sees it stop, then kills the browser mid-hold and sees (from a second phone watching) the
// motor stop all the same. Exit 77 (ctest: skipped) when chromium, node or puppeteer-core are
// missing.
//   node browser-test.mjs STEPCOM [--shots DIR]
import { spawn } from 'node:child_process';
import { existsSync, mkdirSync } from 'node:fs';
import { createRequire } from 'node:module';

const SKIP = 77;
const chromium = process.env.STEPCOM_CHROMIUM || '/usr/bin/chromium';
const stepcomPath = process.argv[2];
const shotsAt = process.argv.indexOf('--shots');
const shots = shotsAt > 0 ? process.argv[shotsAt + 1] : null;

if (!existsSync(chromium)) {
  console.log(`SKIP: no chromium at ${chromium} (scripts/deps.sh --test installs it)`);
  process.exit(SKIP);
}
let puppeteer;
try {
  puppeteer = createRequire(import.meta.url)('puppeteer-core');
} catch (e) {
  console.log('SKIP: puppeteer-core is not installed (scripts/deps.sh --test runs npm ci in tests/core/pendant)');
  process.exit(SKIP);
}

const children = [];
const browsers = [];
let failed = false;
// The whole test is bounded: whatever hangs, everything started here is killed.
const deadline = setTimeout(() => fail('the test took longer than 90 s'), 90_000);

function fail(why) {
  if (!failed) console.error(`FAIL: ${why}`);
  failed = true;
  cleanup().finally(() => process.exit(1));
}

async function cleanup() {
  clearTimeout(deadline);
  for (const b of browsers) {
    try { b.process()?.kill('SIGKILL'); } catch (e) { /* gone already */ }
  }
  for (const c of children) {
    if (c.exitCode === null) c.kill('SIGKILL');
  }
}

function check(ok, what) {
  if (!ok) throw new Error(what);
  console.log(`ok: ${what}`);
}

const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

async function waitFor(what, test, ms = 10_000) {
  const until = Date.now() + ms;
  for (;;) {
    const value = await test();
    if (value) return value;
    if (Date.now() > until) throw new Error(`timed out waiting: ${what}`);
    await sleep(100);
  }
}

function startStepcom() {
  return new Promise((resolve, reject) => {
    const child = spawn(stepcomPath, ['--sim', '--lang', 'en', '--pendant', '127.0.0.1:0',
      '--pendant-allow-jog'], {
      env: { ...process.env, QT_QPA_PLATFORM: 'offscreen' },
      stdio: ['ignore', 'pipe', 'inherit'],
    });
    children.push(child);
    let out = '';
    child.stdout.on('data', (d) => {
      out += d;
      const m = out.match(/pendant: (http:\/\/\S+)/);
      if (m) resolve(m[1]);
    });
    child.on('exit', (code) => reject(new Error(`stepcom ended (${code}) before saying its address`)));
  });
}

async function phone(url, lang = 'en-US') {
  const browser = await puppeteer.launch({
    executablePath: chromium,
    headless: true,
    args: ['--headless=new', '--no-sandbox', '--disable-gpu', `--lang=${lang}`],
  });
  browsers.push(browser);
  const page = await browser.newPage();
  await page.setExtraHTTPHeaders({ 'Accept-Language': lang });
  await page.setViewport({ width: 390, height: 844, isMobile: true, hasTouch: false });
  await page.goto(url, { waitUntil: 'load' });
  return { browser, page };
}

// The text of the element whose accessible name is `name`, found as a screen reader would.
async function textOf(page, name) {
  const el = await page.waitForSelector(`aria/${name}`, { timeout: 10_000 });
  return el.evaluate((e) => e.textContent.trim());
}

const stateOf = (page, n) => page.$eval(`#state${n}`, (e) => e.className);

async function hold(page, name) {
  const el = await page.waitForSelector(`aria/${name}`);
  await waitFor(`${name} enabled`, () => el.evaluate((e) => !e.disabled));
  const box = await el.boundingBox();
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.down();
}

// Holds the button until `seen` shows motor 1 running. A browser starved on a loaded machine
// may miss its 100 ms holds and StepCom then rightly stops the jog at once: let go, try again.
async function holdUntilRunning(page, seen) {
  for (let attempt = 1; ; ++attempt) {
    await hold(page, 'Motor 1 forward');
    try {
      await waitFor('motor 1 running', async () => (await stateOf(seen, 1)).includes('running'), 4000);
      return;
    } catch (e) {
      if (attempt === 3) throw e;
      await page.mouse.up();
      await waitFor('motor 1 idle before trying again', async () => (await stateOf(seen, 1)).includes('idle'));
    }
  }
}

async function main() {
  if (!stepcomPath) throw new Error('usage: browser-test.mjs STEPCOM');
  const url = await startStepcom();
  check(/^http:\/\/127\.0\.0\.1:\d+\/p\/[0-9a-f]{32}$/.test(url), `stepcom printed ${url}`);

  const watcher = await phone(url);
  const a = await phone(url);
  const page = a.page;
  // Both positions read by their accessible names, once the status arrives.
  await waitFor('motor 1 position', async () => (await textOf(page, 'Motor 1 position')) !== '—');
  const p2 = await textOf(page, 'Motor 2 position');
  check(p2 !== '—', `Motor 2 position reads ${p2}`);
  for (const name of ['Motor 1 forward', 'Motor 1 reverse', 'Motor 2 forward', 'Motor 2 reverse',
    'E-STOP', 'Take control']) {
    check(await page.$(`aria/${name}`) !== null, `"${name}" is on the page`);
  }
  // Phone-sized, portrait and landscape: nothing wider than the screen, every button at least
  // 48 px, the positions at 28 px or more, and scrolled to the end nothing under the E-STOP.
  for (const [width, height] of [[360, 640], [640, 360], [844, 390], [390, 844]]) {
    await page.setViewport({ width, height, isMobile: true });
    await sleep(200);
    const at = `${width}x${height}`;
    const sizes = await page.$$eval('button, select', (all) => all.map((b) => {
      const r = b.getBoundingClientRect();
      return [b.getAttribute('aria-label') || b.id, Math.round(r.width), Math.round(r.height)];
    }));
    check(sizes.every(([, w, h]) => w >= 48 && h >= 48), `${at}: every control at least 48 px: ${JSON.stringify(sizes)}`);
    const font = await page.$eval('#pos1', (e) => parseFloat(getComputedStyle(e).fontSize));
    check(font >= 28, `${at}: positions at ${font} px`);
    const layout = await page.evaluate(() => {
      window.scrollTo(0, document.documentElement.scrollHeight);
      const last = document.querySelector('.safety').getBoundingClientRect();
      const estop = document.getElementById('estop').getBoundingClientRect();
      return { wide: document.documentElement.scrollWidth > innerWidth, covered: last.bottom > estop.top };
    });
    check(!layout.wide && !layout.covered, `${at}: nothing cut (${JSON.stringify(layout)})`);
    await page.evaluate(() => window.scrollTo(0, 0));
  }

  // Take control and hold "Motor 1 forward": it runs, the position grows while read.
  await (await page.waitForSelector('aria/Take control')).click();
  const before = await textOf(page, 'Motor 1 position');
  await holdUntilRunning(page, page);
  check(true, 'holding "Motor 1 forward" runs motor 1');
  const moving = await waitFor('motor 1 position changes', async () => {
    const now = await textOf(page, 'Motor 1 position');
    return now !== before ? now : null;
  });
  check(true, `Motor 1 position ${before} -> ${moving} while it moves; Motor 2 position ${await textOf(page, 'Motor 2 position')}`);
  if (shots) {
    mkdirSync(shots, { recursive: true });
    await page.screenshot({ path: `${shots}/pendant-en.png` });
  }
  await page.mouse.up();
  await waitFor('motor 1 idle after letting go', async () => (await stateOf(page, 1)).includes('idle'));
  check(true, 'letting go stops motor 1');

  // Mid-hold the browser is killed: no stop, no close from the phone; the watcher sees the stop.
  await holdUntilRunning(page, watcher.page);
  a.browser.process().kill('SIGKILL');
  await waitFor('motor 1 stopped after the browser died', async () => (await stateOf(watcher.page, 1)).includes('idle'));
  check(true, 'killing the browser mid-hold stops motor 1');

  if (shots) {
    const zh = await phone(url, 'zh-CN');
    await waitFor('the Chinese page', async () => (await textOf(zh.page, '急停')) !== '');
    await sleep(500);
    await zh.page.screenshot({ path: `${shots}/pendant-zh_CN.png` });
    await zh.page.setViewport({ width: 640, height: 360, isMobile: true });
    await sleep(300);
    await zh.page.screenshot({ path: `${shots}/pendant-zh_CN-landscape.png` });
    await watcher.page.setViewport({ width: 360, height: 640, isMobile: true });
    await sleep(300);
    await watcher.page.screenshot({ path: `${shots}/pendant-360.png` });
  }
}

main().then(async () => {
  await cleanup();
  console.log('PASS');
  process.exit(0);
}, (e) => fail(e.message));
