// Point location per point in node (one thread), to set beside the native core's (js/tools/bench_native.py):
//   node js/tools/bench.mjs [FIXTURES_DIR]      (the 100,000 random points of bulk.bin, make js-fixtures)
// Times latLngToCells (Float64Array in, BigUint64Array out: one call into wasm) and latLngToCell per point
// (BigInt and string ids) at level 17 on ISEA: the process's CPU time (steadier than wall time on a shared
// machine), best of 7 runs after a warm-up.
import { readFileSync } from "node:fs";

import * as dggs from "../src/dggs.js";

const dir = process.argv[2] ?? new URL("../../build/js-fixtures/", import.meta.url).pathname;
const b = readFileSync(`${dir}/bulk.bin`);
const n = b.byteLength / 48;
const lat = new Float64Array(b.buffer.slice(b.byteOffset, b.byteOffset + 8 * n));
const lng = new Float64Array(b.buffer.slice(b.byteOffset + 8 * n, b.byteOffset + 16 * n));
await dggs.init();
const LEVEL = 17;

function best(fn, runs = 7) {
  fn();
  let t = Infinity;
  for (let r = 0; r < runs; r++) {
    const c0 = process.cpuUsage();
    fn();
    const c = process.cpuUsage(c0);
    t = Math.min(t, (c.user + c.system) * 1000);
  }
  return t / n;
}

const batch = best(() => dggs.latLngToCells(lat, lng, LEVEL));
const oneBig = best(() => {
  for (let i = 0; i < n; i++) dggs.latLngToCell(lat[i], lng[i], LEVEL, { asBigInt: true });
});
const oneStr = best(() => {
  for (let i = 0; i < n; i++) dggs.latLngToCell(lat[i], lng[i], LEVEL);
});
console.log(`node ${process.version}, ${n} points, level ${LEVEL}, ns per point:`);
console.log(`  latLngToCells (typed arrays)      ${batch.toFixed(0)}`);
console.log(`  latLngToCell, BigInt id          ${oneBig.toFixed(0)}`);
console.log(`  latLngToCell, string id          ${oneStr.toFixed(0)}`);
