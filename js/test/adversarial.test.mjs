// The adversarial suite's corrupt values (tests/index/test_adversarial.py) fed to every verb of the JS package:
// the only acceptable outcomes are an answer that passes a cheap check or a DggsError with a message; anything
// else (a TypeError, a RangeError, a wasm trap, a wrong kind of answer) is a bug. Run: node --test
// js/test/adversarial.test.mjs after `make wasm` (tests/js/test_js.py runs it in the Python suite).
import assert from "node:assert/strict";
import { test } from "node:test";

import * as dggs from "../src/dggs.js";

await dggs.init();

const GOOD = "C401";
const GOOD_BIG = dggs.stringToCell(GOOD);
const CORRUPT_CELLS = [
  "", "C9", "c401", "U0", "C6", "C403", "C4" + "0".repeat(40), "A0\u0000", "\u0000", "A\u00000", "Aé", "🌍", " C401",
  "C401 ", "C4" + "0".repeat(70), null, undefined, NaN, Infinity, -Infinity, 2.5, -1, 0, 1, true, false, {}, [], [GOOD],
  -1n, 0n, 1n << 64n, (1n << 64n) - 1n, -(1n << 63n), (1n << 62n) | 3n, Symbol("C401"), new Date(0), () => GOOD,
  new String(GOOD), Number(GOOD_BIG), 4.5e18,
];
const BAD_LEVELS = [-1, 29, 2.5, "3", true, false, null, NaN, Infinity, 2 ** 70, -(2 ** 70), 3n, [3], {}, Symbol("3")];
const BAD_NUMBERS = [NaN, Infinity, -Infinity, 1e308, -1e308, 90.0000001, -91, "1", true, null, undefined, 1n, {}, [1],
  Symbol("1"), 5e-324, -0, 540, 1e15];
const BAD_K = [-1, 2.5, "3", true, null, NaN, Infinity, 2 ** 70, 3n, [3], {}, 2 ** 31 + 1];
const BAD_OPTS = [null, 5, "ISEA", { projection: "X" }, { projection: 5 }, { maxCells: -1 }, { maxCells: "5" },
  { maxCells: NaN }, { mode: "nope" }, { asBigInt: "yes" }];

function describe(v) {
  try {
    return typeof v === "bigint" ? `${v}n` : typeof v === "symbol" ? v.toString() : JSON.stringify(v) ?? String(v);
  } catch {
    return Object.prototype.toString.call(v);
  }
}

const failures = [];
function call(name, fn, args, check) {
  let got;
  try {
    got = fn(...args);
  } catch (e) {
    if (!(e instanceof dggs.DggsError) || !e.message.trim())
      failures.push(`${name}(${args.map(describe).join(", ")}): ${e?.constructor?.name} ${e?.message}`);
    return;
  }
  if (check && !check(got)) failures.push(`${name}(${args.map(describe).join(", ")}): answered ${describe(got)}`);
}

const isCellAnswer = (c) => (typeof c === "string" && dggs.isValidCell(c)) || (typeof c === "bigint" && dggs.isValidCell(c));
const isCellList = (xs) => Array.isArray(xs) || xs instanceof BigUint64Array;
const isPoint = (p) => Array.isArray(p) && p.length === 2 && p.every(Number.isFinite) && Math.abs(p[0]) <= 90;

test("cell arguments", () => {
  failures.length = 0;
  for (const c of CORRUPT_CELLS) {
    call("isValidCell", dggs.isValidCell, [c], (b) => b === true || b === false);
    call("stringToCell", dggs.stringToCell, [c], (b) => typeof b === "bigint" && dggs.isValidCell(b));
    call("cellToString", dggs.cellToString, [c], isCellAnswer);
    call("getLevel", dggs.getLevel, [c], (l) => Number.isInteger(l) && l >= 0 && l <= 28);
    call("getFace", dggs.getFace, [c], (f) => Number.isInteger(f) && f >= 0 && f < 20);
    call("cellArea", dggs.cellArea, [c], (a) => Number.isFinite(a) && a > 0);
    call("cellToLatLng", dggs.cellToLatLng, [c], isPoint);
    call("cellToBoundary", dggs.cellToBoundary, [c], (b) => Array.isArray(b) && b.every(isPoint));
    call("cellToParent", dggs.cellToParent, [c, 0], isCellAnswer);
    call("cellToCenterChild", dggs.cellToCenterChild, [c, 5], isCellAnswer);
    call("cellToChildren", dggs.cellToChildren, [c, 4], isCellList);
    call("compactCells", dggs.compactCells, [[GOOD, c]], isCellList);
    call("compactCells", dggs.compactCells, [c], isCellList);
    call("uncompactCells", dggs.uncompactCells, [[c], 5], isCellList);
    call("gridDisk", dggs.gridDisk, [c, 1], isCellList);
    call("gridRing", dggs.gridRing, [c, 1], isCellList);
    call("edgeNeighbors", dggs.edgeNeighbors, [c], isCellList);
    call("gridDistance", dggs.gridDistance, [GOOD, c], (d) => Number.isInteger(d) && d >= 0);
    call("gridDistance", dggs.gridDistance, [c, GOOD_BIG], (d) => Number.isInteger(d) && d >= 0);
    call("cellsToLatLngs", dggs.cellsToLatLngs, [[GOOD, c]]);
    call("cellsToBoundaries", dggs.cellsToBoundaries, [[c]]);
    call("cellsToLatLngs", dggs.cellsToLatLngs, [c]);
  }
  assert.deepEqual(failures, []);
});

test("levels, radii, coordinates and options", () => {
  failures.length = 0;
  for (const l of BAD_LEVELS) {
    call("getNumCells", dggs.getNumCells, [l], (n) => Number.isFinite(Number(n)) && Number(n) >= 20);
    call("cellArea", dggs.cellArea, [l], (a) => Number.isFinite(a) && a > 0);
    call("latLngToCell", dggs.latLngToCell, [10, 20, l], isCellAnswer);
    call("cellToParent", dggs.cellToParent, [GOOD, l], isCellAnswer);
    call("cellToCenterChild", dggs.cellToCenterChild, [GOOD, l], isCellAnswer);
    call("cellToChildren", dggs.cellToChildren, [GOOD, l], isCellList);
    call("uncompactCells", dggs.uncompactCells, [[GOOD], l], isCellList);
    call("latLngToCells", dggs.latLngToCells, [[10], [20], l], isCellList);
    call("polygonToCells", dggs.polygonToCells, [[[[0, 0], [0, 1], [1, 1], [0, 0]]], l], isCellList);
  }
  for (const k of BAD_K) {
    call("gridDisk", dggs.gridDisk, [GOOD, k], isCellList);
    call("gridRing", dggs.gridRing, [GOOD, k], isCellList);
  }
  for (const x of BAD_NUMBERS) {
    call("latLngToCell", dggs.latLngToCell, [x, 20, 5], isCellAnswer);
    call("latLngToCell", dggs.latLngToCell, [10, x, 5], isCellAnswer);
    call("latLngToCells", dggs.latLngToCells, [[10, x], [20, 20], 5], isCellList);
    call("latLngToCells", dggs.latLngToCells, [x, [20], 5], isCellList);
    call("polygonToCells", dggs.polygonToCells, [[[[0, 0], [0, x], [1, 1], [0, 0]]], 3], isCellList);
    call("polygonToCells", dggs.polygonToCells, [x, 3], isCellList);
    call("polygonToCells", dggs.polygonToCells, [[x], 3], isCellList);
  }
  for (const o of BAD_OPTS) {
    call("latLngToCell", dggs.latLngToCell, [10, 20, 5, o], isCellAnswer);
    call("cellToBoundary", dggs.cellToBoundary, [GOOD, o]);
    call("gridDisk", dggs.gridDisk, [GOOD, 2, o], isCellList);
    call("cellToChildren", dggs.cellToChildren, [GOOD, 6, o], isCellList);
    call("polygonToCells", dggs.polygonToCells, [[[[0, 0], [0, 1], [1, 1], [0, 0]]], 3, o], isCellList);
  }
  for (const u of ["m2", null, 3, "", "M^2", {}]) call("cellArea", dggs.cellArea, [GOOD, u]);
  assert.deepEqual(failures, []);
});
