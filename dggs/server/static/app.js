// The dggs web map: the store's cells on a MapLibre globe, rolled up by the server to a level chosen
// from the zoom (GET map/layers, GET map/cells), coloured by a value in classes (quantiles, logarithmic or
// linear) with a legend of the classes, a cell popup, and Natural Earth's coastlines and borders beneath.
// An ES module with no build step; MapLibre GL JS, the countries (world-atlas, TopoJSON) and
// topojson-client come from /static/vendor, installed from npm (no internet needed). The cells come as ids
// (map/cells?f=uint64, 24 bytes a cell) and drawn by a WebGL layer from their outlines, computed by the grid's
// WebAssembly core (the JS package js/, copied to /static/vendor/dggs by `make static-wasm`; cells_layer.js); as
// GeoJSON from the server where the core is missing or with ?cells=geojson in the page's URL.
import { Map as MapLibreMap, Marker, NavigationControl, Popup } from './vendor/maplibre-gl/maplibre-gl.mjs';
import { CellsLayer, cellChunks } from './cells_layer.js';

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

// Colour classes (ColorBrewer YlOrRd, 7 classes): bright on the dark globe, lowest values palest.
const RAMP = ['#ffffb2', '#fed976', '#feb24c', '#fd8d3c', '#fc4e2a', '#e31a1c', '#b10026'];
const NO_VALUE_COLOUR = '#8b949e';
const GLOBE_COLOUR = '#1b2736';   // the sea
const LAND_COLOUR = '#2c3a4a';
const GRATICULE_COLOUR = '#33465c';
const COAST_COLOUR = '#8fa3b8';
const BORDER_COLOUR = '#5f7389';
// Natural Earth 1:50m countries (world-atlas), read with topojson-client; both from npm, like MapLibre.
const COUNTRIES_URL = new URL('./vendor/world-atlas/countries-50m.json', import.meta.url);
const TOPOJSON_URL = new URL('./vendor/topojson-client/topojson-client.min.js', import.meta.url);
// The zones of the DGGRS the store's data were binned with (map/layers says which; ISEA before it loads).
// A named dataset's zones are under its collection; the default dataset's under the root, as before datasets.
const zonesPath = () => `${state.collection === null ? '' : `collections/${encodeURIComponent(state.collection)}/`}`
  + `dggs/${encodeURIComponent((layers && layers.dggrs) || 'DGGS-Split26-ISEA')}/zones/`;
// map/layers of the dataset shown (the store's default one: no parameter).
const layersUrl = () => (state.collection === null ? 'map/layers'
  : `map/layers?${new URLSearchParams({ collection: state.collection })}`);

const $ = (id) => document.getElementById(id);
const ui = {
  collection: $('collection'),
  collectionField: $('collection-field'),
  column: $('column'),
  stat: $('stat'),
  level: $('level'),
  scale: $('scale'),
  legendTitle: $('legend-title'),
  legendLevel: $('legend-level'),
  legendSteps: $('legend-steps'),
  status: $('status'),
  subtitle: $('subtitle'),
};

// State read by the tests (and handy in the console).
const state = {
  collection: null,     // the dataset shown: null for the store's default one, else its collection id
  level: null,          // level of the cells on the map
  featureCount: 0,      // cells on the map
  loading: true,
  lastError: null,
  column: null,         // null: row count; else a numeric column
  stat: 'count',
  scale: 'quantile',    // colour classes: 'quantile', 'log' or 'linear'
  bbox: null,           // bbox of the last request [w, s, e, n]
  min: null,            // range of the values in view
  max: null,
  breaks: [],           // lower bounds of the colour classes after the first
  geography: 'loading', // Natural Earth's countries: 'loading', 'loaded' or 'missing'
  renders: 0,           // fetches rendered so far
  selected: null,       // zone id of the clicked cell
  source: 'loading',    // how cells arrive: 'ids' (drawn with the WebAssembly core) or 'geojson'
};
window.dggsState = state;

let layers = null;        // GET map/layers
let controlsWired = false; // the controls' listeners are added once
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

// --- Cells from ids ---------------------------------------------------------------------------------
// The grid's C core as WebAssembly gives each cell's outline from its id, with map_densify's points an edge as
// the server's GeoJSON has it (dggs.cell_to_polygon); cells_layer.js draws them as triangles on the globe.
let core = null; // the JS package (vendor/dggs/dggs.js), once its WebAssembly module is loaded
const coreReady = new URLSearchParams(window.location.search).get('cells') === 'geojson'
  ? Promise.resolve().then(() => { state.source = 'geojson'; })
  : import('./vendor/dggs/dggs.js')
    .then(async (m) => {
      await m.init(new URL('./vendor/dggs/dggs.wasm', import.meta.url));
      core = m;
      state.source = 'ids';
    })
    .catch((err) => {
      state.source = 'geojson';
      console.warn('cells as GeoJSON (no WebAssembly core):', String(err.message || err));
    });

const mapDensify = (level) => (level <= 2 ? 8 : level <= 5 ? 4 : 2); // dggs.server.reader.map_densify
const projectionOf = () => (layers && String(layers.dggrs).endsWith('IVEA') ? 'IVEA' : 'ISEA');
// Where the layer cannot draw (WebGL without what it needs), the cells come as GeoJSON again.
const cellsLayer = new CellsLayer('cells-ids', {
  opacity: 0.8,
  noValueColour: NO_VALUE_COLOUR,
  onError: (err) => {
    console.warn('cells as GeoJSON (the WebGL layer cannot draw):', String(err.message || err));
    core = null;
    state.source = 'geojson';
    if (map.getLayer(cellsLayer.id)) map.removeLayer(cellsLayer.id);
    shownKey = null;
    refresh();
  },
});
window.dggsCellsLayer = cellsLayer;

// map/cells?f=uint64's body: count n, n uint64 ids, n float64 counts, n float64 values (NaN: none).
function cellsFromBody(body) {
  const n = Number(new BigUint64Array(body, 0, 1)[0]);
  return { ids: new BigUint64Array(body, 8, n), counts: new Float64Array(body, 8 + 8 * n, n), values: new Float64Array(body, 8 + 16 * n, n) };
}

// For the tests: the zone ids the layer draws, and the triangles it draws for string ids of one level: for each
// zone its (lng, lat) vertices and its triangles' vertex indices (cells_layer.js's cellChunks, one cell a call).
window.dggsDrawnZones = () => (cellsLayer.cells ? Array.from(cellsLayer.cells.ids, (id) => core.cellToString(id)) : []);
// The cells on the map, whichever way they came: zone id, area and value of each, and the colour classes.
window.dggsDrawnCells = () => {
  if (!core) return map.querySourceFeatures('cells').map((f) => f.properties);
  const c = cellsLayer.cells;
  if (!c) return [];
  const area = core.cellArea(c.level, 'km^2');
  return Array.from(c.ids, (id, i) => ({
    zone_id: core.cellToString(id), area_km2: area, value: Number.isNaN(c.values[i]) ? null : c.values[i],
  }));
};
window.dggsCellPaint = () => (core
  ? JSON.stringify([cellsLayer.breaks, cellsLayer.colours])
  : JSON.stringify(map.getPaintProperty('cells-fill', 'fill-color')));
window.dggsCellTriangles = async (zones, level) => {
  const out = [];
  for (const zone of zones) {
    const ids = BigUint64Array.of(core.stringToCell(zone));
    for await (const c of cellChunks(core, ids, null, { densify: mapDensify(level), projection: projectionOf() })) {
      out.push({ zone, lnglat: Array.from(c.lnglat), index: Array.from(c.index) });
    }
  }
  return out;
};

// --- The map --------------------------------------------------------------------------------------
const style = {
  version: 8,
  projection: { type: 'globe' },
  sources: {
    graticule: { type: 'geojson', data: graticule() },
    land: { type: 'geojson', data: EMPTY },
    borders: { type: 'geojson', data: EMPTY },
    coastline: { type: 'geojson', data: EMPTY },
    cells: { type: 'geojson', data: EMPTY },
  },
  layers: [
    { id: 'background', type: 'background', paint: { 'background-color': GLOBE_COLOUR } },
    { id: 'land', type: 'fill', source: 'land', paint: { 'fill-color': LAND_COLOUR } },
    {
      id: 'graticule', type: 'line', source: 'graticule',
      paint: { 'line-color': GRATICULE_COLOUR, 'line-width': 1 },
    },
    {
      id: 'borders', type: 'line', source: 'borders',
      paint: { 'line-color': BORDER_COLOUR, 'line-width': 0.7, 'line-dasharray': [3, 2] },
    },
    {
      id: 'coastline', type: 'line', source: 'coastline',
      paint: { 'line-color': COAST_COLOUR, 'line-width': 1 },
    },
    {
      id: 'cells-fill', type: 'fill', source: 'cells',
      paint: { 'fill-color': RAMP[0], 'fill-opacity': 0.8 },
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
  // The view in the URL (#zoom/lat/lng/bearing/pitch, MapLibre's own hash): a link shares it, a reload keeps it.
  hash: true,
});
// A page opened with a view in its URL shows that view, not the data's frame.
const viewInUrl = /^#[-\d.]+\/[-\d.]+\/[-\d.]+/.test(window.location.hash);
window.dggsMap = map;
map.addControl(new NavigationControl({ visualizePitch: true }), 'top-right');

// --- Land ------------------------------------------------------------------------------------------
// The countries' outer edges (arcs of one country only) are the coastline, the shared ones the borders.
// world-atlas leaves Russia and Fiji crossing the antimeridian (a step from +179.9 to -179.9), writes
// some points of its cuts along it as -180 between points near +180, and closes Antarctica along the
// south pole with a step across it: MapLibre would draw those steps across the whole globe. So a ring's
// longitudes are made continuous (MapLibre wraps them back) and Antarctica's is closed again along the
// pole; lines are broken at such steps, at the cuts along the antimeridian and along the pole (no coast).
function unwrap(ring) {
  const pole = ring.some(([, y]) => y < -89.99);
  const line = pole ? ring.filter(([, y]) => y >= -89.99) : ring;
  if (line.length < 3) return ring;
  let shift = 0;
  const out = line.map(([x, y], i) => {
    if (i > 0) shift += 360 * Math.round((line[i - 1][0] - x) / 360);
    return [x + shift, y];
  });
  if (pole) out.push([out[out.length - 1][0], -89.999], [out[0][0], -89.999], out[0]);
  return out;
}

function dropCuts(line) {
  const cut = ([ax, ay], [bx, by]) => (Math.abs(ax) === 180 && Math.abs(bx) === 180) || Math.abs(ax - bx) > 180
    || (ay < -89.99 && by < -89.99);
  const parts = [[line[0]]];
  for (let i = 1; i < line.length; i += 1) {
    if (cut(line[i - 1], line[i])) parts.push([]);
    parts[parts.length - 1].push(line[i]);
  }
  return parts.filter((part) => part.length > 1);
}

// world-atlas writes Antarctica (a polygon holding the south pole) as d3-geo does on the sphere: an outer
// ring along -89.999 degrees all the way round and the coast as its hole. On the plane that is a line with a
// hole, which MapLibre filled only in part. Each such hole is the land's coast: it goes once round the pole,
// so its longitudes unwrap to a 360-degree span; it is closed through the pole (down the meridian at its end,
// along -89.999 back, up at its start) into a plain ring, which MapLibre fills to the pole cap.
const SOUTH = -89.99;
const aroundPole = (rings) => rings.length > 1 && rings[0].every(([, y]) => y < SOUTH);

function closeThroughPole(coast) {
  const open = coast.slice(0, -1); // without the closing point
  let shift = 0;
  const out = open.map(([x, y], i) => {
    if (i > 0) shift += 360 * Math.round((open[i - 1][0] - x) / 360);
    return [x + shift, y];
  });
  const [x0, y0] = out[0];
  const end = x0 + 360 * Math.sign(out[out.length - 1][0] - x0);
  out.push([end, y0], [end, -89.999], [x0, -89.999], [x0, y0]);
  return out;
}

function planar(rings) {
  return aroundPole(rings) ? rings.slice(1).map((coast) => [closeThroughPole(coast)]) : [rings.map(unwrap)];
}

function polygons(feature) {
  const g = feature.geometry;
  const parts = g.type === 'Polygon' ? planar(g.coordinates) : g.coordinates.flatMap(planar);
  return { ...feature, geometry: { type: 'MultiPolygon', coordinates: parts } };
}

// --- Labels ------------------------------------------------------------------------------------------
// MapLibre draws text only with glyph files (one more download to vendor), so the names of the largest
// countries are HTML markers instead, at the centre of each country's largest part, shown while zoomed out
// (LABEL_MAX_ZOOM): world-atlas's `name`s, the LABEL_COUNT largest by area on the sphere.
const LABEL_COUNT = 30;
const LABEL_MAX_ZOOM = 4;
const labels = [];
window.dggsLabels = labels;

// Area and centre of a ring in the cylindrical equal-area projection (x the longitude, unwrapped; y the
// sine of the latitude, in degrees' units), so areas compare as on the sphere.
const DEG = Math.PI / 180;
function ringCentre(ring) {
  let a = 0; let cx = 0; let cy = 0;
  for (let i = 1; i < ring.length; i += 1) {
    const x0 = ring[i - 1][0]; const y0 = Math.sin(ring[i - 1][1] * DEG) / DEG;
    const x1 = ring[i][0]; const y1 = Math.sin(ring[i][1] * DEG) / DEG;
    const cross = x0 * y1 - x1 * y0;
    a += cross; cx += (x0 + x1) * cross; cy += (y0 + y1) * cross;
  }
  if (a === 0) return null;
  return { area: Math.abs(a / 2), lng: wrapLng(cx / (3 * a)), lat: Math.asin(clamp(cy / (3 * a) * DEG, -1, 1)) / DEG };
}

function largestPart(feature) {
  let best = null;
  for (const rings of feature.geometry.coordinates) {
    const c = ringCentre(rings[0]);
    if (c && (!best || c.area > best.area)) best = c;
  }
  return best;
}

function addLabels(features) {
  const parts = features.map((f) => ({ name: f.properties.name, ...largestPart(f) })).filter((p) => p.name && p.area);
  const total = (f) => f.geometry.coordinates.reduce((sum, rings) => sum + (ringCentre(rings[0])?.area || 0), 0);
  const area = new globalThis.Map(features.map((f) => [f.properties.name, total(f)]));
  parts.sort((a, b) => area.get(b.name) - area.get(a.name));
  for (const p of parts.slice(0, LABEL_COUNT)) {
    const el = document.createElement('div');
    el.className = 'country-label';
    el.textContent = p.name;
    labels.push({ name: p.name, lng: p.lng, lat: p.lat, element: el });
    new Marker({ element: el, opacityWhenCovered: '0' }).setLngLat([p.lng, p.lat]).addTo(map); // hidden behind the globe
  }
  showLabels();
}

function showLabels() {
  document.body.classList.toggle('labels-hidden', map.getZoom() > LABEL_MAX_ZOOM);
}

function lines(multiLine) {
  return { type: 'MultiLineString', coordinates: multiLine.coordinates.flatMap(dropCuts) };
}

async function loadGeography() {
  try {
    const [response] = await Promise.all([fetch(COUNTRIES_URL), import(TOPOJSON_URL.href)]);
    if (!response.ok) throw new Error(`${response.status} ${response.statusText}`);
    const topo = await response.json();
    const { feature, mesh } = window.topojson; // the UMD build sets window.topojson
    const countries = topo.objects.countries;
    const land = feature(topo, countries);
    const features = land.features.map(polygons);
    map.getSource('land').setData({ ...land, features });
    addLabels(features);
    map.getSource('coastline').setData(lines(mesh(topo, countries, (a, b) => a === b)));
    map.getSource('borders').setData(lines(mesh(topo, countries, (a, b) => a !== b)));
    state.geography = 'loaded';
  } catch (err) {
    // The map works without land (a wheel built without npm lacks it): say so, no more.
    state.geography = 'missing';
    console.warn('no coastlines:', String(err.message || err));
  }
}

const popup = new Popup({ closeButton: true, closeOnClick: true, maxWidth: '280px' });
popup.on('close', () => {
  state.selected = null;
  if (map.getLayer('cells-selected')) map.setFilter('cells-selected', ['==', ['get', 'zone_id'], '']);
  if (core) cellsLayer.select(core, null);
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
  if (state.collection !== null) params.set('collection', state.collection);
  if (state.column === null) {
    params.set('stat', 'count');
  } else {
    params.set('column', state.column);
    params.set('stat', state.stat);
  }
  return `map/cells?${params}`;
}

// Colour classes for the values in view (sorted, ascending): the lower bounds of classes 2..n.
// quantile: each class holds about as many cells (the default: sums and counts are skewed, and a few
// big cells would otherwise leave all the rest in the palest class); log: bounds in equal ratios
// (offset when values reach 0 or below); linear: equal widths. Log and linear bounds are rounded to two
// significant digits, for a legend one can read.
function classBreaks(sorted, scale) {
  const n = RAMP.length;
  const lo = sorted[0];
  const hi = sorted[sorted.length - 1];
  const shift = lo > 0 ? 0 : 1 - lo; // log of (value + shift), shift making the lowest value 1
  const cuts = [];
  for (let i = 1; i < n; i += 1) {
    if (scale === 'quantile') cuts.push(sorted[Math.floor((i * sorted.length) / n)]);
    else if (scale === 'log') cuts.push(Number(((lo + shift) * ((hi + shift) / (lo + shift)) ** (i / n) - shift).toPrecision(2)));
    else cuts.push(Number((lo + ((hi - lo) * i) / n).toPrecision(2)));
  }
  // Strictly ascending and inside (lo, hi], as MapLibre's 'step' needs and no class left empty by design.
  return cuts.filter((c, i) => c > lo && c <= hi && (i === 0 || c > cuts[i - 1]));
}

// The colour of each class: the whole ramp, spread over fewer classes when there are fewer.
function classColours(count) {
  if (count === 1) return [RAMP[RAMP.length - 1]];
  return Array.from({ length: count }, (_, i) => RAMP[Math.round((i * (RAMP.length - 1)) / (count - 1))]);
}

// Fill colour: a 'step' over the classes; grey where a cell has no value.
function fillColour(breaks, colours) {
  const step = ['step', ['get', 'value'], colours[0]];
  breaks.forEach((b, i) => step.push(b, colours[i + 1]));
  return ['case', ['==', ['typeof', ['get', 'value']], 'number'], breaks.length ? step : colours[0], NO_VALUE_COLOUR];
}

// The legend: one row a class, its colour and its range (the last class ends at the largest value).
function updateLegend(level, min, max, breaks, colours) {
  ui.legendTitle.textContent = valueLabel();
  ui.legendLevel.textContent = `level ${level}`;
  ui.legendSteps.replaceChildren();
  if (min === null) return;
  const bounds = [min, ...breaks, max];
  colours.forEach((colour, i) => {
    const li = document.createElement('li');
    const swatch = document.createElement('span');
    swatch.className = 'swatch';
    swatch.style.background = colour;
    li.dataset.colour = colour;
    li.dataset.from = String(bounds[i]);
    li.dataset.to = String(bounds[i + 1]);
    li.append(swatch, `${formatNumber(bounds[i])} – ${formatNumber(bounds[i + 1])}`);
    ui.legendSteps.append(li);
  });
}

// Draws the cells: `fc` (GeoJSON from the server) or `cells` ({ids, counts, values} from map/cells?f=uint64, drawn
// by the WebGL layer; resolves once its buffers are built, false if a newer refresh came first).
async function render({ fc = null, cells = null }, level, bbox, wanted) {
  if (state.level !== level) { // the clicked cell is gone
    popup.remove();
    if (core) cellsLayer.select(core, null);
  }
  const values = cells
    ? Array.from(cells.values).filter(Number.isFinite)
    : fc.features.map((f) => f.properties.value).filter((v) => typeof v === 'number' && Number.isFinite(v));
  values.sort((a, b) => a - b);
  const min = values.length ? values[0] : null;
  const max = values.length ? values[values.length - 1] : null;
  const breaks = values.length ? classBreaks(values, state.scale) : [];
  const colours = classColours(breaks.length + 1);
  const count = cells ? cells.ids.length : fc.features.length;
  if (cells) {
    const drawn = await cellsLayer.setCells(core, cells.ids, {
      level, densify: mapDensify(level), projection: projectionOf(), values: cells.values, counts: cells.counts,
    });
    if (!drawn) return false;
    cellsLayer.setClasses(breaks, colours);
  } else {
    map.getSource('cells').setData(fc);
    map.setPaintProperty('cells-fill', 'fill-color', fillColour(breaks, colours));
  }
  Object.assign(state, { level, featureCount: count, min, max, breaks, bbox, lastError: null });
  updateLegend(level, min, max, breaks, colours);
  const area = !count ? null : cells ? core.cellArea(level, 'km^2') : fc.features[0].properties.area_km2;
  const areaText = area ? ` · ${formatNumber(Math.round(area))} km² each` : '';
  const coarser = level < wanted ? ` (level ${wanted} has too many cells here)` : '';
  setStatus(`level ${level} · ${count.toLocaleString('en-US')} cells${areaText}${coarser}`);
  return true;
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
  const key = JSON.stringify([state.collection, wanted, bbox, state.column, state.stat, state.scale]);
  if (key === shownKey) {
    // Nothing new to fetch (say, the whole globe turned): the cells on the map stay.
    whenMapIdle(seq, 'idle');
    return;
  }
  try {
    await coreReady;
    if (core && !map.getLayer(cellsLayer.id)) map.addLayer(cellsLayer, 'cells-fill');
    for (;;) {
      const url = cellsUrl(level, bbox);
      const response = await fetch(core ? `${url}&f=uint64` : url, { signal });
      if (seq !== requestSeq) return;
      if (response.status === 413 && level > 0) {
        level -= 1;
        continue;
      }
      if (!response.ok) throw new Error(`cells at level ${level}: ${await readError(response)}`);
      const answer = core ? { cells: cellsFromBody(await response.arrayBuffer()) } : { fc: await response.json() };
      if (seq !== requestSeq) return;
      if (core) setStatus(`drawing ${answer.cells.ids.length.toLocaleString('en-US')} cells…`);
      if (!(await render(answer, level, bbox, wanted)) || seq !== requestSeq) return;
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
  if (core) cellsLayer.select(core, core.stringToCell(p.zone_id));
  else map.setFilter('cells-selected', ['==', ['get', 'zone_id'], p.zone_id]);
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
    const response = await fetch(zonesPath() + encodeURIComponent(p.zone_id), {
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

// Cells drawn from ids: the cell under the pointer is the one latLngToCell gives at the shown level (exact, and
// a binary search among the drawn ids), if it is drawn; off the globe there is none.
function cellAt(e) {
  if (!core || !cellsLayer.cells || !onGlobe(e.point.x, e.point.y)) return null;
  const i = cellsLayer.pick(core, e.lngLat.lng, e.lngLat.lat);
  if (i < 0) return null;
  const { ids, counts, values, level } = cellsLayer.cells;
  const value = values ? values[i] : NaN;
  return {
    properties: {
      zone_id: core.cellToString(ids[i]), level, area_km2: core.cellArea(level, 'km^2'),
      count: counts ? counts[i] : 0, value: Number.isNaN(value) ? null : value,
    },
  };
}
map.on('click', (e) => {
  const cell = cellAt(e);
  if (cell) showCell(cell, e.lngLat);
});
map.on('mousemove', (e) => {
  if (core && cellsLayer.cells) map.getCanvas().style.cursor = cellAt(e) ? 'pointer' : '';
});
map.on('zoom', showLabels);

// --- Controls -------------------------------------------------------------------------------------
function readControls() {
  state.column = ui.column.value === '' ? null : ui.column.value;
  ui.stat.disabled = state.column === null;
  state.stat = state.column === null ? 'count' : ui.stat.value;
  state.scale = ui.scale.value;
}

function setUpControls() {
  ui.column.innerHTML = '';
  ui.column.add(new Option('count (rows)', ''));
  for (const name of layers.numeric_columns) ui.column.add(new Option(name, name));
  ui.level.innerHTML = '';
  ui.level.add(new Option('auto (from zoom)', 'auto', true, true));
  for (const level of layers.levels) ui.level.add(new Option(String(level), String(level)));
  if (!controlsWired) {
    controlsWired = true;
    for (const select of [ui.column, ui.stat, ui.level, ui.scale]) {
      select.addEventListener('change', () => {
        readControls();
        refresh();
      });
    }
    setUpDatasets();
  }
  readControls();
  const rows = Number(layers.count).toLocaleString('en-US');
  ui.subtitle.textContent = `${layers.collection}: ${rows} rows at level ${layers.stored_level}`;
}

// The dataset picker: shown when the store has more than one (map/layers' collections, the default first).
function setUpDatasets() {
  const ids = layers.collections || [layers.collection];
  ui.collection.innerHTML = '';
  for (const id of ids) ui.collection.add(new Option(id, id, id === ids[0], id === ids[0]));
  ui.collectionField.hidden = ids.length < 2;
  ui.collection.addEventListener('change', async () => {
    state.collection = ui.collection.value === ids[0] ? null : ui.collection.value;
    state.selected = null;
    popup.remove();
    if (await loadLayers()) {
      setUpControls();
      refresh();
    }
  });
}

// GET map/layers of the dataset shown; false (with the error shown) if it fails.
async function loadLayers() {
  try {
    const response = await fetch(layersUrl(), { headers: { Accept: 'application/json' } });
    if (!response.ok) throw new Error(`map/layers: ${await readError(response)}`);
    layers = await response.json();
    return true;
  } catch (err) {
    state.lastError = String(err.message || err);
    state.loading = false;
    setStatus(state.lastError, true);
    setBodyState('error');
    return false;
  }
}

// Frame the data: the whole globe around the data's centre, or the data's bbox when it is small.
function frameData() {
  if (viewInUrl) return;
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
  if (!(await loadLayers())) return;
  setUpControls();
  loadGeography();
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
