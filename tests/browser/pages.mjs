// Kerf's HTML pages in a real browser: Debian's chromium driven by puppeteer-core (which downloads
// no browser), both installed by .ci/install-deps.sh --tests. Called by tests/tools/browser_test.cmake:
//
//   node pages.mjs report DIR SHOTS [PAGE...]  every page of a report (the index, the programs' pages,
//                                              their 3D pages): no console error, no failed request,
//                                              every link and picture resolves; screenshots of the
//                                              index and of each PAGE into SHOTS
//   node pages.mjs part FILE SHOTS             the 3D page of samples/sector_r40.nc: a click on line 15
//                                              selects the arc and draws both candidate centres; Up and
//                                              Down step; a click on the part selects its block; the
//                                              findings and passes lists; offline; a screenshot
//   node pages.mjs hostile FILE...             pages of programs that try to be markup: the page's own
//                                              title, no element from the input, the page still works
//   node pages.mjs open COLOUR FILE...         3D pages that open in that colouring with no error, every
//                                              colouring drawn in turn
//   node pages.mjs orbit FILE FRAMES           the frame rate of a scripted orbit (tests/bench)
//
// Environment: KERF_TEST_TOOLS (the folder whose node_modules holds puppeteer-core), CHROMIUM.
// Exit status 0 when every check holds; each failure is printed.
import { createRequire } from 'node:module';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

const tools = process.env.KERF_TEST_TOOLS || '/opt/kerf-test-tools';
const puppeteer = createRequire(path.join(tools, 'node_modules', '/'))('puppeteer-core');
const failures = [];
const fail = (what) => { failures.push(what); console.error('FAIL: ' + what); };
const check = (ok, what) => { if (!ok) fail(what); };

async function launch() {
  return puppeteer.launch({
    executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
    protocolTimeout: 900000, // ms: an exact 10⁶-triangle page draws a frame in seconds on SwiftShader
    headless: true,
    // WebGL on SwiftShader (no GPU); no background traffic (this network is closed).
    args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--no-first-run',
           '--disable-background-networking', '--disable-component-update', '--disable-sync',
           '--font-render-hinting=none', '--hide-scrollbars'],
  });
}

/// A page that reports console errors, page errors and any request that leaves the file system.
async function openPage(browser, file) {
  const page = await browser.newPage();
  await page.setViewport({ width: 1280, height: 800, deviceScaleFactor: 1 });
  const name = path.basename(file);
  page.on('console', (m) => { if (m.type() === 'error') fail(name + ': console error: ' + m.text()); });
  page.on('pageerror', (e) => fail(name + ': script error: ' + e.message));
  page.on('requestfailed', (r) => fail(name + ': request failed: ' + r.url()));
  await page.setRequestInterception(true);
  page.on('request', (r) => {
    const url = r.url();
    if (url.startsWith('file:') || url.startsWith('data:')) return r.continue();
    fail(name + ': asks the network for ' + url);
    return r.abort();
  });
  await page.setOfflineMode(true);
  await page.goto(pathToFileURL(file).href, { waitUntil: 'load', timeout: 300000 });
  return page;
}

async function waitReady(page, file) {
  try {
    await page.waitForFunction(() => document.documentElement.dataset.ready === '1', { timeout: 30000 });
  } catch (e) {
    fail(path.basename(file) + ': its script never marked it ready');
  }
}

/// Every link, picture and script of the page names a file that is there; pictures decoded.
async function checkLinks(page, file) {
  const refs = await page.evaluate(() => [
    ...Array.from(document.querySelectorAll('a[href]'), (a) => a.href),
    ...Array.from(document.querySelectorAll('img[src]'), (i) => i.src),
    ...Array.from(document.querySelectorAll('script[src]'), (s) => s.src),
  ]);
  const local = [];
  for (const ref of refs) {
    const url = new URL(ref);
    if (url.protocol !== 'file:') { fail(path.basename(file) + ': links out of the report: ' + ref); continue; }
    const target = fileURLToPath(url.origin === 'null' ? 'file://' + url.pathname : url.href.split('#')[0]);
    check(fs.existsSync(target), path.basename(file) + ': broken link ' + ref);
    if (target.endsWith('.html')) local.push(target);
  }
  const broken = await page.evaluate(() =>
    Array.from(document.images).filter((i) => !i.complete || i.naturalWidth === 0).map((i) => i.src));
  for (const src of broken) fail(path.basename(file) + ': picture not shown: ' + src);
  return local;
}

async function report(dir, shots, shotPages) {
  const browser = await launch();
  const seen = new Set();
  const queue = [path.join(dir, 'index.html')];
  while (queue.length) {
    const file = queue.shift();
    if (seen.has(file)) continue;
    seen.add(file);
    const page = await openPage(browser, file);
    if (file.endsWith('.3d.html') || file.endsWith('index.html')) await waitReady(page, file);
    for (const next of await checkLinks(page, file)) queue.push(next);
    const base = path.basename(file);
    if (base === 'index.html' || shotPages.includes(base))
      await page.screenshot({ path: path.join(shots, base.replace(/\.html$/, '') + '.png') });
    await page.close();
  }
  const pages = fs.readdirSync(dir).filter((f) => f.endsWith('.html'));
  check(seen.size === pages.length, 'the index leads to every page (' + seen.size + ' of ' + pages.length + ')');
  console.log('loaded ' + seen.size + ' pages');
  await browser.close();
}

async function part(file, shots) {
  const browser = await launch();
  const page = await openPage(browser, file);
  await waitReady(page, file);
  const state = () => page.evaluate(() => ({ line: window.kerf.selectedLine, move: window.kerf.selectedMove,
                                             roles: window.kerf.drawnRoles,
                                             moveLine: window.kerf.selectedMove === null ? null
                                               : window.kerf.lineOfMove(window.kerf.selectedMove) }));
  await page.click('#tools button:nth-child(1)'); // top
  await page.click('#lines div[data-line="15"]');
  let s = await state();
  check(s.line === 15 && s.move !== null && s.moveLine === 15, 'a click on line 15 selects its move: ' + JSON.stringify(s));
  check(s.roles.includes('centre') && s.roles.includes('rejected'), 'both candidate centres drawn: ' + s.roles);
  check(s.roles.includes('chord') && s.roles.includes('bisector'), 'the chord and its bisector drawn: ' + s.roles);
  const text = await page.$eval('#construction', (e) => e.textContent);
  check(text.includes('G03 X0 Y40. R40.') && text.includes('rejected'), 'the construction is said: ' + text.slice(0, 120));
  await new Promise((r) => setTimeout(r, 200));
  await page.screenshot({ path: path.join(shots, 'sector_r40_line15.png') });
  await page.keyboard.press('ArrowDown');
  check((await state()).line === 16, 'Down steps to line 16');
  await page.keyboard.press('ArrowUp');
  await page.keyboard.press('ArrowUp');
  check((await state()).line === 14, 'Up steps back to line 14');
  // A click on the arc's wall, half way round and half way up, in iso, selects line 15 again.
  await page.click('#tools button:nth-child(4)'); // iso: the wall seen from the side
  const iso = await page.evaluate(() => {
    const d = JSON.parse(document.getElementById('kerf-data').textContent).scene;
    return window.kerf.project(40 * Math.SQRT1_2, 40 * Math.SQRT1_2, (d.boundsMin[2] + d.boundsMax[2]) / 2);
  });
  await page.mouse.click(iso.x, iso.y);
  check((await state()).line === 15, 'a click on the arc selects line 15 (at ' + JSON.stringify(iso) + ')');
  // The finding (the lead-out over the lead-in, line 17) selects its block.
  await page.click('#findings li');
  check((await state()).line === 17, 'a click on the finding selects line 17');
  // Passes hidden leave their surface out.
  const all = await page.evaluate(() => window.kerf.shownTriangles());
  await page.click('#passes input');
  const hidden = await page.evaluate(() => window.kerf.shownTriangles());
  check(all > 0 && hidden < all, 'hiding the pass hides its surface (' + all + ' -> ' + hidden + ')');
  await browser.close();
}

async function hostile(files) {
  const browser = await launch();
  for (const file of files) {
    const page = await openPage(browser, file);
    const part = (await page.$('#kerf-data')) !== null;
    if (part) await waitReady(page, file);
    const title = await page.title();
    check(!title.includes('pwned') && title !== '1', path.basename(file) + ': its title is its own: ' + title);
    const injected = await page.evaluate(() => document.querySelectorAll('[onerror], img[src="x"], #pwned').length);
    check(injected === 0, path.basename(file) + ': no element from the input');
    const hidden = await page.evaluate(() => getComputedStyle(document.body).display === 'none');
    check(!hidden, path.basename(file) + ': no style from the input');
    if (part && /script_comment|a_b_x/.test(file)) { // the program's text is in its panel, as text
      const shown = await page.$eval('#lines', (e) => e.textContent.includes('(</script><script>document.title='));
      check(shown, path.basename(file) + ': the hostile line is shown as text');
    }
    await page.close();
  }
  await browser.close();
}

async function open(colour, files) {
  const browser = await launch();
  for (const file of files) {
    const page = await openPage(browser, file);
    await waitReady(page, file);
    const shown = await page.evaluate(() => document.documentElement.dataset.colourBy);
    check(shown === colour, path.basename(file) + ': opens coloured by ' + shown + ', not ' + colour);
    for (const mode of await page.$$eval('#tools select option', (os) => os.map((o) => o.value))) {
      await page.select('#tools select', mode);
      check((await page.evaluate(() => document.documentElement.dataset.colourBy)) === mode,
            path.basename(file) + ': colours by ' + mode);
    }
    await page.close();
  }
  await browser.close();
}

async function orbit(file, frames) {
  const browser = await launch();
  const start = Date.now();
  const page = await openPage(browser, file);
  await waitReady(page, file);
  const loaded = Date.now() - start;
  await page.evaluate((n) => window.kerf.orbit(n), Math.min(frames, 10)); // warm up
  const r = await page.evaluate((n) => window.kerf.orbit(n), frames);
  console.log(JSON.stringify({ frames: r.frames, ms: Math.round(r.ms), fps: +(r.frames / (r.ms / 1000)).toFixed(2),
                               loadMs: loaded, bytes: fs.statSync(file).size }));
  await browser.close();
}

const [mode, ...args] = process.argv.slice(2);
if (mode === 'report') await report(args[0], args[1], args.slice(2));
else if (mode === 'part') await part(args[0], args[1]);
else if (mode === 'hostile') await hostile(args);
else if (mode === 'open') await open(args[0], args.slice(1));
else if (mode === 'orbit') await orbit(args[0], Number(args[1] || 120));
else fail('usage: node pages.mjs report|part|hostile|orbit ...');
process.exit(failures.length ? 1 : 0);
