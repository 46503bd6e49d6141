// dggs for JavaScript: the grid's C core (libdggs) compiled to WebAssembly (dist/dggs.wasm, `make wasm`), with
// its verbs in JS's naming. Thin: every answer is the C core's; this file converts ids and copies arrays.
//
//   import * as dggs from "dggs";
//   await dggs.init();                      // loads dist/dggs.wasm (node: from disk; browser: fetch)
//   dggs.latLngToCell(48.85, 2.35, 10);     // "C4011120210"
//   dggs.latLngToCell(48.85, 2.35, 10, { asBigInt: true, projection: "IVEA" });
//
// Ids are strings ("C401") or BigInts (the 64-bit integer ids); a verb answers in the kind it was given.
// Batches take and give typed arrays: Float64Array latitudes and longitudes, BigUint64Array ids.

const PROJECTIONS = { ISEA: 0, IVEA: 1 };
const FILL_MODES = { center: 0, contains: 1, overlaps: 2, overlapping_bbox: 3 };
const ERRORS = [
  "OK", "E_LATLNG", "E_LEVEL", "E_CELL", "E_LEVEL_MISMATCH", "E_BUFFER", "E_DOMAIN", "E_FAILED",
  "E_PROJECTION", "E_EDGE", "E_VERTEX",
];
export const MAX_LEVEL = 28;
/** Most cells a verb builds unless told otherwise (its `maxCells` option). */
export const MAX_CELLS = 10_000_000;
// The WGS84 ellipsoid's area in m^2 (dggs.geometry.authalic.WGS84.area): 4 pi R'^2 of the authalic radius.
const WGS84_AREA = 510065621724088.44;
const UNITS = { "m^2": WGS84_AREA, "km^2": WGS84_AREA * 1e-6, "rads^2": 4 * Math.PI };

/** An error of the C core (`code` its dggs_error, `errorName` e.g. "E_CELL") or of an argument. */
export class DggsError extends Error {
  constructor(message, code = 6) {
    super(message);
    this.name = "DggsError";
    this.code = code;
    this.errorName = ERRORS[code] ?? "E_UNKNOWN";
  }
}

let W = null; // the instance's exports
let buf = null; // the memory's ArrayBuffer the views below are of (replaced when memory grows)
let U8, F64, U64, I64;
let scratch = 0; // SCRATCH bytes of malloc'ed memory for single calls
const SCRATCH = 4096;

function views() {
  if (buf !== W.memory.buffer) {
    buf = W.memory.buffer;
    U8 = new Uint8Array(buf);
    F64 = new Float64Array(buf);
    U64 = new BigUint64Array(buf);
    I64 = new BigInt64Array(buf);
  }
}

/**
 * Load the WebAssembly module. `source`: nothing (dist/dggs.wasm beside this package), a URL or path, bytes
 * (ArrayBuffer, typed array), a Response or a WebAssembly.Module. Resolves to this module's namespace.
 */
export async function init(source) {
  if (W && source === undefined) return api;
  let mod;
  if (source instanceof WebAssembly.Module) mod = source;
  else {
    if (source === undefined) source = new URL("../dist/dggs.wasm", import.meta.url);
    let bytes = source;
    const isNode = typeof process !== "undefined" && process.versions?.node;
    if (typeof source === "string" || source instanceof URL) {
      const url = source instanceof URL ? source : new URL(source, isNode ? `file://${process.cwd()}/` : location.href);
      if (isNode && url.protocol === "file:") {
        const { readFile } = await import("node:fs/promises");
        bytes = await readFile(url);
      } else bytes = await fetch(url);
    }
    if (typeof Response !== "undefined" && bytes instanceof Response) {
      mod = WebAssembly.compileStreaming
        ? await WebAssembly.compileStreaming(bytes).catch(async () => WebAssembly.compile(await bytes.arrayBuffer()))
        : await WebAssembly.compile(await bytes.arrayBuffer());
    } else mod = await WebAssembly.compile(bytes);
  }
  const instance = await WebAssembly.instantiate(mod, {});
  W = instance.exports;
  W._initialize?.();
  buf = null;
  scratch = W.malloc(SCRATCH);
  views();
  return api;
}

const rdI64 = (ptr) => (views(), Number(I64[ptr >> 3]));
const rdU64 = (ptr) => (views(), U64[ptr >> 3]);

function core() {
  if (!W) throw new DggsError("dggs: call `await init()` before using the grid");
  views();
  return W;
}

// Throw a DggsError for an error code; `what` is a function giving the message's start (built only then).
function check(err, what) {
  if (err !== 0) {
    const ptr = W.dggs_error_string(err);
    views();
    let end = ptr;
    while (U8[end]) end++;
    throw new DggsError(`${typeof what === "function" ? what() : what}: ${String.fromCharCode(...U8.subarray(ptr, end))}`, err);
  }
}

function projection(opts) {
  const p = opts?.projection;
  if (p === undefined || p === "ISEA") return 0;
  if (p === "IVEA") return 1;
  const v = PROJECTIONS[typeof p === "string" ? p.toUpperCase() : p];
  if (v === undefined) throw new DggsError(`projection ${JSON.stringify(p)} is not ISEA or IVEA`, 8);
  return v;
}

// Any argument in a message: Symbols, BigInts and objects too (a template string throws on a Symbol).
function show(v) {
  if (typeof v === "string") return JSON.stringify(v.length > 80 ? `${v.slice(0, 80)}...` : v);
  if (typeof v === "bigint") return `${v}n`;
  if (typeof v === "symbol" || typeof v === "function") return v.toString().slice(0, 80);
  if (v === null || typeof v !== "object") return String(v);
  try {
    return (JSON.stringify(v) ?? Object.prototype.toString.call(v)).slice(0, 80);
  } catch {
    return Object.prototype.toString.call(v);
  }
}

function intArg(v, name, lo, hi) {
  if (!Number.isInteger(v) || v < lo || v > hi) throw new DggsError(`${name} ${show(v)} is not an integer ${lo}..${hi}`, name === "level" ? 2 : 6);
  return v;
}

const levelArg = (v) => intArg(v, "level", 0, MAX_LEVEL);

// A coordinate: a number (NaN and infinities go to the core, which names them); anything else is refused here,
// as a BigInt or a Symbol would throw a TypeError on its way into WebAssembly.
function numArg(v, name) {
  if (typeof v !== "number") throw new DggsError(`${name} ${show(v)} is not a number`, 1);
  return v;
}

// An array of numbers or a Float64Array (each element checked as numArg).
function numbersArg(v, name) {
  if (v instanceof Float64Array) return v;
  if (!Array.isArray(v)) throw new DggsError(`${name} ${show(v)} is not an array of numbers or a Float64Array`, 1);
  for (let i = 0; i < v.length; i++) numArg(v[i], `${name}[${i}]`);
  return v;
}

// ---- ids ----------------------------------------------------------------------------------------

/** The 64-bit id (BigInt) of a string id or BigInt id (checked). */
export function stringToCell(s) {
  const w = core();
  if (typeof s !== "string") throw new DggsError(`${show(s)} is not a string id`, 3);
  if (s.length > 64) throw new DggsError(`${JSON.stringify(s.slice(0, 40))}... is not a cell id`, 3);
  for (let i = 0; i < s.length; i++) U8[scratch + 8 + i] = s.charCodeAt(i) & 0xff;
  U8[scratch + 8 + s.length] = 0;
  for (let i = 0; i < s.length; i++) if (s.charCodeAt(i) > 0x7f || s.charCodeAt(i) === 0) U8[scratch + 8] = 0x21;
  check(w.dggs_string_to_cell(scratch + 8, scratch), () => `${JSON.stringify(s)} is not a cell id`);
  return rdU64(scratch);
}

/** The string id of a BigInt id (checked). */
export function cellToString(cell) {
  const w = core();
  const id = toBig(cell);
  check(w.dggs_cell_to_string(BigInt.asIntN(64, id), scratch, 32), () => `${show(cell)} is not a cell id`);
  let end = scratch;
  while (U8[end]) end++;
  return String.fromCharCode(...U8.subarray(scratch, end));
}

function toBig(cell) {
  if (typeof cell === "string") return stringToCell(cell);
  if (typeof cell === "bigint") {
    if (cell < 0n || cell >= 1n << 64n || !W.dggs_is_valid_cell(cell)) throw new DggsError(`${show(cell)} is not a cell id`, 3);
    return cell;
  }
  throw new DggsError(`${show(cell)} is not a cell id (a string or a BigInt)`, 3);
}

const big = (v) => BigInt.asUintN(64, v);
const like = (given, cell) => (typeof given === "string" ? cellToString(cell) : cell);

/** Whether `cell` (a string or BigInt) is a cell id. Never throws. */
export function isValidCell(cell) {
  const w = core();
  if (typeof cell === "bigint") return cell >= 0n && cell < 1n << 64n && w.dggs_is_valid_cell(cell) === 1;
  if (typeof cell !== "string") return false;
  try {
    stringToCell(cell);
    return true;
  } catch {
    return false;
  }
}

/** The level 0..28 of a cell. */
export function getLevel(cell) {
  return core().dggs_get_level(toBig(cell));
}

/** The face 0..19 (level-0 ancestor) of a cell. */
export function getFace(cell) {
  return core().dggs_get_face(toBig(cell));
}

/** Area of a cell, or of every cell of a level (a number 0..28): the WGS84 area over the level's cell count. */
export function cellArea(cellOrLevel, unit = "m^2") {
  const total = UNITS[unit];
  if (total === undefined) throw new DggsError(`unit ${JSON.stringify(unit)} is not one of m^2, km^2, rads^2`);
  const level = typeof cellOrLevel === "number" ? intArg(cellOrLevel, "level", 0, MAX_LEVEL) : getLevel(cellOrLevel);
  return total / (level === 0 ? 20 : 120 * 3 ** (level - 1));
}

/** The number of cells at a level. */
export function getNumCells(level) {
  levelArg(level);
  return level === 0 ? 20 : 120 * 3 ** (level - 1);
}

// ---- points -------------------------------------------------------------------------------------

/** The cell of `level` holding the point (WGS84 degrees): a string id, or a BigInt with `{ asBigInt: true }`. */
export function latLngToCell(lat, lng, level, opts) {
  const w = core();
  numArg(lat, "lat");
  numArg(lng, "lng");
  levelArg(level);
  check(w.dggs_latlng_to_cell(lat, lng, level, projection(opts), scratch), () => `point (${lat}, ${lng}) at level ${level}`);
  const cell = rdU64(scratch);
  return opts?.asBigInt ? cell : cellToString(cell);
}

/** The centre of a cell as [lat, lng] degrees. */
export function cellToLatLng(cell, opts) {
  const w = core();
  check(w.dggs_cell_to_latlng(toBig(cell), projection(opts), scratch, scratch + 8), () => `cell ${cell}`);
  return [F64[scratch >> 3], F64[(scratch >> 3) + 1]];
}

/**
 * The boundary of a cell: its 3 corners counter-clockwise seen from outside, each followed by `densify` points
 * along its edge, as [lat, lng] pairs (not closed).
 */
export function cellToBoundary(cell, opts) {
  const w = core();
  const densify = intArg(opts?.densify ?? 0, "densify", 0, 100000);
  const n = 3 * (densify + 1);
  const id = toBig(cell);
  const ptr = n * 16 <= SCRATCH - 16 ? scratch + 16 : w.malloc(n * 16);
  try {
    check(w.dggs_cell_to_boundary(id, densify, projection(opts), ptr, n, scratch), () => `cell ${cell}`);
    views();
    const out = new Array(n);
    for (let i = 0, p = ptr >> 3; i < n; i++, p += 2) out[i] = [F64[p], F64[p + 1]];
    return out;
  } finally {
    if (ptr !== scratch + 16) w.free(ptr);
  }
}

// ---- batches: typed arrays in and out -----------------------------------------------------------

function withHeap(bytes, fn) {
  const w = core();
  const ptr = w.malloc(Math.max(bytes, 8));
  if (!ptr) throw new DggsError(`out of memory (${bytes} bytes)`, 7);
  try {
    return fn(ptr);
  } finally {
    w.free(ptr);
  }
}

function toIds(cells) {
  if (cells instanceof BigUint64Array) return cells;
  if (!Array.isArray(cells)) throw new DggsError(`${show(cells)} is not an array of ids or a BigUint64Array`, 3);
  const out = new BigUint64Array(cells.length);
  for (let i = 0; i < cells.length; i++) out[i] = toBig(cells[i]);
  return out;
}

/** The cells of `level` holding points lat[i], lng[i] (Float64Array or arrays of numbers): a BigUint64Array. */
export function latLngToCells(lat, lng, level, opts) {
  numbersArg(lat, "lat");
  numbersArg(lng, "lng");
  const n = lat.length;
  if (lng.length !== n) throw new DggsError(`lat and lng differ in length (${n}, ${lng.length})`);
  const proj = projection(opts);
  intArg(level, "level", 0, MAX_LEVEL);
  return withHeap(24 * n, (ptr) => {
    const la = ptr, ln = ptr + 8 * n, out = ptr + 16 * n;
    views();
    F64.set(lat, la >> 3);
    F64.set(lng, ln >> 3);
    const bad = W.dggsjs_latlng_to_cells(la, ln, n, level, proj, out);
    views();
    if (bad >= 0) check(W.dggs_latlng_to_cell(lat[bad], lng[bad], level, proj, ptr), () => `point ${bad} (${lat[bad]}, ${lng[bad]})`);
    return U64.slice(out >> 3, (out >> 3) + n);
  });
}

/** The centres of cells (a BigUint64Array or an array of ids) as a Float64Array of n (lat, lng) pairs. */
export function cellsToLatLngs(cells, opts) {
  const ids = toIds(cells);
  const n = ids.length;
  const proj = projection(opts);
  return withHeap(24 * n, (ptr) => {
    views();
    U64.set(ids, ptr >> 3);
    const out = ptr + 8 * n;
    const bad = W.dggsjs_cells_to_latlngs(ptr, n, proj, out);
    views();
    if (bad >= 0) throw new DggsError(`cell ${bad} (${ids[bad]}) is not a cell id`, 3);
    return F64.slice(out >> 3, (out >> 3) + 2 * n);
  });
}

/**
 * The boundaries of cells (a BigUint64Array or an array of ids) as one Float64Array: cell i's 3 (densify + 1)
 * (lat, lng) pairs at 6 (densify + 1) i.
 */
export function cellsToBoundaries(cells, opts) {
  const ids = toIds(cells);
  const n = ids.length;
  const densify = intArg(opts?.densify ?? 0, "densify", 0, 100000);
  const proj = projection(opts);
  const per = 6 * (densify + 1);
  return withHeap(8 * n + 8 * per * n, (ptr) => {
    views();
    U64.set(ids, ptr >> 3);
    const out = ptr + 8 * n;
    const bad = W.dggsjs_cells_to_boundaries(ptr, n, densify, proj, out);
    views();
    if (bad >= 0) throw new DggsError(`cell ${bad} (${ids[bad]}) is not a cell id`, 3);
    return F64.slice(out >> 3, (out >> 3) + per * n);
  });
}

// ---- hierarchy ----------------------------------------------------------------------------------

/** The ancestor of a cell at `level` (default: one level up). */
export function cellToParent(cell, level) {
  const w = core();
  const id = toBig(cell);
  const lv = level === undefined ? w.dggs_get_level(id) - 1 : levelArg(level);
  check(w.dggs_cell_to_parent(id, lv, scratch), () => `parent of ${cell} at level ${lv}`);
  return like(cell, rdU64(scratch));
}

/** The descendant of a cell at `level` (default: one level down) holding its centre. */
export function cellToCenterChild(cell, level) {
  const w = core();
  const id = toBig(cell);
  const lv = level === undefined ? w.dggs_get_level(id) + 1 : levelArg(level);
  check(w.dggs_cell_to_center_child(id, lv, scratch), () => `centre child of ${cell} at level ${lv}`);
  return like(cell, rdU64(scratch));
}

// An array of ids out, in the kind of `given`: strings for a string, BigInts for a BigInt, a BigUint64Array
// for a typed array.
function idsOut(given, ptr, n) {
  views();
  const ids = U64.slice(ptr >> 3, (ptr >> 3) + n);
  if (given instanceof BigUint64Array) return ids;
  const asString = typeof given === "string";
  const out = new Array(n);
  for (let i = 0; i < n; i++) out[i] = asString ? cellToString(ids[i]) : ids[i];
  return out;
}

function maxCells(opts) {
  return opts?.maxCells ?? MAX_CELLS;
}

/** The descendants of a cell at `level` (default: one level down), in id order. */
export function cellToChildren(cell, level, opts) {
  const w = core();
  const id = toBig(cell);
  const lv = level === undefined ? w.dggs_get_level(id) + 1 : levelArg(level);
  check(w.dggs_cell_to_children_size(id, lv, scratch), () => `children of ${cell} at level ${lv}`);
  const n = rdI64(scratch);
  if (n > maxCells(opts)) throw new DggsError(`${n} children of ${cell} at level ${lv} exceed maxCells ${maxCells(opts)}`, 6);
  return withHeap(8 * n, (ptr) => {
    check(w.dggs_cell_to_children(id, lv, ptr, BigInt(n)), () => `children of ${cell}`);
    return idsOut(cell, ptr, n);
  });
}

function idsIn(cells) {
  const ids = toIds(cells);
  const kind = cells instanceof BigUint64Array ? cells : cells.length && typeof cells[0] === "string" ? "" : 0n;
  return [ids, kind];
}

/** The fewest cells covering the area of `cells` (any levels, duplicates allowed), sorted. */
export function compactCells(cells) {
  const w = core();
  const [ids, kind] = idsIn(cells);
  const n = ids.length;
  check(w.dggs_compact_cells_size(BigInt(n), scratch), "compactCells");
  const size = rdI64(scratch);
  return withHeap(8 * n + 8 * size, (ptr) => {
    views();
    U64.set(ids, ptr >> 3);
    const out = ptr + 8 * n;
    check(w.dggs_compact_cells(ptr, BigInt(n), out, BigInt(size), scratch), "compactCells");
    return idsOut(kind, out, rdI64(scratch));
  });
}

/** All descendants at `level` of the area `cells` cover, sorted and unique. */
export function uncompactCells(cells, level, opts) {
  const w = core();
  const [ids, kind] = idsIn(cells);
  const n = ids.length;
  levelArg(level);
  return withHeap(8 * n, (inp) => {
    views();
    U64.set(ids, inp >> 3);
    check(w.dggs_uncompact_cells_size(inp, BigInt(n), level, scratch), () => `uncompactCells to level ${level}`);
    const size = rdI64(scratch);
    if (size > Math.max(maxCells(opts), 3 * n + 20480)) throw new DggsError(`uncompactCells: ${size} cells exceed maxCells ${maxCells(opts)}`, 6);
    return withHeap(8 * size, (out) => {
      check(w.dggs_uncompact_cells(inp, BigInt(n), level, out, BigInt(size), scratch), "uncompactCells");
      return idsOut(kind, out, rdI64(scratch));
    });
  });
}

// ---- neighbours -----------------------------------------------------------------------------------

function sizedSearch(name, cell, k, opts) {
  const w = core();
  const id = toBig(cell);
  if (!Number.isInteger(k) || k < 0) throw new DggsError(`k ${show(k)} is not a non-negative integer`, 6);
  check(w[`dggs_${name}_size`](id, BigInt(k), scratch), () => `${name} of ${cell}`);
  const size = rdI64(scratch);
  if (size > 4 * maxCells(opts)) throw new DggsError(`${name} of ${cell} with k ${k}: over maxCells ${maxCells(opts)}`, 6);
  return withHeap(8 * size, (ptr) => {
    check(w[`dggs_${name}`](id, BigInt(k), ptr, BigInt(size), scratch), () => `${name} of ${cell}`);
    return idsOut(cell, ptr, rdI64(scratch));
  });
}

/** The cells within k edge steps of a cell (the cell included), sorted by id. */
export function gridDisk(cell, k = 1, opts) {
  return sizedSearch("grid_disk", cell, k, opts);
}

/** The cells exactly k edge steps from a cell, sorted by id. */
export function gridRing(cell, k = 1, opts) {
  return sizedSearch("grid_ring", cell, k, opts);
}

/** The three cells sharing an edge with a cell (across its edges from corner i to i + 1). */
export function edgeNeighbors(cell) {
  const w = core();
  check(w.dggs_edge_neighbors(toBig(cell), scratch), () => `cell ${cell}`);
  return idsOut(cell, scratch, 3);
}

/** The number of edge steps between two cells of one level. */
export function gridDistance(a, b) {
  const w = core();
  check(w.dggs_grid_distance(toBig(a), toBig(b), scratch), () => `distance from ${a} to ${b}`);
  return rdI64(scratch);
}

// ---- polygons -----------------------------------------------------------------------------------

/**
 * The cells of `level` of a polygon: `polygon` is an array of rings (the shell, then holes; several shells for
 * a multipolygon), each an array of [lat, lng] points ([lng, lat] with `{ geoJson: true }`), longitudes in
 * -180..180. `mode`: "center" (default), "contains", "overlaps" or "overlapping_bbox". Sorted ids: strings, or
 * a BigUint64Array with `{ asBigInt: true }`.
 */
export function polygonToCells(polygon, level, opts) {
  const w = core();
  const mode = FILL_MODES[opts?.mode ?? "center"];
  if (mode === undefined) throw new DggsError(`mode ${JSON.stringify(opts.mode)} is not one of ${Object.keys(FILL_MODES)}`);
  const proj = projection(opts);
  levelArg(level);
  const rings = polygon;
  if (!Array.isArray(rings)) throw new DggsError(`polygon ${show(polygon)} is not an array of rings`, 6);
  rings.forEach((ring, k) => {
    if (!Array.isArray(ring)) throw new DggsError(`ring ${k} ${show(ring)} is not an array of points`, 6);
    ring.forEach((pt, i) => {
      if (!Array.isArray(pt) || pt.length < 2) throw new DggsError(`point ${i} of ring ${k} ${show(pt)} is not a pair of numbers`, 6);
      numArg(pt[0], `point ${i} of ring ${k}: coordinate`);
      numArg(pt[1], `point ${i} of ring ${k}: coordinate`);
    });
  });
  const points = rings.reduce((s, r) => s + r.length, 0);
  const [a, b] = opts?.geoJson ? [1, 0] : [0, 1];
  return withHeap(16 * points + 8 * rings.length + 8, (ptr) => {
    views();
    const sizes = ptr + 16 * points;
    let p = ptr >> 3;
    rings.forEach((ring, k) => {
      I64[(sizes >> 3) + k] = BigInt(ring.length);
      for (const pt of ring) {
        F64[p++] = pt[a];
        F64[p++] = pt[b];
      }
    });
    check(w.dggs_polygon_to_cells_size(ptr, sizes, BigInt(rings.length), level, mode, proj, scratch), "polygonToCells");
    let size = rdI64(scratch);
    if (size > 4 * maxCells(opts)) throw new DggsError(`polygonToCells: up to ${size} cells, over maxCells ${maxCells(opts)}`, 6);
    for (;;) {
      const out = w.malloc(Math.max(8 * size, 8));
      try {
        const err = w.dggs_polygon_to_cells(ptr, sizes, BigInt(rings.length), level, mode, proj, out, BigInt(size), scratch);
        views();
        const count = rdI64(scratch);
        if (err === 5 && count > size) {
          size = count;
          continue;
        }
        check(err, "polygonToCells");
        return idsOut(opts?.asBigInt ? new BigUint64Array(0) : "", out, count);
      } finally {
        w.free(out);
      }
    }
  });
}

const api = {
  init, DggsError, MAX_LEVEL, MAX_CELLS, stringToCell, cellToString, isValidCell, getLevel, getFace, cellArea,
  getNumCells, latLngToCell, cellToLatLng, cellToBoundary, latLngToCells, cellsToLatLngs, cellsToBoundaries,
  cellToParent, cellToCenterChild, cellToChildren, compactCells, uncompactCells, gridDisk, gridRing, edgeNeighbors,
  gridDistance, polygonToCells,
};
