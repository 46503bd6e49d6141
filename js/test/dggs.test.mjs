// The JS package against the Python package: fixtures written by js/tools/write_fixtures.py into
// $DGGS_JS_FIXTURES (default build/js-fixtures at the repository's root). Ids must be equal, centres and
// boundaries within 1e-12 degrees. Run: make test-js (or node --test js/test/dggs.test.mjs after both).
import assert from "node:assert/strict";
import { readFileSync } from "node:fs";
import { test } from "node:test";

import * as dggs from "../src/dggs.js";

const dir = process.env.DGGS_JS_FIXTURES ?? new URL("../../build/js-fixtures/", import.meta.url).pathname;
const fx = JSON.parse(readFileSync(`${dir}/fixtures.json`, "utf8"));
await dggs.init();

const TOL = 1e-12;
const PROJECTIONS = ["ISEA", "IVEA"];

// Points within 1e-12 degrees: latitude, and longitude as arc on the sphere (times cos(lat): at a pole a
// longitude is any, and beside one an ulp of atan2 moves it by up to 1e-12 / cos(lat) degrees).
let worst = { lat: 0, lng: 0, arc: 0 };
function near(got, want, what) {
  assert.equal(got.length, want.length, `${what}: ${got.length} points, want ${want.length}`);
  for (let i = 0; i < want.length; i++) {
    const dlat = Math.abs(got[i][0] - want[i][0]);
    let dlng = Math.abs(got[i][1] - want[i][1]);
    dlng = Math.min(dlng, Math.abs(dlng - 360)); // -180 and 180 are one meridian
    const arc = dlng * Math.cos((want[i][0] * Math.PI) / 180);
    worst = { lat: Math.max(worst.lat, dlat), lng: Math.max(worst.lng, dlng), arc: Math.max(worst.arc, arc) };
    if (!(dlat <= TOL && arc <= TOL)) assert.fail(`${what}, point ${i}: (${got[i]}) vs Python's (${want[i]})`);
  }
}

// The id of point i at a level: Python's, exactly, also for a point on an edge or corner of its cell (L.ties),
// where the tie rules decide by the last bit of sin, cos, atan2, hypot and asin: both builds carry the core's own
// (libdggs/src/dmath.c, issue 34) instead of their platform's libm (glibc's natively, musl's in wasi-libc), so
// they round alike there.
function sameCell(got, L, i, what) {
  assert.equal(got, L.cells[i], L.ties[i] ? `${what} (a tie of ${L.ties[i]})` : what);
}

const pairs = (flat) => Array.from({ length: flat.length / 2 }, (_, i) => [flat[2 * i], flat[2 * i + 1]]);
const lat = Float64Array.from(fx.points, (p) => p[0]);
const lng = Float64Array.from(fx.points, (p) => p[1]);

for (const proj of PROJECTIONS) {
  const P = fx.projections[proj];
  const opts = { projection: proj };
  for (const L of Object.values(P.levels)) L.proj = proj;

  test(`${proj}: latLngToCell equals Python at every level, as strings and BigInts`, () => {
    for (const [level, L] of Object.entries(P.levels)) {
      fx.points.forEach(([a, b, name], i) => {
        const got = dggs.latLngToCell(a, b, Number(level), opts);
        sameCell(got, L, i, `${name} ${i} (${a}, ${b}) level ${level}`);
        assert.equal(dggs.latLngToCell(a, b, Number(level), { ...opts, asBigInt: true }), dggs.stringToCell(got));
      });
    }
  });

  test(`${proj}: latLngToCells (typed arrays) equals Python at every level`, () => {
    for (const [level, L] of Object.entries(P.levels)) {
      const got = dggs.latLngToCells(lat, lng, Number(level), opts);
      assert.ok(got instanceof BigUint64Array);
      got.forEach((id, i) => sameCell(dggs.cellToString(id), L, i, `point ${i} level ${level}`));
      assert.deepEqual(Array.from(got, String), L.ints);
    }
  });

  test(`${proj}: centres and corners within 1e-12 degrees of Python's`, () => {
    for (const [level, L] of Object.entries(P.levels)) {
      L.unique.forEach((cell, i) => {
        near([dggs.cellToLatLng(cell, opts)], [L.centres[i]], `centre of ${cell}`);
        near(dggs.cellToBoundary(cell, opts), pairs(L.boundaries[i]), `boundary of ${cell}`);
      });
      const ids = BigUint64Array.from(L.unique, (c) => dggs.stringToCell(c));
      near(pairs(dggs.cellsToLatLngs(ids, opts)), L.centres, `centres at level ${level}`);
      near(pairs(dggs.cellsToBoundaries(ids, opts)), L.boundaries.flatMap(pairs), `boundaries at level ${level}`);
    }
  });

  test(`${proj}: densified boundaries within 1e-12 degrees`, () => {
    for (const { cell, densify, boundary } of P.dense) {
      near(dggs.cellToBoundary(cell, { ...opts, densify }), boundary, `${cell} densify ${densify}`);
      near(dggs.cellToBoundary(dggs.stringToCell(cell), { ...opts, densify }), boundary, `${cell} as BigInt`);
    }
  });

  test(`${proj}: polygonToCells equals Python in every mode`, () => {
    for (const { name, rings, level, mode, cells } of P.polygons) {
      const got = dggs.polygonToCells(rings, level, { ...opts, mode, geoJson: true });
      assert.deepEqual(got, cells, `${name} level ${level} ${mode}`);
      const latFirst = rings.map((r) => r.map(([x, y]) => [y, x]));
      const ids = dggs.polygonToCells(latFirst, level, { ...opts, mode, asBigInt: true });
      assert.deepEqual(Array.from(ids, dggs.cellToString), cells, `${name} as BigInts`);
    }
  });
}

test("ties: every point on an edge or corner of its cell gets Python's cell, on both projections", (t) => {
  // On main's build (musl's libm in WebAssembly) 755 of these point-levels got another of the cells meeting there.
  let n = 0;
  for (const proj of PROJECTIONS) {
    for (const [level, L] of Object.entries(fx.projections[proj].levels)) {
      const idx = Object.keys(L.ties).map(Number);
      const got = dggs.latLngToCells(Float64Array.from(idx, (i) => lat[i]), Float64Array.from(idx, (i) => lng[i]),
        Number(level), { projection: proj });
      idx.forEach((i, k) => assert.equal(dggs.cellToString(got[k]), L.cells[i], `${proj} tie ${i} level ${level}`));
      n += idx.length;
    }
  }
  assert.ok(n > 7000, `${n} ties in the fixtures`);
  t.diagnostic(`points on an edge or corner of their cell (of ${2 * 29 * fx.points.length}): ${n}, all with Python's cell`);
  t.diagnostic(`largest differences from Python's centres and boundaries: latitude ${worst.lat}, longitude ${worst.lng} degrees (${worst.arc} as arc)`);
});

test("bulk: 100,000 random points at levels 17 and 28 on both projections, equal ids", () => {
  const b = readFileSync(`${dir}/bulk.bin`);
  const n = b.byteLength / 8 / 6;
  const f = new Float64Array(b.buffer, b.byteOffset, 2 * n);
  const la = f.subarray(0, n);
  const ln = f.subarray(n, 2 * n);
  let col = 2;
  for (const proj of PROJECTIONS) {
    for (const level of [17, 28]) {
      const want = new BigUint64Array(b.buffer, b.byteOffset + col++ * 8 * n, n);
      const got = dggs.latLngToCells(la, ln, level, { projection: proj });
      let bad = 0;
      for (let i = 0; i < n; i++) if (got[i] !== want[i]) bad++;
      assert.equal(bad, 0, `${proj} level ${level}: ${bad} of ${n} ids differ`);
    }
  }
});

test("parents, children, disks and rings equal Python's, as strings and BigInts", () => {
  const T = fx.topology;
  const big = (c) => dggs.stringToCell(c);
  for (const { cell, level, parent } of T.parents) {
    assert.equal(dggs.cellToParent(cell, level), parent);
    assert.equal(dggs.cellToParent(big(cell), level), big(parent));
    if (level === dggs.getLevel(cell) - 1) assert.equal(dggs.cellToParent(cell), parent);
  }
  for (const { cell, level, children } of T.children) {
    assert.deepEqual(dggs.cellToChildren(cell, level), children);
    assert.deepEqual(dggs.cellToChildren(big(cell), level), children.map(big));
  }
  for (const { cell, k, cells } of T.disks) {
    assert.deepEqual(dggs.gridDisk(cell, k), cells, `disk ${cell} k ${k}`);
    assert.deepEqual(dggs.gridDisk(big(cell), k), cells.map(big));
  }
  for (const { cell, k, cells } of T.rings) assert.deepEqual(dggs.gridRing(cell, k), cells, `ring ${cell}`);
});

test("compactCells and uncompactCells equal Python's", () => {
  for (const { cells, compact, level, uncompact } of fx.topology.compact) {
    assert.deepEqual(dggs.compactCells(cells), compact);
    assert.deepEqual(dggs.uncompactCells(compact, level), uncompact);
    const ids = BigUint64Array.from(cells, (c) => dggs.stringToCell(c));
    assert.deepEqual(Array.from(dggs.compactCells(ids), dggs.cellToString), compact);
    const back = dggs.uncompactCells(BigUint64Array.from(compact, (c) => dggs.stringToCell(c)), level);
    assert.ok(back instanceof BigUint64Array);
    assert.deepEqual(Array.from(back, dggs.cellToString), uncompact);
  }
});

test("isValidCell, string and integer ids, areas", () => {
  for (const [s, ok] of fx.valid.strings) {
    assert.equal(dggs.isValidCell(s), ok, JSON.stringify(s));
    if (ok) assert.equal(dggs.cellToString(dggs.stringToCell(s)), s);
    else assert.throws(() => dggs.stringToCell(s), dggs.DggsError);
  }
  for (const [s, ok] of fx.valid.ints) assert.equal(dggs.isValidCell(BigInt(s)), ok, s);
  assert.equal(dggs.isValidCell(-1n), false);
  assert.equal(dggs.isValidCell(1n << 64n), false);
  assert.equal(dggs.isValidCell(17), false);
  for (const [unit, areas] of Object.entries(fx.areas)) {
    areas.forEach((area, level) => {
      assert.equal(dggs.cellArea(level, unit), area, `level ${level} ${unit}`);
    });
  }
  const cell = fx.projections.ISEA.levels["9"].cells[0];
  assert.equal(dggs.cellArea(cell), fx.areas["m^2"][9]);
  assert.equal(dggs.cellArea(dggs.stringToCell(cell), "km^2"), fx.areas["km^2"][9]);
});

test("errors: typed, with the core's code", () => {
  const code = (fn) => {
    try {
      fn();
    } catch (e) {
      assert.ok(e instanceof dggs.DggsError, String(e));
      return e.errorName;
    }
    assert.fail("no error");
  };
  assert.equal(code(() => dggs.latLngToCell(91, 0, 3)), "E_LATLNG");
  assert.equal(code(() => dggs.latLngToCell(NaN, 0, 3)), "E_LATLNG");
  assert.equal(code(() => dggs.latLngToCell(0, 0, 29)), "E_LEVEL");
  assert.equal(code(() => dggs.latLngToCell(0, 0, 3, { projection: "PROJ" })), "E_PROJECTION");
  assert.equal(code(() => dggs.cellToLatLng("C7")), "E_CELL");
  assert.equal(code(() => dggs.cellToLatLng(12345n)), "E_CELL");
  assert.equal(code(() => dggs.cellToParent("C401", 4)), "E_LEVEL_MISMATCH");
  assert.equal(code(() => dggs.cellToChildren("C", 28)), "E_DOMAIN"); // over maxCells
  assert.equal(code(() => dggs.latLngToCells([0, 91], [0, 0], 3)), "E_LATLNG");
  assert.equal(code(() => dggs.gridDisk("C401", -1)), "E_DOMAIN");
  assert.equal(dggs.gridDistance("C401", dggs.gridRing("C401", 2)[0]), 2);
  assert.deepEqual(dggs.edgeNeighbors("C401").length, 3);
  assert.equal(dggs.cellToCenterChild("C401", 5).length, 6);
});

test("init from bytes or a compiled module; batches that grow the memory", async () => {
  const bytes = readFileSync(new URL("../dist/dggs.wasm", import.meta.url));
  await dggs.init(new WebAssembly.Module(bytes));
  assert.equal(dggs.latLngToCell(48.85, 2.35, 10), "C5210001102");
  await dggs.init(bytes);
  const n = 1_500_000; // 36 MB of arguments and answers: the memory grows during the call
  const la = new Float64Array(n).map((_, i) => -89 + ((i * 7919) % 178000) / 1000);
  const ln = new Float64Array(n).map((_, i) => -180 + ((i * 104729) % 360000) / 1000);
  const ids = dggs.latLngToCells(la, ln, 24);
  for (let i = 0; i < n; i += 9973) assert.equal(dggs.latLngToCell(la[i], ln[i], 24, { asBigInt: true }), ids[i]);
  assert.equal(dggs.cellsToBoundaries(ids.subarray(0, 200_000)).length, 1_200_000);
  assert.equal(dggs.cellToChildren("C401", 14).length, 3 ** 11);
});
