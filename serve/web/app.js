// The navigator page: state (history, tab, radius, display), the API calls of `brdfnav serve`
// (docs/SERVE.md) and the drawing of the stage. No framework, no build step.

const TABS = [
  ['diffuse', 'Diffuse colour'],
  ['specular', 'Specular colour'],
  ['lobe', 'Lobe shape'],
  ['models', 'Other models'],
  ['gallery', 'Start gallery'],
];
const SLIDER_STEPS = 100;  // the radius slider's positions, spaced evenly in log(radius)
const KEY_STEP = 5;        // slider positions per + / - key press
const PROGRESS_DELAY_MS = 100;
const THUMBNAIL_CACHE = 400;

const $ = (selector) => document.querySelector(selector);
const state = {
  info: null,        // GET /api/info of the current lighting
  lightings: [],     // GET /api/lightings: one database per map
  lighting: '',      // the current one's id, named in every API call
  history: [],  // {material, lighting} visited; `at` is the current one
  at: -1,
  tab: 'gallery',
  radius: 0,
  exact: true,  // variations placed by rendering (POST /api/neighbors exact: true)
  display: '',
  view: '',
};
let generation = 0;  // bumped by every redraw; answers for an older one are dropped
let neighborQuery = null;
// Whether the ring had the keyboard focus when a redraw began: the new ring takes it back,
// rather than leaving it on <body> when the old variations go.
let ringFocus = false;

// ---- the API ------------------------------------------------------------------------------

// `path` with the lighting the call is for (the current one unless `lighting` is given).
function apiPath(path, lighting = state.lighting) {
  if (!lighting) return path;
  return `${path}${path.includes('?') ? '&' : '?'}lighting=${encodeURIComponent(lighting)}`;
}

async function call(path, body, options = {}) {
  const init = { method: body === undefined ? 'GET' : 'POST', signal: options.signal };
  if (body !== undefined) {
    init.body = typeof body === 'string' ? body : JSON.stringify(body);
    init.headers = { 'Content-Type': options.type || 'application/json' };
  }
  const response = await fetch(apiPath(path, options.lighting), init);
  if (!response.ok) {
    const text = await response.text();
    let message = `${path}: HTTP ${response.status}`;
    try { message = JSON.parse(text).error || message; } catch { /* not JSON */ }
    throw new Error(message);
  }
  return response;
}

// Thumbnail object URLs by (material, display, view, preview, size), least recently used first:
// going back, or to a variation already on screen, shows its image at once.
const thumbnails = new Map();

// This page's name for the server, which drops the renders of the rings it has left: every
// query and exact thumbnail carries `ring: {client, id: generation}` (docs/SERVE.md).
const CLIENT = (crypto.randomUUID?.() ?? `${Date.now()}-${Math.random()}`).replace(/[^\w-]/g, '');
const ring = (gen) => ({ client: CLIENT, id: gen });

// The PNG of a material's thumbnail for the ring `gen`: the exact render, or with `preview` the
// quick blend of the database's images that stands in while the exact one renders. `size`: one
// of the server's thumbnail_sizes, its resolution by default.
function thumbnail(material, gen, preview = false, size = undefined) {
  const key = JSON.stringify([state.lighting, material, state.display, state.view, preview, size]);
  let entry = thumbnails.get(key);
  // Still on its way for a ring left since, which the server may drop: asked again for this one
  // (if it is being rendered, the server answers both from one render).
  if (entry && entry.pending && entry.gen < gen) entry = undefined;
  if (entry) {
    thumbnails.delete(key);  // now the most recently used
    thumbnails.set(key, entry);
    return entry.url;
  }
  entry = { gen, pending: true };
  entry.url = call('/api/thumbnail', { material, display: state.display, view: state.view,
    preview, size, ring: ring(gen) })
    .then((r) => r.blob())
    .then((blob) => URL.createObjectURL(blob));
  entry.url.then(() => { entry.pending = false; }, () => {
    if (thumbnails.get(key) === entry) thumbnails.delete(key);
  });
  thumbnails.set(key, entry);
  if (thumbnails.size > THUMBNAIL_CACHE) {
    const [oldest, old] = thumbnails.entries().next().value;
    thumbnails.delete(oldest);
    old.url.then(URL.revokeObjectURL, () => {});
  }
  return entry.url;
}

// ---- progress: shown only when the work takes longer than PROGRESS_DELAY_MS -----------------

const progress = {
  timer: 0,
  start(text) {
    clearTimeout(this.timer);
    this.set(text, 0, 0);
    this.timer = setTimeout(() => { $('#progress').hidden = false; }, PROGRESS_DELAY_MS);
  },
  set(text, done, total) {
    $('#progress span').textContent = text;
    const bar = $('#progress progress');
    if (total > 0) { bar.max = total; bar.value = done; } else { bar.removeAttribute('value'); }
  },
  stop() {
    clearTimeout(this.timer);
    $('#progress').hidden = true;
  },
};

// ---- formatting -----------------------------------------------------------------------------

const number = (x) => (Math.abs(x) >= 1e4 || (x !== 0 && Math.abs(x) < 1e-3)
  ? x.toExponential(3) : Number(x.toPrecision(4)).toString());
const rgb = (c) => c.map((x) => x.toFixed(3)).join(' ');

// The centre image's text alternative: the model and the values the readout lists.
function describe(material) {
  const { title, params } = modelInfo(material.model);
  const values = params.map((p) => `${p.name} ${number(material.params[p.name])}`);
  return `Current material: ${title}, ${values.join(', ')}, rho_d ${rgb(material.rho_d)}, ` +
    `rho_s ${rgb(material.rho_s)}`;
}

function modelInfo(name) {
  return state.info.models.find((m) => m.name === name);
}

// ---- drawing --------------------------------------------------------------------------------

function drawReadout(material) {
  const info = modelInfo(material.model);
  $('#readout h2').textContent = `${info.title} (${info.name})`;
  const rows = info.params.map((p) => [p.name, number(material.params[p.name]), p.unit,
    p.description]);
  rows.push(['rho_d', rgb(material.rho_d), 'RGB', 'diffuse albedo'],
    ['rho_s', rgb(material.rho_s), 'RGB', 'specular scale'],
    ['colorspace', material.colorspace, '', 'colour space of rho_d and rho_s']);
  $('#readout tbody').replaceChildren(...rows.map(([name, value, unit, help]) => {
    const tr = document.createElement('tr');
    tr.title = help;
    tr.dataset.key = name;
    for (const text of [name, value, unit === '1' ? '' : unit]) {
      const td = document.createElement('td');
      td.textContent = text;
      tr.append(td);
    }
    return tr;
  }));
}

// The flags in words (the API's names are for programs).
const FLAG_WORDS = {
  at_boundary: 'end of range',
  clamped: 'colour at its limit',
  beyond_radius: 'closest this model gets',
};

// The offer's words ("sharper", "towards red", "as Ward"), its distance and its flags, as
// elements (labels are data, never markup).
function caption(n) {
  const span = document.createElement('span');
  span.className = 'caption';
  const name = document.createElement('b');
  name.textContent = n.words || n.label;
  const line = document.createElement('span');
  line.textContent = `d = ${n.distance.toFixed(4)}`;
  span.append(name, line);
  for (const flag of n.flags) {
    const badge = document.createElement('span');
    badge.className = 'flag';
    badge.textContent = FLAG_WORDS[flag] ?? flag.replace('_', ' ');
    line.append(' ', badge);
  }
  return span;
}

// The ring's geometry in CSS pixels. A variation is a 176 x 232 box (its 160 px image, padding
// and three caption lines: a name of up to two, its distance) placed by its image's centre, 84 px
// below the box's top; the centre's 256 px image and caption take -128..128 across and -128..162
// down around the middle.
const BOX = { width: 176, height: 232, above: 84 };
const CENTRE = { left: -128, right: 128, top: -128, bottom: 162 };
const MAX_RX = 408;  // a stage of 2 * 408 + 176 = 992 px fits a 1024 px window

function ringBoxes(count, rx, ry) {
  return Array.from({ length: count }, (_, i) => {
    const angle = (2 * Math.PI * i) / count;
    const x = Math.round(rx * Math.sin(angle));
    const y = Math.round(-ry * Math.cos(angle));
    return { x, y, left: x - BOX.width / 2, right: x + BOX.width / 2, top: y - BOX.above,
      bottom: y - BOX.above + BOX.height };
  });
}

const apart = (a, b, gap) => a.right + gap <= b.left || b.right + gap <= a.left ||
  a.bottom + gap <= b.top || b.bottom + gap <= a.top;

// The smallest circle (radius at most MAX_RX) on which `count` boxes at angles 2 pi i / count
// touch neither the centre nor each other; past MAX_RX an ellipse taller than wide.
function ringLayout(count) {
  const fits = (rx, ry) => {
    const boxes = ringBoxes(count, rx, ry);
    return boxes.every((b, i) => apart(b, CENTRE, 12) &&
      boxes.slice(0, i).every((o) => apart(b, o, 8)));
  };
  for (let r = 260; r <= MAX_RX; r += 4) if (fits(r, r)) return { rx: r, ry: r };
  let ry = MAX_RX;
  while (!fits(MAX_RX, ry) && ry < 2000) ry += 4;
  return { rx: MAX_RX, ry };
}

// The variations on a circle (or an ellipse) around the centre, in the service's ring order:
// offer i at angle 2 pi i / n clockwise from the top, so that each offer faces its opposite
// (i + n/2) across the current material, with no gap however many there are.
function drawRing(neighbors, placeholders = new Map()) {
  ringFocus ||= $('#ring').contains(document.activeElement);
  const { rx, ry } = ringLayout(neighbors.length);
  const boxes = ringBoxes(neighbors.length, rx, ry);
  const stage = $('#stage');
  stage.style.setProperty('--rx', `${rx}px`);
  stage.style.setProperty('--ry', `${ry}px`);
  const figures = neighbors.map((n, i) => {
    const button = document.createElement('button');
    button.type = 'button';
    button.className = 'variation';
    button.style.setProperty('--x', `${boxes[i].x}px`);
    button.style.setProperty('--y', `${boxes[i].y}px`);
    Object.assign(button.dataset, {
      tab: n.tab, label: n.label, distance: n.distance, flags: n.flags.join(' '),
      material: JSON.stringify(n.material),
    });
    button.title = `${n.words}: ${n.change}`;
    // Already at the end of the database grid (or of the colour range) in this direction.
    if (n.distance < 1e-3 * state.radius) button.classList.add('no-step');
    const img = document.createElement('img');
    img.alt = '';  // the caption names it
    if (placeholders.has(n.label)) img.src = placeholders.get(n.label);
    button.append(img, caption(n));
    button.addEventListener('click', () => navigate(n.material));
    return button;
  });
  $('#ring').replaceChildren(...figures);
  $('#ring').removeAttribute('aria-busy');
  $('#empty').hidden = neighbors.length > 0;
  // Unless the focus went elsewhere meanwhile (a tab, the slider).
  const lost = !document.activeElement || document.activeElement === document.body;
  if (ringFocus && lost) figures[0]?.focus();
  ringFocus = false;
  return neighbors.map((n, i) => [n, figures[i].querySelector('img')]);
}

// The variations of the previous state are not clickable while the new ones load: a second
// click would navigate from a material no longer current, or push the same one twice.
function freezeRing() {
  const ring = $('#ring');
  ringFocus ||= ring.contains(document.activeElement);
  ring.setAttribute('aria-busy', 'true');
  for (const button of ring.querySelectorAll('button')) button.disabled = true;
}

// What a failed query leaves: no variation of another state, and no "none here" either.
function clearRing() {
  $('#ring').replaceChildren();
  $('#ring').removeAttribute('aria-busy');
  $('#empty').hidden = true;
  ringFocus = false;
}

// Puts the thumbnail on `img` unless a newer redraw has begun meanwhile: its images win.
async function show(img, url, gen) {
  const src = await url;
  if (gen !== generation) return;
  img.src = src;
  await img.decode();
}

// A short confirmation (an export), read out by screen readers, gone after a few seconds.
let noticeTimer = 0;
function notify(message) {
  $('#notice').textContent = message;
  $('#notice').hidden = false;
  clearTimeout(noticeTimer);
  noticeTimer = setTimeout(() => { $('#notice').hidden = true; }, 5000);
}

// The preview first, then the exact render in its place; resolves when the exact one is shown.
async function progressive(img, material, gen) {
  await show(img, thumbnail(material, gen, true), gen);
  await show(img, thumbnail(material, gen), gen);
}

// The size of the centre's sharp render: the smallest the server offers that fills the centre's
// 256 CSS pixels in device pixels (512 at a device pixel ratio of 2), else its largest.
function sharpSize() {
  const wanted = 256 * (window.devicePixelRatio || 1);
  const sizes = state.info.thumbnail_sizes;
  return sizes.find((s) => s >= wanted - 0.5) ?? sizes[sizes.length - 1];
}

// Once the ring is on screen: the centre at sharpSize() in place of its render at the
// thumbnails' resolution. <img data-size> says which is shown.
async function sharpen(img, material, gen) {
  const size = sharpSize();
  if (size <= state.info.thumbnail_resolution) return;
  await show(img, thumbnail(material, gen, false, size), gen);
  if (gen === generation) img.dataset.size = String(size);
}

// The ring the embedding places, shown in previews until the exact one replaces it (clickable:
// its offers are good materials at about eps). Resolves, once its previews are drawn, to each
// offer's preview by label: the exact ring's placeholders, so that nothing flickers.
async function previewRing({ neighbors }, gen) {
  if (gen !== generation) return new Map();
  const images = drawRing(neighbors);
  $('#ring').setAttribute('aria-busy', 'true');  // the exact ring is on its way
  await Promise.all(images.map(([n, img]) =>
    show(img, thumbnail(n.material, gen, true), gen).catch(() => {})));
  return new Map(images.map(([n, img]) => [n.label, img.src]));
}

function showError(message) {
  $('#error').textContent = message;
  $('#error').hidden = !message;
}

// Redraws the stage for the current material, tab, radius and display. <body data-ready> says
// to tests when every image is on screen; the centre's sharp render comes after.
async function redraw() {
  const gen = ++generation;
  const { material, lighting } = state.history[state.at];
  if (lighting !== state.lighting) {  // Back or Forward across a change of lighting
    document.body.dataset.ready = 'false';
    try {
      await useLighting(lighting);
    } catch (error) {
      showError(error.message);
      document.body.dataset.ready = 'true';
      return;
    }
    if (gen !== generation) return;
  }
  document.body.dataset.ready = 'false';
  $('#back').disabled = state.at <= 0;
  $('#forward').disabled = state.at >= state.history.length - 1;
  for (const tab of document.querySelectorAll('#tabs [role=tab]'))
    tab.setAttribute('aria-selected', String(tab.dataset.tab === state.tab));
  const centre = $('#centre');
  centre.dataset.material = JSON.stringify(material);
  centre.querySelector('figcaption').textContent = modelInfo(material.model).title;
  centre.querySelector('img').alt = describe(material);
  centre.querySelector('img').dataset.size = String(state.info.thumbnail_resolution);
  drawReadout(material);
  freezeRing();
  neighborQuery?.abort();
  neighborQuery = new AbortController();
  // The gallery's offers are the database's own materials: nothing to render to place them.
  const exact = state.exact && state.tab !== 'gallery';
  progress.start(exact ? 'Rendering to place the variations\u2026' : 'Finding variations\u2026');
  let shown = false;  // every image of the ring: the centre's sharp render follows
  try {
    const centreShown = progressive(centre.querySelector('img'), material, gen);
    centreShown.catch(() => {});  // awaited below, unless this redraw is overtaken first
    const query = (steps) => call('/api/neighbors',
      { material, radius: state.radius, tab: state.tab, exact: steps, ring: ring(gen) },
      { signal: neighborQuery.signal }).then((r) => r.json());
    // With exact steps: the embedding's ring at once, in previews, until renders place the
    // ring; the exact query starts once the previews are shown, so as not to slow them down.
    const placeholders = exact ? await previewRing(await query(false), gen) : undefined;
    if (gen !== generation) return;
    const { neighbors } = await query(exact);
    if (gen !== generation) return;
    const images = drawRing(neighbors, placeholders);
    let done = 0;
    const total = images.length + 1;
    const step = () => progress.set(`Rendering thumbnails ${++done} / ${total}`, done, total);
    progress.set(`Rendering thumbnails 0 / ${total}`, 0, total);
    await Promise.all([centreShown.then(step),
      ...images.map(([n, img]) => progressive(img, n.material, gen).then(step))]);
    if (gen !== generation) return;
    showError('');
    shown = true;
  } catch (error) {
    if (error.name === 'AbortError' || gen !== generation) return;
    if ($('#ring').hasAttribute('aria-busy')) clearRing();  // still the previous state's ring
    showError(error.message);
  }
  progress.stop();
  document.body.dataset.ready = 'true';
  if (shown) {
    await sharpen(centre.querySelector('img'), material, gen).catch((error) => {
      if (gen === generation) showError(error.message);
    });
  }
}

// ---- actions --------------------------------------------------------------------------------

// Makes `material` the current one; the current one again (a load of the same file) adds no
// history entry, which Back would seem to skip.
function navigate(material) {
  const entry = { material, lighting: state.lighting };
  if (JSON.stringify(entry) !== JSON.stringify(state.history[state.at])) {
    state.history.splice(state.at + 1, Infinity, entry);
    state.at = state.history.length - 1;
  }
  redraw();
}

function move(by) {
  const at = state.at + by;
  if (at < 0 || at >= state.history.length) return;
  state.at = at;
  redraw();
}

const radiusAt = (position) => {
  const { min, max } = state.info.radius;
  return min * (max / min) ** (position / SLIDER_STEPS);
};
const positionOf = (radius) => {
  const { min, max } = state.info.radius;
  return Math.round((SLIDER_STEPS * Math.log(radius / min)) / Math.log(max / min));
};

function setRadius(position) {
  const slider = $('#radius');
  slider.value = Math.min(SLIDER_STEPS, Math.max(0, position));
  state.radius = radiusAt(Number(slider.value));
  $('#radius-value').textContent = state.radius.toFixed(4);
  slider.setAttribute('aria-valuetext', `radius ${state.radius.toFixed(4)}`);
}

function selectTab(tab) {
  state.tab = tab;
  // The keyboard focus follows the selection among the tabs, so that a shortcut does not leave
  // the focus ring on the tab the page has left.
  const focused = document.activeElement;
  if (focused?.closest('#tabs') && focused.dataset.tab !== tab)
    document.querySelector(`#tabs [data-tab=${tab}]`)?.focus();
  redraw();
}

// The export formats: the file's extension and type. MaterialX and Cycles take the material's
// ggx form; the server renders it to state the residual, which takes a few seconds.
const EXPORT_FORMATS = {
  yaml: { extension: 'yaml', type: 'application/yaml' },
  materialx: { extension: 'mtlx', type: 'application/xml' },
  cycles: { extension: 'json', type: 'application/json' },
};

async function exportMaterial() {
  const button = $('#export');
  button.disabled = true;
  try {
    const { material } = state.history[state.at];
    const format = $('#export-format').value;
    const text = await (await call('/api/export', { material, format })).text();
    const link = document.createElement('a');
    link.href = URL.createObjectURL(new Blob([text], { type: EXPORT_FORMATS[format].type }));
    link.download = `brdfnav-${material.model}.${EXPORT_FORMATS[format].extension}`;
    link.click();
    setTimeout(() => URL.revokeObjectURL(link.href), 10000);
    notify(`Exported ${link.download}: ${modelInfo(material.model).title}, with its ` +
      'equivalents in the other models');
  } catch (error) {
    showError(`Export: ${error.message}`);
  } finally {
    button.disabled = false;
  }
}

async function loadYaml(file) {
  document.body.dataset.ready = 'false';  // until the loaded material is drawn
  try {
    const path = `/api/import?name=${encodeURIComponent(file.name)}`;
    const answer = await call(path, await file.text(), { type: 'application/yaml' });
    navigate((await answer.json()).material);
  } catch (error) {
    showError(error.message);
    document.body.dataset.ready = 'true';
  }
}

function fillViews() {
  const display = state.info.displays.find((d) => d.name === state.display);
  const select = $('#view');
  select.replaceChildren(...display.views.map((v) => new Option(v, v)));
  if (!display.views.includes(state.view)) [state.view] = display.views;
  select.value = state.view;
}

function onKey(event) {
  const target = event.target;
  if (target.matches('select, input[type=file]') || event.ctrlKey || event.metaKey) return;
  const alt = event.altKey;
  const actions = {
    '[': () => move(-1),
    ']': () => move(1),
    '+': () => changeRadius(KEY_STEP),
    '=': () => changeRadius(KEY_STEP),
    '-': () => changeRadius(-KEY_STEP),
  };
  TABS.forEach(([tab], i) => { actions[String(i + 1)] = () => selectTab(tab); });
  let action = alt ? null : actions[event.key];
  if (alt && event.key === 'ArrowLeft') action = () => move(-1);
  if (alt && event.key === 'ArrowRight') action = () => move(1);
  if (!action) return;
  event.preventDefault();
  action();
}

function changeRadius(steps) {
  setRadius(Number($('#radius').value) + steps);
  redraw();
}

// ---- start ----------------------------------------------------------------------------------

// ---- lighting: one database per map, the current material carried from one to another ----

const lightingOf = (id) => state.lightings.find((l) => l.id === id);
const environmentPicture = (id) => apiPath(`/api/environment?display=${
  encodeURIComponent(state.display)}&view=${encodeURIComponent(state.view)}`, id);

// The current lighting's name and picture, and a button for each of the others.
function drawLightings() {
  const current = lightingOf(state.lighting);
  $('#lit-by img').src = environmentPicture(current.id);
  $('#lit-by img').alt = `the map ${current.map}`;
  $('#lit-by strong').textContent = current.map;
  $('#lightings').hidden = state.lightings.length < 2;
  $('#lightings').replaceChildren(...state.lightings.map((l) => {
    const button = document.createElement('button');
    Object.assign(button, { type: 'button', title: `Light every image by ${l.map} (${l.path}; ` +
      `${l.profile} profile, ${l.resolution} px; models: ${l.models.join(', ')})` });
    button.dataset.lighting = l.id;
    button.setAttribute('aria-pressed', String(l.id === state.lighting));
    const picture = new Image();
    picture.src = environmentPicture(l.id);
    picture.alt = '';
    button.append(picture, l.map.replace(/\.[^.]*$/, ''));
    button.addEventListener('click', () => switchLighting(l.id));
    return button;
  }));
}

// Makes `id` the current lighting: its database's models, grids and provenance.
async function useLighting(id) {
  const info = await (await call('/api/info', undefined, { lighting: id })).json();
  state.lighting = id;
  state.info = info;
  $('#provenance').textContent = describeDatabase(info);
  drawLightings();
}

// Moves to lighting `id` with the current material: the same parameters where its model is in
// both databases, else its nearest material there (POST /api/carry).
async function switchLighting(id) {
  if (id === state.lighting) return;
  document.body.dataset.ready = 'false';
  try {
    const { material } = state.history[state.at];
    const answer = await (await call('/api/carry', { material, from: state.lighting },
      { lighting: id })).json();
    const before = modelInfo(material.model).title;
    await useLighting(id);
    if (answer.carried === 'nearest') {
      notify(`${before} is not in the ${lightingOf(id).map} database: its nearest material ` +
        `there is ${modelInfo(answer.material.model).title}`);
    } else if (answer.carried === 'start') {
      notify(`The ${lightingOf(id).map} database shares no model with the last one: its start ` +
        'material is shown');
    }
    navigate(answer.material);
  } catch (error) {
    showError(`Lighting: ${error.message}`);
    document.body.dataset.ready = 'true';
  }
}

function describeDatabase(info) {
  const db = info.database;
  const env = db.environment.path.split('/').pop();
  return `Database ${db.database}: profile ${db.profile}, ${db.resolution} px, ${db.scene}, ${env}` +
    ` \u00b7 ${info.colour_config}`;
}

function wire() {
  $('#tabs').replaceChildren(...TABS.filter(([tab]) => state.info.tabs.includes(tab))
    .map(([tab, title], i) => {
      const button = document.createElement('button');
      Object.assign(button, { type: 'button', textContent: title, title: `${title} (${i + 1})` });
      button.setAttribute('role', 'tab');
      button.dataset.tab = tab;
      button.addEventListener('click', () => selectTab(tab));
      return button;
    }));
  $('#back').addEventListener('click', () => move(-1));
  $('#forward').addEventListener('click', () => move(1));
  let pending = 0;
  $('#radius').addEventListener('input', (event) => {
    setRadius(Number(event.target.value));
    document.body.dataset.ready = 'false';  // a redraw is coming
    clearTimeout(pending);
    pending = setTimeout(redraw, 120);  // one query when the slider rests, not one per pixel
  });
  $('#display').replaceChildren(...state.info.displays.map((d) => new Option(d.name, d.name)));
  $('#display').addEventListener('change', (event) => {
    state.display = event.target.value;
    fillViews();
    drawLightings();
    redraw();
  });
  $('#view').addEventListener('change', (event) => {
    state.view = event.target.value;
    drawLightings();
    redraw();
  });
  $('#exact').addEventListener('change', (event) => { state.exact = event.target.checked; redraw(); });
  $('#export').addEventListener('click', exportMaterial);
  $('#load-file').addEventListener('change', (event) => {
    const [file] = event.target.files;
    if (file) loadYaml(file);
    event.target.value = '';  // the same file again is a new load
  });
  $('#error').addEventListener('click', () => showError(''));
  document.addEventListener('keydown', onKey);
}

async function start() {
  try {
    const lightings = await (await call('/api/lightings')).json();
    state.lightings = lightings.lightings;
    state.lighting = lightings.default;
    state.info = await (await call('/api/info')).json();
  } catch (error) {
    showError(`Cannot reach the navigator: ${error.message}`);
    document.body.dataset.ready = 'true';
    return;
  }
  $('#provenance').textContent = describeDatabase(state.info);
  [state.display] = state.info.displays.map((d) => d.name);
  wire();
  fillViews();
  drawLightings();
  setRadius(positionOf(state.info.radius.start));
  navigate(state.info.start);
}

start();
