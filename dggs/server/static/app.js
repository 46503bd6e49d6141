// The dggs web map: the store's cells on a MapLibre globe, rolled up by the server to a level chosen
// from the zoom (GET map/layers, GET map/cells), coloured by a value, with a legend and a cell popup.
// An ES module with no build step; MapLibre GL JS comes from /static/vendor (no internet needed).
import { Map as MapLibreMap, NavigationControl, Popup } from './vendor/maplibre-gl/maplibre-gl.mjs';

// --- Level from zoom ------------------------------------------------------------------------------
// From level 1 on, each level divides a cell into 3 similar triangles: cells shrink sqrt(3)-fold in
// length per level, while each zoom step doubles the map's scale. So level = a + b * z, rounded and
// clamped to 0..stored_level, with b = log(2) / log(sqrt(3)) = 1.262 levels per zoom step. z is the
// zoom corrected for the globe's latitude scale (MapLibre's globe shows 512 * 2^zoom / cos(lat) px per
// turn at the centre, as Mercator does), so cells keep their on-screen size whatever the latitude.
// A level-1 cell (4.25 million km2, sqrt 2,062 km) is 26 px at z = 0; a = 2.4 keeps the square root of a
// cell's area at 10-17 px (its long edge at 20-40 px): a full window holds a few thousand cells.
const LEVEL_PER_ZOOM = Math.log(2) / Math.log(Math.sqrt(3));
const LEVEL_AT_ZOOM_0 = 2.4;
const WORLD_BBOX = [-180, -90, 180, 90];

// Colour ramp (ColorBrewer YlOrRd, 5 classes): bright on the dark globe, from the minimum to the maximum.
const RAMP = ['#ffffb2', '#fecc5c', '#fd8d3c', '#f03b20', '#bd0026'];
const NO_VALUE_COLOUR = '#8b949e';
const GLOBE_COLOUR = '#1b2736';
const GRATICULE_COLOUR = '#3b4d63';
const ZONES_PATH = 'dggs/DGGS-Split26-ISEA/zones/';

const $ = (id) => document.getElementById(id);
const ui = {
  column: $('column'),
  stat: $('stat'),
  level: $('level'),
  legendTitle: $('legend-title'),
  legendRamp: $('legend-ramp'),
  legendMin: $('legend-min'),
  legendMax: $('legend-max'),
  status: $('status'),
  subtitle: $('subtitle'),
};

// State read by the tests (and handy in the console).
const state = {
  level: null,          // level of the cells on the map
  featureCount: 0,      // cells on the map
  loading: true,
  lastError: null,
  column: null,         // null: row count; else a numeric column
  stat: 'count',
  bbox: null,           // bbox of the last request [w, s, e, n]
  min: null,            // legend range
  max: null,
  renders: 0,           // fetches rendered so far
  selected: null,       // zone id of the clicked cell
};
window.dggsState = state;

let layers = null;        // GET map/layers
let requestSeq = 0;       // the latest refresh; older answers are dropped
let controller = null;    // aborts the previous request
let shownKey = null;      // the request whose cells are on the map

// --- Helpers --------------------------------------------------------------------------------------
const clamp = (x, lo, hi) => Math.min(hi, Math.max(lo, x));
const wrapLng = (lng) => ((((lng + 180) % 360) + 360) % 360) - 180;

function formatNumber(x) {
  if (x === null || x === undefined || Number.isNaN(x)) return '–';
  if (Number.isInteger(x)) return x.toLocaleString('en-US');
  const digits = Math.abs(x) >= 100 ? 1 : Math.abs(x) >= 1 ? 3 : 5;
  return x.toLocaleString('en-US', { maximumFractionDigits: digits });
}

function setStatus(text, isError = false) {
  ui.status.textContent = text;
  ui.status.classList.toggle('error', isError);
}

function setBodyState(value) {
  document.body.dataset.state = value;
}

function valueLabel() {
  return state.column === null ? 'count (rows per cell)' : `${state.stat} of ${state.column}`;
}

// A graticule every 30 degrees, densified so the lines follow the globe.
function graticule(step = 30, density = 2) {
  const features = [];
  for (let lng = -180; lng < 180; lng += step) {
    const coords = [];
    for (let lat = -90; lat <= 90; lat += density) coords.push([lng, lat]);
    features.push({ type: 'Feature', properties: {}, geometry: { type: 'LineString', coordinates: coords } });
  }
  for (let lat = -90 + step; lat < 90; lat += step) {
    const coords = [];
    for (let lng = -180; lng <= 180; lng += density) coords.push([lng, lat]);
    features.push({ type: 'Feature', properties: {}, geometry: { type: 'LineString', coordinates: coords } });
  }
  return { type: 'FeatureCollection', features };
}

const EMPTY = { type: 'FeatureCollection', features: [] };

// --- The map --------------------------------------------------------------------------------------
const style = {
  version: 8,
  projection: { type: 'globe' },
  sources: {
    graticule: { type: 'geojson', data: graticule() },
    cells: { type: 'geojson', data: EMPTY },
  },
  layers: [
    { id: 'background', type: 'background', paint: { 'background-color': GLOBE_COLOUR } },
    {
      id: 'graticule', type: 'line', source: 'graticule',
      paint: { 'line-color': GRATICULE_COLOUR, 'line-width': 1 },
    },
    {
      id: 'cells-fill', type: 'fill', source: 'cells',
      paint: { 'fill-color': RAMP[0], 'fill-opacity': 0.9 },
    },
    {
      id: 'cells-line', type: 'line', source: 'cells',
      paint: { 'line-color': 'rgba(14, 17, 23, 0.45)', 'line-width': 0.5 },
    },
    {
      id: 'cells-selected', type: 'line', source: 'cells',
      filter: ['==', ['get', 'zone_id'], ''],
      paint: { 'line-color': '#ffffff', 'line-width': 2 },
    },
  ],
};

const map = new MapLibreMap({
  container: 'map',
  style,
  center: [10, 20],
  zoom: 1.5,
  attributionControl: false,
  maxPitch: 60,
});
window.dggsMap = map;
map.addControl(new NavigationControl({ visualizePitch: true }), 'top-right');

const popup = new Popup({ closeButton: true, closeOnClick: true, maxWidth: '280px' });
popup.on('close', () => {
  state.selected = null;
  if (map.getLayer('cells-selected')) map.setFilter('cells-selected', ['==', ['get', 'zone_id'], '']);
});

// A screen point off the globe does not survive unproject + project (unproject clamps it to the limb).
function onGlobe(x, y) {
  const back = map.project(map.unproject([x, y]));
  return Math.hypot(back.x - x, back.y - y) < 2;
}

// The globe's radius on screen (px), found along the vertical through the centre.
function globeRadius() {
  const { clientWidth: w, clientHeight: h } = map.getCanvas();
  let lo = 0;
  let hi = Math.max(w, h) * 4;
  for (let i = 0; i < 24; i += 1) {
    const mid = (lo + hi) / 2;
    if (onGlobe(w / 2, h / 2 - mid)) lo = mid; else hi = mid;
  }
  return lo;
}

// Show the whole globe around `center`, filling about 85 % of the window's smaller side.
function showWholeGlobe(center) {
  const { clientWidth: w, clientHeight: h } = map.getCanvas();
  const target = Math.min(w, h) * 0.425;
  map.jumpTo({ center, zoom: 1, pitch: 0, bearing: 0 });
  for (let i = 0; i < 4; i += 1) {
    const radius = globeRadius();
    if (!(radius > 0) || Math.abs(radius - target) < 2) break;
    map.jumpTo({ zoom: map.getZoom() + Math.log2(target / radius) });
  }
}

// The zoom corrected for the globe's scale at the centre's latitude (see "Level from zoom").
function scaleZoom() {
  const lat = clamp(map.getCenter().lat, -85, 85);
  return map.getZoom() - Math.log2(Math.cos((lat * Math.PI) / 180));
}

function levelForZoom(zoom) {
  return clamp(Math.round(LEVEL_AT_ZOOM_0 + LEVEL_PER_ZOOM * zoom), 0, layers.stored_level);
}

function targetLevel() {
  const chosen = ui.level.value;
  return chosen === 'auto' ? levelForZoom(scaleZoom()) : Number(chosen);
}

// Whether the whole globe is in the window: the window's border (corners and edge midpoints) lies
// off the globe.
function wholeGlobeInView() {
  const { clientWidth: w, clientHeight: h } = map.getCanvas();
  const border = [[0, 0], [w / 2, 0], [w, 0], [0, h / 2], [w, h / 2], [0, h], [w / 2, h], [w, h]];
  return border.every(([x, y]) => !onGlobe(x, y));
}

// The part of the world in view, [w, s, e, n] (w > e across the antimeridian), padded by 5 % so small
// moves need no new cells; the whole world when the whole globe is in view.
function viewBbox() {
  if (wholeGlobeInView()) return WORLD_BBOX;
  const b = map.getBounds();
  let w = b.getWest();
  let e = b.getEast();
  let s = b.getSouth();
  let n = b.getNorth();
  if (!Number.isFinite(w + e + s + n)) return WORLD_BBOX;
  const padLng = (e - w) * 0.05;
  const padLat = (n - s) * 0.05;
  s = clamp(s - padLat, -90, 90);
  n = clamp(n + padLat, -90, 90);
  w -= padLng;
  e += padLng;
  if (e - w >= 360 || n >= 89.99 || s <= -89.99) {
    // A pole in view: every longitude is.
    w = -180;
    e = 180;
  } else {
    w = wrapLng(w);
    e = wrapLng(e);
    if (e === -180) e = 180;
  }
  return [w, s, e, n].map((x) => Math.round(x * 1e4) / 1e4);
}

function cellsUrl(level, bbox) {
  const params = new URLSearchParams({ level: String(level), bbox: bbox.join(',') });
  if (state.column === null) {
    params.set('stat', 'count');
  } else {
    params.set('column', state.column);
    params.set('stat', state.stat);
  }
  return `map/cells?${params}`;
}

// Fill colour: the ramp from min to max of the values in view; grey where a cell has no value.
function fillColour(min, max) {
  if (min === null) return RAMP[0];
  let ramp;
  if (max > min) {
    ramp = ['interpolate', ['linear'], ['get', 'value']];
    RAMP.forEach((colour, i) => ramp.push(min + ((max - min) * i) / (RAMP.length - 1), colour));
  } else {
    ramp = RAMP[RAMP.length - 1];
  }
  return ['case', ['==', ['typeof', ['get', 'value']], 'number'], ramp, NO_VALUE_COLOUR];
}

function updateLegend(min, max) {
  ui.legendTitle.textContent = valueLabel();
  ui.legendRamp.style.background = `linear-gradient(to right, ${RAMP.join(', ')})`;
  ui.legendMin.textContent = formatNumber(min);
  ui.legendMax.textContent = formatNumber(max);
  ui.legendMin.dataset.value = min === null ? '' : String(min);
  ui.legendMax.dataset.value = max === null ? '' : String(max);
}

function render(fc, level, bbox, wanted) {
  if (state.level !== level) popup.remove(); // the clicked cell is gone
  let min = null;
  let max = null;
  for (const f of fc.features) {
    const v = f.properties.value;
    if (typeof v !== 'number' || !Number.isFinite(v)) continue;
    if (min === null || v < min) min = v;
    if (max === null || v > max) max = v;
  }
  map.getSource('cells').setData(fc);
  map.setPaintProperty('cells-fill', 'fill-color', fillColour(min, max));
  Object.assign(state, { level, featureCount: fc.features.length, min, max, bbox, lastError: null });
  updateLegend(min, max);
  const area = fc.features.length ? fc.features[0].properties.area_km2 : null;
  const areaText = area ? ` · ${formatNumber(Math.round(area))} km² each` : '';
  const coarser = level < wanted ? ` (level ${wanted} has too many cells here)` : '';
  setStatus(`level ${level} · ${fc.features.length.toLocaleString('en-US')} cells${areaText}${coarser}`);
}

function whenMapIdle(seq, value) {
  const done = () => {
    if (seq !== requestSeq) return;
    state.loading = false;
    state.renders += 1;
    setBodyState(value);
  };
  if (value !== 'idle') {
    done();
    return;
  }
  // The new data is parsed in a worker; the map fires 'idle' once it is drawn and nothing moves.
  map.once('idle', done);
  map.triggerRepaint();
}

async function readError(response) {
  try {
    const body = await response.json();
    return typeof body.detail === 'string' ? body.detail : JSON.stringify(body.detail ?? body);
  } catch {
    return `${response.status} ${response.statusText}`;
  }
}

// Fetch the cells in view at the level for the zoom (or the chosen level); on 413 (too many zones)
// step to coarser levels until the server accepts.
async function refresh() {
  if (!layers) return;
  const seq = ++requestSeq;
  if (controller) controller.abort();
  controller = new AbortController();
  const { signal } = controller;
  state.loading = true;
  setBodyState('loading');
  const bbox = viewBbox();
  const wanted = targetLevel();
  let level = wanted;
  const key = JSON.stringify([wanted, bbox, state.column, state.stat]);
  if (key === shownKey) {
    // Nothing new to fetch (say, the whole globe turned): the cells on the map stay.
    whenMapIdle(seq, 'idle');
    return;
  }
  try {
    for (;;) {
      const response = await fetch(cellsUrl(level, bbox), { signal });
      if (seq !== requestSeq) return;
      if (response.status === 413 && level > 0) {
        level -= 1;
        continue;
      }
      if (!response.ok) throw new Error(`cells at level ${level}: ${await readError(response)}`);
      const fc = await response.json();
      if (seq !== requestSeq) return;
      render(fc, level, bbox, wanted);
      shownKey = key;
      whenMapIdle(seq, 'idle');
      return;
    }
  } catch (err) {
    if (signal.aborted || seq !== requestSeq) return;
    state.lastError = String(err.message || err);
    shownKey = null;
    setStatus(state.lastError, true);
    whenMapIdle(seq, 'error');
  }
}

// --- The cell popup -------------------------------------------------------------------------------
function row(table, label, value, field) {
  const tr = table.insertRow();
  const th = document.createElement('th');
  th.scope = 'row';
  th.textContent = label;
  tr.appendChild(th);
  const td = tr.insertCell();
  td.textContent = value;
  if (field) td.dataset.field = field;
  return td;
}

function formatCentroid(centroid) {
  const coords = centroid && (centroid.coordinates || centroid);
  if (!Array.isArray(coords) || coords.length < 2) return null;
  const [lng, lat] = coords.map(Number);
  return `${lat.toFixed(4)}°, ${lng.toFixed(4)}°`;
}

async function showCell(feature, lngLat) {
  const p = feature.properties;
  state.selected = p.zone_id;
  map.setFilter('cells-selected', ['==', ['get', 'zone_id'], p.zone_id]);
  const box = document.createElement('div');
  box.className = 'cell-info';
  box.dataset.zoneId = p.zone_id;
  const table = document.createElement('table');
  row(table, 'zone', p.zone_id, 'zone_id');
  row(table, 'level', String(p.level), 'level');
  row(table, 'area', `${formatNumber(Number(p.area_km2))} km²`, 'area_km2');
  row(table, 'rows', formatNumber(Number(p.count)), 'count');
  if (state.column !== null) {
    const v = p.value;
    row(table, `${state.stat} of ${state.column}`, typeof v === 'number' ? formatNumber(v) : '–', 'value');
  }
  box.appendChild(table);
  popup.setLngLat(lngLat).setDOMContent(box).addTo(map);

  try {
    const response = await fetch(ZONES_PATH + encodeURIComponent(p.zone_id), {
      headers: { Accept: 'application/json' },
    });
    if (!response.ok || state.selected !== p.zone_id) return;
    const info = await response.json();
    const centroid = formatCentroid(info.centroid);
    if (centroid) row(table, 'centre', centroid, 'centroid');
    if (typeof info.parent === 'string') row(table, 'parent', info.parent, 'parent');
    box.dataset.info = 'loaded';
  } catch {
    // The zone information is extra; the popup already shows the cell.
  }
}

map.on('click', 'cells-fill', (e) => {
  if (e.features && e.features.length) showCell(e.features[0], e.lngLat);
});
map.on('mouseenter', 'cells-fill', () => { map.getCanvas().style.cursor = 'pointer'; });
map.on('mouseleave', 'cells-fill', () => { map.getCanvas().style.cursor = ''; });

// --- Controls -------------------------------------------------------------------------------------
function readControls() {
  state.column = ui.column.value === '' ? null : ui.column.value;
  ui.stat.disabled = state.column === null;
  state.stat = state.column === null ? 'count' : ui.stat.value;
}

function setUpControls() {
  ui.column.innerHTML = '';
  ui.column.add(new Option('count (rows)', ''));
  for (const name of layers.numeric_columns) ui.column.add(new Option(name, name));
  ui.level.innerHTML = '';
  ui.level.add(new Option('auto (from zoom)', 'auto', true, true));
  for (const level of layers.levels) ui.level.add(new Option(String(level), String(level)));
  for (const select of [ui.column, ui.stat, ui.level]) {
    select.addEventListener('change', () => {
      readControls();
      refresh();
    });
  }
  readControls();
  const rows = Number(layers.count).toLocaleString('en-US');
  ui.subtitle.textContent = `${layers.collection}: ${rows} rows at level ${layers.stored_level}`;
}

// Frame the data: the whole globe around the data's centre, or the data's bbox when it is small.
function frameData() {
  const [w, s, e, n] = layers.bbox || WORLD_BBOX;
  const lngSpan = e >= w ? e - w : e + 360 - w;
  const centre = [wrapLng(w + lngSpan / 2), clamp((s + n) / 2, -60, 60)];
  if (lngSpan > 60 || n - s > 40) {
    showWholeGlobe(centre);
  } else {
    map.fitBounds([[w, s], [w + lngSpan, n]], { padding: 60, maxZoom: 9, animate: false });
  }
}

async function start() {
  try {
    const response = await fetch('map/layers', { headers: { Accept: 'application/json' } });
    if (!response.ok) throw new Error(`map/layers: ${await readError(response)}`);
    layers = await response.json();
  } catch (err) {
    state.lastError = String(err.message || err);
    state.loading = false;
    setStatus(state.lastError, true);
    setBodyState('error');
    return;
  }
  setUpControls();
  if (layers.stored_level === null || layers.stored_level === undefined || !layers.levels.length) {
    state.loading = false;
    setStatus('The store holds no cells yet.');
    setBodyState('idle');
    return;
  }
  frameData();
  map.on('moveend', refresh);
  refresh();
}

map.on('error', (e) => {
  state.lastError = String((e.error && e.error.message) || e.error || e);
  console.error('map error', state.lastError);
});

if (map.loaded()) start();
else map.once('load', start);
