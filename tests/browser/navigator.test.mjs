// `brdfnav serve` end to end: the page in Debian's headless Chromium, driven by Playwright, and
// the JSON API's answers to bad requests. On CTest's shared database ($BRDFNAV_TEST_DATABASE: the
// test profile, the smoke profile in the sanitized trees), else a test-profile one it builds,
// starts the server on a free loopback port and keeps a screenshot of every step in the
// artefacts directory.
//
//   node tests/browser/navigator.test.mjs [BRDFNAV_CLI] [ARTEFACTS_DIR]
import { after, before, test } from 'node:test';
import assert from 'node:assert/strict';
import { execFile, spawn } from 'node:child_process';
import fs from 'node:fs';
import net from 'node:net';
import os from 'node:os';
import path from 'node:path';
import { promisify } from 'node:util';
import { fileURLToPath } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
const root = path.resolve(here, '../..');
const cli = path.resolve(process.argv[2] || path.join(root, 'build/bin/brdfnav'));
const artefacts = path.resolve(process.argv[3] || path.join(root, 'build/browser-artifacts'));
const CHROMIUM = '/usr/bin/chromium';
const CHROMIUM_ARGS = ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic',
  '--no-first-run', '--disable-background-networking', '--disable-component-update',
  '--disable-sync'];

let chromium;
let YAML;
try {
  ({ chromium } = await import('playwright-core'));
  YAML = await import('yaml');
} catch (error) {
  throw new Error(`${error.message}\n(run \`npm ci\` in tests/browser; ./run test does)`);
}

const run = promisify(execFile);
const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'brdfnav-browser-'));
let db;
let profile;  // the database's, as its manifest names it
let server;
let url;
let context;
let page;
const pageErrors = [];
let shots = 0;

// The URL the server prints once it listens.
function startServer(db) {
  server = spawn(cli, ['serve', '--db', db, '--port', '0'], { stdio: ['ignore', 'pipe', 'pipe'] });
  return urlOf(server, 'serve.log');
}

// The URL a `brdfnav serve` process prints once it listens; its stderr goes to `logName`.
function urlOf(server, logName) {
  const log = fs.createWriteStream(path.join(artefacts, logName));
  server.stderr.pipe(log);
  return new Promise((resolve, reject) => {
    let out = '';
    const timer = setTimeout(() => reject(new Error(`no URL from serve: ${out}`)), 60000);
    server.stdout.on('data', (chunk) => {
      out += chunk;
      const found = /http:\/\/\S+/.exec(out);
      if (found) { clearTimeout(timer); resolve(found[0]); }
    });
    server.on('exit', (code) => reject(new Error(`serve exited with ${code}: ${out}`)));
  });
}

before(async () => {
  fs.mkdirSync(artefacts, { recursive: true });
  for (const old of fs.readdirSync(artefacts)) fs.rmSync(path.join(artefacts, old), { force: true });
  // CTest's shared test database (tests/CMakeLists.txt), else one of its own.
  db = process.env.BRDFNAV_TEST_DATABASE;
  if (!db) {
    db = path.join(tmp, 'db');
    const { stderr } = await run(cli, ['precompute', '--profile', 'test', '--out', db],
      { maxBuffer: 64 << 20 });
    fs.writeFileSync(path.join(artefacts, 'precompute.log'), stderr);
  }
  profile = YAML.parse(fs.readFileSync(path.join(db, 'manifest.yaml'), 'utf8')).profile;
  url = await startServer(db);
  context = await chromium.launchPersistentContext(path.join(tmp, 'chromium-profile'), {
    executablePath: CHROMIUM, headless: true, args: CHROMIUM_ARGS,
    viewport: { width: 1400, height: 950 }, acceptDownloads: true,
  });
  page = context.pages()[0] || await context.newPage();
  page.on('pageerror', (error) => pageErrors.push(error.message));
}, { timeout: 900000 });

after(async () => {
  await context?.close();
  if (server && server.exitCode === null) {
    const exited = new Promise((resolve) => server.on('exit', resolve));
    server.kill('SIGTERM');
    assert.equal(await exited, 0, 'serve stops cleanly on SIGTERM');
  }
  fs.rmSync(tmp, { recursive: true, force: true });
});

// ---- helpers --------------------------------------------------------------------------------

async function settled() {
  await page.waitForFunction(() => document.body.dataset.ready === 'true', null,
    { timeout: 60000 });
}

async function shot(name) {
  shots += 1;
  const file = path.join(artefacts, `${String(shots).padStart(2, '0')}-${name}.png`);
  await page.screenshot({ path: file, fullPage: true });
}

const centre = async () => JSON.parse(await page.locator('#centre').getAttribute('data-material'));

async function variations() {
  return page.locator('.variation').evaluateAll((buttons) => buttons.map((b) => ({
    tab: b.dataset.tab,
    label: b.dataset.label,
    distance: Number(b.dataset.distance),
    flags: b.dataset.flags ? b.dataset.flags.split(' ') : [],
    material: JSON.parse(b.dataset.material),
  })));
}

async function selectTab(tab) {
  await page.click(`#tabs [data-tab=${tab}]`);
  await settled();
  assert.equal(await page.getAttribute(`#tabs [data-tab=${tab}]`, 'aria-selected'), 'true');
}

async function setSlider(position) {
  await page.locator('#radius').fill(String(position));
  await settled();
  return Number(await page.locator('#radius-value').textContent());
}

async function api(pathname, body, type = 'application/json') {
  const init = body === undefined ? {} : { method: 'POST', body, headers: { 'Content-Type': type } };
  // undici's 'fetch failed' says nothing more; its cause names the socket error.
  const response = await fetch(new URL(pathname, url), init).catch((error) => {
    throw new Error(`${pathname}: ${error.message}: ${error.cause?.code ?? error.cause}`);
  });
  const text = await response.text();
  return { status: response.status, type: response.headers.get('content-type'), text,
    headers: response.headers };
}

const info = async () => JSON.parse((await api('/api/info')).text);

// A POST announcing `length` bytes of body and sending none: what the server answers from the
// headers alone (fetch would be reset sending a body the server refuses unread).
function announce(pathname, length) {
  const { hostname, port } = new URL(url);
  return new Promise((resolve, reject) => {
    const socket = net.connect(Number(port), hostname);
    let reply = '';
    socket.on('connect', () => socket.write(`POST ${pathname} HTTP/1.1\r\nHost: ${hostname}\r\n` +
      `Content-Type: application/json\r\nContent-Length: ${length}\r\n\r\n`));
    socket.on('data', (chunk) => { reply += chunk; });
    socket.on('end', () => resolve(reply));
    socket.on('error', reject);
    socket.setTimeout(10000, () => socket.destroy(new Error(`no answer to ${length} bytes`)));
  });
}

// ---- the page -------------------------------------------------------------------------------

let start;
let chosen;

test('the page opens on the start gallery around the start material', async () => {
  await page.goto(url);
  await settled();
  const { start: expected, models } = await info();
  start = await centre();
  assert.deepEqual(start, expected);
  assert.equal(await page.getAttribute('#tabs [data-tab=gallery]', 'aria-selected'), 'true');
  const offered = await variations();
  assert.equal(offered.length, 8);
  for (const v of offered) assert.equal(v.tab, 'gallery');
  const readout = await page.locator('#readout tbody tr').evaluateAll(
    (rows) => rows.map((r) => r.dataset.key));
  const params = models.find((m) => m.name === start.model).params.map((p) => p.name);
  assert.deepEqual(readout, [...params, 'rho_d', 'rho_s', 'colorspace']);
  assert.match(await page.textContent('#provenance'), new RegExp(`profile ${profile}`));
  assert.equal(await page.isDisabled('#back'), true);
  await shot('start-gallery');
});

test('clicking a variation makes it the current material', async () => {
  const offered = await variations();
  const index = Math.max(0, offered.findIndex((v) => v.material.model !== start.model));
  const pick = offered[index];
  await page.locator('.variation').nth(index).click();
  await settled();
  chosen = await centre();
  assert.deepEqual(chosen, pick.material);
  const { models } = await info();
  assert.match(await page.textContent('#readout h2'),
    new RegExp(models.find((m) => m.name === chosen.model).title.replace(/[()]/g, '\\$&')));
  assert.equal(await page.isDisabled('#back'), false);
  assert.equal(await page.isDisabled('#forward'), true);
  await shot('clicked-variation');
});

test('a larger radius moves the variations away', async () => {
  await selectTab('diffuse');
  const small = await setSlider(30);
  const near = await variations();
  await shot('diffuse-small-radius');
  const large = await setSlider(70);
  assert.ok(large > small);
  const far = await variations();
  await shot('diffuse-large-radius');
  assert.equal(far.length, near.length);
  for (const v of far) {
    const before_ = near.find((n) => n.label === v.label);
    assert.ok(v.distance >= before_.distance - 1e-9, `${v.label}: ${before_.distance} -> ${v.distance}`);
    if (!before_.flags.includes('clamped')) assert.ok(v.distance > before_.distance, v.label);
    // Exact steps (on by default): placed by rendering, within their 2% tolerance.
    if (!v.flags.includes('clamped')) {
      assert.ok(Math.abs(v.distance / large - 1) <= 0.02, `${v.label}: ${v.distance} for ${large}`);
    }
  }
  // Without exact steps the database alone places them: at the embedded radius, to 1e-3.
  assert.equal(await page.isChecked('#exact'), true);
  await page.uncheck('#exact');
  await settled();
  const embedded = await variations();
  assert.equal(embedded.length, far.length);
  for (const v of embedded) {
    if (!v.flags.includes('clamped')) assert.ok(Math.abs(v.distance - large) < 1e-3 * large + 1e-4);
  }
  // The same offers where the database's placement was already within the tolerance, but each
  // exact distance is a render's, not the radius.
  assert.ok(embedded.some((v) => far.find((f) => f.label === v.label).distance !== v.distance));
  await page.check('#exact');
  await settled();
  await selectTab('lobe');
  const lobeFar = await variations();
  await setSlider(30);
  const lobeNear = await variations();
  for (const v of lobeFar) {
    const before_ = lobeNear.find((n) => n.label === v.label);
    assert.ok(v.distance >= before_.distance - 1e-6, `${v.label}: ${before_.distance} -> ${v.distance}`);
  }
  // The + key moves the slider up by one step of five positions.
  const position = Number(await page.inputValue('#radius'));
  await page.keyboard.press('+');
  await settled();
  assert.equal(Number(await page.inputValue('#radius')), position + 5);
  await page.keyboard.press('-');
  await settled();
  assert.equal(Number(await page.inputValue('#radius')), position);
});

test('every tab offers its own variations', async () => {
  const { models } = await info();
  const current = await centre();
  const params = models.find((m) => m.name === current.model).params.length;
  const expected = {
    diffuse: (n) => n === 10,
    specular: (n) => n === 10,
    lobe: (n) => n === 2 * params + (current.model === 'ward' ? 2 : 0),
    models: (n) => n <= 8,
    gallery: (n) => n === 8,
  };
  await page.focus('#tabs [data-tab=lobe]');  // a tab had the focus: it follows the shortcuts
  for (const [key, tab] of ['diffuse', 'specular', 'lobe', 'models', 'gallery'].entries()) {
    await page.keyboard.press(String(key + 1));  // the tabs' shortcuts
    await settled();
    assert.equal(await page.getAttribute(`#tabs [data-tab=${tab}]`, 'aria-selected'), 'true');
    assert.equal(await page.evaluate(() => document.activeElement.dataset.tab), tab);
    const offered = await variations();
    assert.ok(expected[tab](offered.length), `${tab}: ${offered.length} variations`);
    for (const v of offered) assert.equal(v.tab, tab);
    assert.equal(await page.isVisible('#empty'), offered.length === 0);
    await shot(`tab-${tab}`);
  }
  await selectTab('lobe');
});

test('the ring fits a 1024 px window: opposites face each other, nothing overlaps or is cut', async () => {
  await page.setViewportSize({ width: 1024, height: 768 });
  try {
    for (const tab of ['diffuse', 'lobe', 'models', 'gallery']) {
      await selectTab(tab);
      const boxes = await page.locator('.variation').evaluateAll((buttons) => buttons.map((b) => {
        const r = b.getBoundingClientRect();
        const img = b.querySelector('img').getBoundingClientRect();
        return { left: r.left, right: r.right, top: r.top, bottom: r.bottom, image: img.width,
          x: (img.left + img.right) / 2, y: (img.top + img.bottom) / 2,
          words: b.querySelector('.caption b').textContent, title: b.title,
          // Caption lines whose text does not fit their box (cut, or under an ellipsis).
          cut: [...b.querySelectorAll('.caption > *')].filter((e) =>
            e.scrollWidth > e.clientWidth + 1 || e.scrollHeight > e.clientHeight + 1)
            .map((e) => e.textContent) };
      }));
      const c = await page.locator('#centre img').evaluate((img) => {
        const r = img.getBoundingClientRect();
        return { left: r.left, right: r.right, top: r.top, bottom: r.bottom, width: r.width };
      });
      assert.ok(c.width >= 256, `centre ${c.width} px`);
      const mid = [(c.left + c.right) / 2, (c.top + c.bottom) / 2];
      for (const [i, b] of boxes.entries()) {
        assert.ok(b.image >= 160, `${tab} ${b.words}: ${b.image} px`);
        assert.ok(b.left >= 0 && b.right <= 1024, `${tab} ${b.words}: ${b.left}..${b.right}`);
        assert.deepEqual(b.cut, [], `${tab} ${b.words}: caption cut`);
        assert.doesNotMatch(b.words, /^(L[+-]|ab\+\d+|\w+[+-])$/, 'words, not labels');
        assert.ok(b.title.length > b.words.length, `${tab} ${b.words}: tooltip '${b.title}'`);
        // Neither on the centre's image nor on another variation.
        const apart = (a, o) => a.right <= o.left || o.right <= a.left || a.bottom <= o.top ||
          o.bottom <= a.top;
        assert.ok(apart(b, c), `${tab} ${b.words} covers the centre`);
        for (const o of boxes.slice(0, i)) assert.ok(apart(b, o), `${tab} ${b.words} / ${o.words}`);
        // The images of offers i and i + n/2 mirror each other through the centre's image (the
        // service's ring order; the models and the gallery have no opposites).
        if (tab !== 'gallery' && tab !== 'models' && i < boxes.length / 2) {
          const o = boxes[i + boxes.length / 2];
          assert.ok(Math.abs((b.x + o.x) / 2 - mid[0]) < 2, `${tab} ${b.words} / ${o.words}`);
          assert.ok(Math.abs((b.y + o.y) / 2 - mid[1]) < 2, `${tab} ${b.words} / ${o.words}`);
        }
      }
    }
    await shot('ring-1024');
  } finally {
    await page.setViewportSize({ width: 1400, height: 950 });
  }
  await selectTab('lobe');
});

test('Export YAML downloads the export of the current material', async () => {
  const current = await centre();
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#export')]);
  const file = path.join(artefacts, 'export.yaml');
  await download.saveAs(file);
  const doc = YAML.parse(fs.readFileSync(file, 'utf8'));
  assert.equal(doc.brdfnav_material, 1);
  for (const key of ['model', 'params', 'rho_d', 'rho_s', 'colorspace'])
    assert.deepEqual(doc[key], current[key], key);
  assert.equal(doc.provenance.profile, profile);
  assert.match(doc.provenance.manifest_sha1, /^[0-9A-F]{40}$/);
  const others = (await info()).models.map((m) => m.name).filter((m) => m !== current.model);
  assert.deepEqual(Object.keys(doc.equivalents), others);
  for (const [model, e] of Object.entries(doc.equivalents)) {
    assert.equal(e.material.model, model);
    assert.ok(e.residual >= 0);
  }
  // The export is a material file for every other brdfnav command.
  await run(cli, ['eval', '--material', file, '--wi', '0,0.5,1', '--wo', '0.3,0,1']);
  // The page confirms it.
  assert.match(await page.textContent('#notice'), /^Exported brdfnav-\w+\.yaml/);
  await shot('exported');
});

test('Export in the renderers\' formats downloads the material\'s ggx form', async () => {
  const current = await centre();
  const downloaded = async (format, name) => {
    await page.selectOption('#export-format', format);
    const [download] = await Promise.all([page.waitForEvent('download'), page.click('#export')]);
    assert.equal(download.suggestedFilename(), `brdfnav-${current.model}.${name.split('.')[1]}`);
    const file = path.join(artefacts, name);
    await download.saveAs(file);
    return fs.readFileSync(file, 'utf8');
  };
  const cycles = JSON.parse(await downloaded('cycles', 'export.json'));
  assert.equal(cycles.brdfnav_cycles, 1);
  assert.equal(cycles.material.model, 'ggx');
  assert.deepEqual(cycles.chosen, current);
  assert.ok(cycles.residual >= 0);
  const mtlx = await downloaded('materialx', 'export.mtlx');
  assert.match(mtlx, /^<\?xml version="1.0"\?>\n<materialx version="1.38"/);
  assert.match(mtlx, /<generalized_schlick_bsdf name="brdfnav_specular" type="BSDF">/);
  assert.ok(mtlx.includes('in brdfnav\'s image metric'), 'the comment states the distances');
  await page.selectOption('#export-format', 'yaml');
  await shot('exported-for-renderers');
});

test('back and forward walk the history', async () => {
  await page.click('#back');
  await settled();
  assert.deepEqual(await centre(), start);
  assert.equal(await page.isDisabled('#forward'), false);
  await shot('back');
  for (const [key, expected] of [[']', chosen], ['Alt+ArrowLeft', start],
    ['Alt+ArrowRight', chosen], ['[', start]]) {
    await page.keyboard.press(key);
    await settled();
    assert.deepEqual(await centre(), expected, key);
  }
});

test('loading a YAML file starts from it, and a bad one is reported', async () => {
  const material = {
    model: 'he', params: { sigma: 0.3, tau: 6, eta: 2 },
    rho_d: [0.1, 0.2, 0.3], rho_s: [0.7, 0.7, 0.7], colorspace: 'lin_rec709',
  };
  const file = path.join(tmp, 'chosen.yaml');
  fs.writeFileSync(file, YAML.stringify({ brdfnav_material: 1, ...material }));
  await page.setInputFiles('#load-file', file);
  await settled();
  assert.deepEqual(await centre(), material);
  assert.equal(await page.isDisabled('#forward'), true, 'a load starts a new branch');
  assert.match(await page.textContent('#readout tbody tr[data-key=sigma]'), /0\.3/);
  await shot('loaded-yaml');
  // The same file again is the current material again: no second history entry.
  await page.setInputFiles('#load-file', file);
  await settled();
  await page.click('#back');
  await settled();
  assert.notDeepEqual(await centre(), material, 'Back leaves the loaded material');
  await page.click('#forward');
  await settled();

  const bad = path.join(tmp, 'bad.yaml');
  fs.writeFileSync(bad, YAML.stringify({ brdfnav_material: 1, ...material,
    params: { sigma: -1, tau: 6, eta: 2 } }));
  await page.setInputFiles('#load-file', bad);
  await page.waitForSelector('#error:not([hidden])');
  assert.match(await page.textContent('#error'), /bad\.yaml:\d+: params\.sigma/);
  assert.deepEqual(await centre(), material, 'a bad file changes nothing');
  await shot('bad-yaml');
  await page.click('#error');
});

test('a progress indicator shows while thumbnails take longer than 100 ms', async () => {
  await page.route('**/api/thumbnail?*', async (route) => {
    await new Promise((resolve) => setTimeout(resolve, 600));
    await route.continue();
  });
  await page.keyboard.press('2');
  await page.waitForSelector('#progress:not([hidden])', { timeout: 2000 });
  assert.match(await page.textContent('#progress'), /Rendering thumbnails \d+ \/ \d+|Finding|Rendering to place/);
  await shot('progress');
  await settled();
  assert.equal(await page.isVisible('#progress'), false);
  // The page asks for the centre's sharp render once ready: a handler may still be holding it.
  // Waiting for it lets it continue the request itself (a plain unroute continued it first, and
  // the handler's own continue() then failed: "Route is already handled!").
  await page.unrouteAll({ behavior: 'wait' });
});

test('the display and view selectors re-render through OCIO', async () => {
  const before_ = await page.getAttribute('#centre img', 'src');
  await page.selectOption('#view', 'ACES 1.0 SDR-video');
  await settled();
  assert.notEqual(await page.getAttribute('#centre img', 'src'), before_);
  await shot('aces-view');
  await page.selectOption('#display', 'Rec.1886');
  await settled();
  assert.equal(await page.inputValue('#view'), 'ACES 1.0 SDR-video', 'the view is kept');
  await page.selectOption('#display', 'sRGB');
  await page.selectOption('#view', 'Standard');
  await settled();
  assert.deepEqual(pageErrors, []);
});

test('a failed query leaves no variation of the previous state to click', async () => {
  const previous = await centre();
  await selectTab('lobe');
  assert.ok((await variations()).length > 0);
  const file = path.join(tmp, 'acescg.yaml');
  fs.writeFileSync(file, YAML.stringify({ brdfnav_material: 1, ...previous, colorspace: 'acescg' }));
  await page.setInputFiles('#load-file', file);  // every tab refuses a space but lin_rec709
  await settled();
  assert.match(await page.textContent('#error'), /colorspace 'acescg'/);
  assert.deepEqual(await variations(), [], 'no variation of the previous material is left');
  assert.equal(await page.isVisible('#empty'), false);
  await shot('failed-query');
  await page.keyboard.press('[');
  await settled();
  assert.deepEqual(await centre(), previous);
  assert.ok((await variations()).length > 0);
  assert.equal(await page.isVisible('#error'), false);
});

test('quick clicks add one history entry, from the ring on screen', async () => {
  const before_ = await centre();
  const moves = (await variations()).map((v, index) => ({ ...v, index }))
    .filter((v) => JSON.stringify(v.material) !== JSON.stringify(before_));
  assert.ok(moves.length >= 2);
  // While the new variations load, the old ones cannot be clicked.
  await page.route('**/api/neighbors?*', async (route) => {
    await new Promise((resolve) => setTimeout(resolve, 300));
    await route.continue();
  });
  await page.locator('.variation').nth(moves[0].index).dblclick();
  assert.equal(await page.locator('.variation').first().isDisabled(), true);
  await settled();
  await page.unrouteAll({ behavior: 'wait' });
  assert.deepEqual(await centre(), moves[0].material);
  assert.equal(await page.locator('.variation').first().isDisabled(), false);
  await page.click('#back');
  await settled();
  assert.deepEqual(await centre(), before_, 'a double click is one history entry');
  // A second click before the new ring arrives does not navigate from the old one.
  await page.evaluate(([a, b]) => {
    const buttons = document.querySelectorAll('.variation');
    buttons[a].click();
    buttons[b].click();
  }, [moves[0].index, moves[1].index]);
  await settled();
  assert.deepEqual(await centre(), moves[0].material);
  await page.click('#back');
  await settled();
  assert.deepEqual(await centre(), before_);
});

test('every query and thumbnail names its ring, so that the server drops the rings left', async () => {
  const rings = [];
  const record = (request) => {
    if (!/\/api\/(neighbors|thumbnail)(\?|$)/.test(request.url())) return;
    rings.push({ path: new URL(request.url()).pathname, ...JSON.parse(request.postData()).ring });
  };
  page.on('request', record);
  try {
    await selectTab('diffuse');
    await selectTab('lobe');
  } finally {
    page.off('request', record);
  }
  assert.ok(rings.some((r) => r.path === '/api/neighbors'));
  assert.ok(rings.some((r) => r.path === '/api/thumbnail'));
  assert.equal(new Set(rings.map((r) => r.client)).size, 1, 'one client id per page');
  assert.match(rings[0].client, /^[\w-]{1,64}$/);
  // The lobe tab's ring comes after the diffuse tab's.
  // (With exact steps a ring asks twice: the embedding's ring first, shown in previews.)
  const ids = [...new Set(rings.filter((r) => r.path === '/api/neighbors').map((r) => r.id))];
  assert.ok(ids.length === 2 && ids[1] > ids[0], `rings ${ids}`);
});

test('a variation chosen with the keyboard leaves the focus on the new ring', async () => {
  const before_ = await centre();
  const move = (await variations()).findIndex(
    (v) => JSON.stringify(v.material) !== JSON.stringify(before_));
  await page.locator('.variation').nth(move).focus();
  await page.keyboard.press('Enter');
  await settled();
  assert.notDeepEqual(await centre(), before_);
  assert.equal(await page.evaluate(() => document.activeElement === document.querySelector(
    '#ring .variation')), true, 'the first new variation has the focus');
  await page.keyboard.press('[');
  await settled();
});

test('the radius slider and the centre image describe their values', async () => {
  const radius = await page.textContent('#radius-value');
  assert.equal(await page.getAttribute('#radius', 'aria-valuetext'), `radius ${radius}`);
  const current = await centre();
  const { title } = (await info()).models.find((m) => m.name === current.model);
  const alt = await page.getAttribute('#centre img', 'alt');
  assert.ok(alt.includes(title), alt);
  for (const name of Object.keys(current.params)) {
    const value = await page.textContent(`#readout tr[data-key=${name}] td:nth-child(2)`);
    assert.ok(alt.includes(`${name} ${value}`), `${name} ${value} in ${alt}`);
  }
});

test('at a device pixel ratio of 2 the centre is sharp and every silhouette antialiased', async () => {
  const sharp = await chromium.launch({ executablePath: CHROMIUM, headless: true,
    args: CHROMIUM_ARGS });
  try {
    const retina = await sharp.newPage({ viewport: { width: 1400, height: 950 },
      deviceScaleFactor: 2 });
    await retina.goto(url);
    await retina.waitForFunction(() => document.body.dataset.ready === 'true', null,
      { timeout: 60000 });
    // After the ring, the centre's render at 512 px: one image pixel per device pixel.
    await retina.waitForSelector('#centre img[data-size="512"]', { timeout: 120000 });
    const images = await retina.evaluate(() => {
      // Alpha of an image's pixels: how many are neither 0 nor 1 (the edge's partial coverage),
      // and the alpha of the corners (the margin around the sphere).
      const alpha = (img) => {
        const canvas = document.createElement('canvas');
        canvas.width = img.naturalWidth;
        canvas.height = img.naturalHeight;
        const context = canvas.getContext('2d');
        context.drawImage(img, 0, 0);
        const { data } = context.getImageData(0, 0, canvas.width, canvas.height);
        let partial = 0;
        for (let i = 3; i < data.length; i += 4) partial += data[i] > 0 && data[i] < 255;
        const w = canvas.width;
        return { width: w, partial, corner: data[3] + data[4 * (w - 1) + 3] };
      };
      const centre = document.querySelector('#centre img');
      const box = centre.getBoundingClientRect();
      const style = getComputedStyle(centre);
      return {
        centre: alpha(centre),
        box: box.width,
        content: box.width - parseFloat(style.paddingLeft) - parseFloat(style.paddingRight),
        ring: [...document.querySelectorAll('.variation img')].map(alpha),
      };
    });
    assert.equal(images.centre.width, 512);
    assert.ok(images.box >= 256, `centre box ${images.box} px`);
    // The sphere's 512 pixels across fill the content box at 2 device pixels per CSS pixel or
    // more densely: nothing is magnified.
    assert.ok(2 * images.content <= 512, `centre content ${images.content} px`);
    // A circle of 512 px crosses about 4 x 512 / sqrt(2) ~ 1450 pixels partly.
    assert.ok(images.centre.partial > 1000, `centre: ${images.centre.partial} partial pixels`);
    assert.equal(images.centre.corner, 0);
    assert.ok(images.ring.length > 0);
    for (const r of images.ring) {
      assert.ok(r.partial > 0, `variation of ${r.width} px: no partial pixel`);
      assert.equal(r.corner, 0);
    }
    await retina.screenshot({ path: path.join(artefacts, 'dpr2-centre.png') });
  } finally {
    await sharp.close();
  }
});

// ---- the API's answers to bad requests ---------------------------------------------------------

test('bad API requests get 400 naming the field, and the server keeps serving', async () => {
  const m = (await info()).start;
  const body = (fields) => JSON.stringify(fields);
  const cases = [
    ['/api/neighbors', body({ material: { ...m, model: 'nope' }, radius: 0.02, tab: 'lobe' }),
      /^material:\d+: model: unknown model 'nope'/],
    ['/api/neighbors', body({ material: m, radius: 'NaN', tab: 'lobe' }), /^radius: /],
    ['/api/neighbors', `{"material": ${JSON.stringify(m)}, "radius": NaN, "tab": "lobe"}`,
      /^body: malformed JSON/],
    ['/api/neighbors', `{"material": ${JSON.stringify(m)}, "radius": 1e999, "tab": "lobe"}`,
      /^body: malformed JSON/],
    ['/api/neighbors', body({ material: m, radius: -0.02, tab: 'lobe' }), /^radius: must be/],
    ['/api/neighbors', body({ material: m, radius: 0, tab: 'lobe' }), /^radius: must be/],
    ['/api/neighbors', body({ material: m, tab: 'lobe' }), /^radius: missing/],
    ['/api/neighbors', body({ material: m, radius: 0.02, tab: 'nope' }), /^tab: unknown tab/],
    ['/api/neighbors', body({ material: m, radius: 0.02, tab: 7 }), /^tab: unknown tab/],
    ['/api/neighbors', body({ material: m, radius: 0.02, tab: 'models', k: 0 }), /^k: /],
    ['/api/neighbors', body({ material: m, radius: 0.02, tab: 'lobe', extra: 1 }),
      /^extra: unknown field/],
    ['/api/neighbors', body({ material: { ...m, rho_d: undefined }, radius: 0.02, tab: 'lobe' }),
      /^material:\d+: rho_d: missing/],
    ['/api/neighbors', body({ material: { ...m, rho_s: [1, 2] }, radius: 0.02, tab: 'lobe' }),
      /^material:\d+: rho_s: expected 3 components/],
    ['/api/neighbors', body({ material: { ...m, params: { n: -5 } }, radius: 0.02, tab: 'lobe' }),
      /^material:\d+: params\.n: /],
    ['/api/neighbors', body({ material: { ...m, params: { n: '5' } }, radius: 0.02, tab: 'lobe' }),
      /^material:\d+: params\.n: expected a number/],
    ['/api/neighbors', body({ material: 'blinn_phong', radius: 0.02, tab: 'lobe' }),
      /^material: expected an object/],
    ['/api/neighbors', body({ material: { params: { a: [[[[[1]]]]] } }, radius: 1, tab: 'lobe' }),
      /^material: nested too deeply/],
    // Valid JSON, but a key over YAML's 1024-character limit for implicit keys: quotes and
    // escapes count (the 1024-byte key was a fuzzer's, tests/corpus/serve_request/crashes/).
    ['/api/neighbors', body({ material: { ...m, [']'.repeat(1100)]: 1 }, radius: 0.02, tab: 'lobe' }),
      /^material: unknown key of 1100 bytes "\]\]\]/],
    ['/api/neighbors', body({ material: { ...m, [']'.repeat(1023)]: 1 }, radius: 0.02, tab: 'lobe' }),
      /^material: unknown key of 1023 bytes/],
    ['/api/neighbors', body({ material: { ...m, ['a'.repeat(1000) + '\u0001'.repeat(4)]: 1 },
      radius: 0.02, tab: 'lobe' }), /^material: unknown key of 1004 bytes/],
    ['/api/neighbors', body({ material: { ...m, [']'.repeat(1022)]: 1 }, radius: 0.02, tab: 'lobe' }),
      /^material:\d+: \]{1022}: unknown key/],
    ['/api/neighbors', '{"material": ', /^body: malformed JSON/],
    ['/api/neighbors', '[1, 2]', /^body: expected a JSON object/],
    ['/api/neighbors', ' '.repeat(70 * 1024), /^body: larger than 65536 bytes/],
    ['/api/thumbnail', body({ material: m, display: 'nope' }), /^display: /],
    ['/api/thumbnail', body({ material: m, view: 'nope' }), /^view: /],
    ['/api/thumbnail', body({ display: 'sRGB' }), /^material: missing/],
    ['/api/thumbnail', body({ material: m, size: 100 }), /^size: expected one of \d+, 256, 512/],
    ['/api/thumbnail', body({ material: m, size: 256, preview: true }), /^size: a preview/],
    ['/api/export', body({ material: { ...m, colorspace: '' } }), /^material:\d+: colorspace: /],
    ['/api/export', body({ material: { ...m, colorspace: 'lin\ufdd0' } }),
      /^material:\d+: colorspace: byte 3 is not allowed/],
    ['/api/import?name=x.yaml', 'model: he\n', /^x\.yaml:1: brdfnav_material: missing/],
    ['/api/import', 'brdfnav_material: 1\nmodel: [', /^upload:\d+: syntax error/],
    ['/api/import', Buffer.from('brdfnav_material: 1\nmodel: \xff\xfe\n', 'latin1'),
      /^upload:2: model: unknown model '\ufffd\ufffd'/],
  ];
  for (const [pathname, payload, error] of cases) {
    const answer = await api(pathname, payload);
    assert.equal(answer.status, 400, `${pathname} ${String(payload).slice(0, 80)}: ${answer.text}`);
    assert.match(answer.type, /^application\/json/);
    assert.match(JSON.parse(answer.text).error, error, String(payload).slice(0, 80));
  }
  // Over 1 MiB httplib refuses the body from its Content-Length, in the API's words.
  const refused = await announce('/api/neighbors', 2 * 1024 * 1024);
  assert.match(refused, /^HTTP\/1\.1 400 /);
  assert.match(refused, /"error":\s*"body: larger than 65536 bytes"/);
  const missing = await api('/api/nope');
  assert.equal(missing.status, 404);
  assert.match(JSON.parse(missing.text).error, /not found/);
  // A method the path does not take: 405, naming those it does.
  for (const [pathname, payload, allow] of [['/api/neighbors', undefined, 'POST'],
    ['/api/info', '{}', 'GET, HEAD']]) {
    const refused = await api(pathname, payload);
    assert.equal(refused.status, 405, pathname);
    assert.equal(refused.headers.get('allow'), allow);
    assert.match(JSON.parse(refused.text).error, /: method not allowed/);
  }
  const deleted = await fetch(new URL('/api/info', url), { method: 'DELETE' });
  assert.equal(deleted.status, 405);
  assert.equal(deleted.headers.get('allow'), 'GET, HEAD');
  // docs/SERVE.md quotes the Content-Security-Policy the server sends.
  const csp = (await api('/')).headers.get('content-security-policy');
  const doc = fs.readFileSync(path.join(root, 'docs/SERVE.md'), 'utf8').replace(/\s+/g, ' ');
  assert.ok(doc.includes(`\`Content-Security-Policy: ${csp}\``), csp);

  // All at once, good and bad: every request is answered, and the good ones correctly.
  const good = body({ material: m, radius: 0.02, tab: 'diffuse' });
  const answers = await Promise.all(cases.flatMap(([p, payload]) => [api(p, payload),
    api('/api/neighbors', good)]));
  answers.forEach((a, i) => assert.equal(a.status, i % 2 ? 200 : 400));
  assert.equal(JSON.parse(answers[1].text).neighbors.length, 10);
  assert.equal((await api('/api/info')).status, 200);
  const png = await fetch(new URL('/api/thumbnail', url), { method: 'POST', body: body({ material: m }) });
  assert.equal(png.headers.get('content-type'), 'image/png');
  assert.equal(Buffer.from(await png.arrayBuffer()).subarray(1, 4).toString(), 'PNG');
  // The server's log names each failure in words, whatever encoding the client accepted (fetch
  // accepts gzip: the log once showed the compressed bytes).
  const logged = await fetch(new URL('/api/neighbors', url), { method: 'POST',
    headers: { 'Accept-Encoding': 'gzip, br' }, body: body({ material: m, radius: 0.02, tab: 'nope' }) });
  assert.equal(logged.status, 400);
  const serveLog = fs.readFileSync(path.join(artefacts, 'serve.log'), 'utf8');
  assert.match(serveLog, /brdfnav: serve: POST \/api\/neighbors -> 400 \{"error":\s*"tab: unknown tab/);
});

// Raw sockets on the server's port, each with promises of its connection and first answer;
// `request` is sent on each once it connects.
function openSockets(count, request) {
  const { hostname, port } = new URL(url);
  return Array.from({ length: count }, () => {
    const socket = net.connect(Number(port), hostname);
    const state = { socket, closed: false };
    state.connected = new Promise((resolve) => socket.on('connect', resolve));
    state.answered = new Promise((resolve) => socket.once('data', resolve));
    socket.on('close', () => { state.closed = true; });
    socket.on('error', () => {});  // destroyed mid-handshake by the test
    if (request) socket.on('connect', () => socket.write(request));
    return state;
  });
}

test('a burst of connections and idle keep-alive ones hold no request back', async () => {
  // While the server cannot accept (stopped), the kernel queues the connections up to the listen
  // backlog; httplib's compiled-in 5 dropped the rest, and clients gave up after 10 s.
  server.kill('SIGSTOP');
  try {
    const burst = openSockets(64);
    const connected = await Promise.race([Promise.all(burst.map((s) => s.connected)),
      new Promise((resolve) => setTimeout(() => resolve(false), 3000))]);
    burst.forEach((s) => s.socket.destroy());
    assert.ok(connected, 'all 64 connections completed while the server was stopped');
  } finally {
    server.kill('SIGCONT');
  }
  // Each answered keep-alive connection holds a server thread until its next request or the 5 s
  // keep-alive timeout; with httplib's 8 threads, 16 of them made the next request wait for the
  // first timeouts. It must be answered while all 16 are still open.
  const { host } = new URL(url);
  const idle = openSockets(16, `GET /api/info HTTP/1.1\r\nHost: ${host}\r\n\r\n`);
  try {
    await Promise.all(idle.map((s) => s.answered));
    assert.equal((await api('/api/info')).status, 200);
    assert.equal(idle.filter((s) => s.closed).length, 0, 'no idle connection timed out first');
  } finally {
    idle.forEach((s) => s.socket.destroy());
  }
});

test('serve refuses a port in use, a missing database and one lighting twice, naming them', async () => {
  const { port } = new URL(url);
  // Exit status 4: a file or socket that cannot be used; 5: a database that is not there; 2: an
  // argument that cannot be (the same map, profile and resolution twice).
  const twice = new RegExp(`--db: ${db}: the same map, profile and resolution as ${db}`);
  for (const [args, error, status] of [[['--db', db, '--port', port], /--port: /, 4],
    [['--db', path.join(tmp, 'none'), '--port', '0'], /--db: /, 5],
    [['--db', db, '--db', db, '--port', '0'], twice, 2]]) {
    // A serve that starts after all is killed after 20 s, and fails the check on its exit code.
    await assert.rejects(run(cli, ['serve', ...args], { timeout: 20000 }),
      (e) => e.code === status && error.test(e.stderr));
  }
});

test('with a second lighting the page names each map, switches, and carries the material', async () => {
  const courtyard = path.join(tmp, 'db-courtyard');
  await run(cli, ['precompute', '--profile', 'smoke', '--out', courtyard, '--env',
    '/usr/share/blender/datafiles/studiolights/world/courtyard.exr'], { maxBuffer: 64 << 20 });
  const first = path.basename(YAML.parse(
    fs.readFileSync(path.join(db, 'manifest.yaml'), 'utf8')).environment.path);
  const both = spawn(cli, ['serve', '--db', db, '--db', courtyard, '--port', '0'],
    { stdio: ['ignore', 'pipe', 'pipe'] });
  const lit = await context.newPage();
  try {
    await lit.goto(await urlOf(both, 'serve-lightings.log'));
    const ready = () => lit.waitForFunction(() => document.body.dataset.ready === 'true', null,
      { timeout: 60000 });
    await ready();
    const litBy = () => lit.textContent('#lit-by strong');
    assert.equal(await litBy(), first);
    const buttons = lit.locator('#lightings button');
    assert.equal(await buttons.count(), 2);
    assert.equal(await buttons.nth(0).getAttribute('aria-pressed'), 'true');
    // The map's picture, as the server drew it.
    await lit.waitForFunction(() => {
      const img = document.querySelector('#lit-by img');
      return img.complete && img.naturalWidth > 0;
    }, null, { timeout: 30000 });
    assert.equal(await lit.evaluate(() => document.querySelector('#lit-by img').naturalWidth), 256);
    const before = JSON.parse(await lit.locator('#centre').getAttribute('data-material'));
    await lit.click('#lightings button[data-lighting=courtyard]');
    await ready();
    assert.equal(await litBy(), 'courtyard.exr');
    assert.equal(await buttons.nth(1).getAttribute('aria-pressed'), 'true');
    // Its model is in both databases: the same material, now lit by the other map.
    assert.deepEqual(JSON.parse(await lit.locator('#centre').getAttribute('data-material')), before);
    assert.match(await lit.textContent('#provenance'), /courtyard\.exr/);
    await lit.screenshot({ path: path.join(artefacts, 'lightings.png'), fullPage: true });
    // Back returns to the first lighting with the material seen under it.
    await lit.click('#back');
    await ready();
    assert.equal(await litBy(), first);
    assert.equal(await lit.textContent('#error'), '');
  } finally {
    await lit.close();
    const exited = new Promise((resolve) => both.on('exit', resolve));
    both.kill('SIGTERM');
    assert.equal(await exited, 0, 'serve stops cleanly on SIGTERM');
  }
});
