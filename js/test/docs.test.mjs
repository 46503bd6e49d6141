// The code blocks of docs/js.md and js/README.md, run under node so that they cannot rot.
//
// A ```js block runs as an ES module with `import ... from "dggs"` pointed at ../src/dggs.js. A line
// `expression;  // → value` also checks its answer: the expression must equal the value (deepStrictEqual, so
// "C521" is not 5024146296391335936n and 15 is not "15"). Other comments are prose. A block that throws fails.
//
// The ```html block of docs/js.md (the MapLibre page) runs here too, with MapLibre and the server stood in for:
// its module script in a folder laid out as the page expects (vendor/dggs/ holding this package), `fetch` of
// `/map/cells?level=3&f=uint64` answered with the body `dggs serve` sends (a uint64 count n, n uint64 ids, n
// float64 counts, n float64 values) for known cells, and `Map` recording the style it is given. The features
// it builds must be those cells, with their counts, and rings that are the cells' boundaries (densify 4),
// closed, longitudes unwrapped. tests/server/test_browser.py runs the same page in Chromium against a server.
import assert from "node:assert/strict";
import { copyFileSync, mkdirSync, mkdtempSync, readFileSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { test } from "node:test";
import { fileURLToPath, pathToFileURL } from "node:url";

import * as dggs from "../src/dggs.js";

const ROOT = new URL("../../", import.meta.url);
const MODULE = new URL("js/src/dggs.js", ROOT).href;
const EXPECT = /^(?<code>.*?);?\s*\/\/ → (?<value>.+)$/;

/** The fenced blocks of a Markdown file in a language, with the line each starts on. */
function blocks(file, lang) {
  const text = readFileSync(new URL(file, ROOT), "utf8");
  const found = [];
  const re = new RegExp("^```" + lang + "\\n([\\s\\S]*?)^```", "gm");
  for (let m = re.exec(text); m; m = re.exec(text)) {
    found.push({ code: m[1], line: text.slice(0, m.index).split("\n").length + 1 });
  }
  return found;
}

/** A js block as a module: the package imported from this repository, each `// → value` line an assertion. */
function asModule(code, where) {
  const lines = code.split("\n").map((line, i) => {
    line = line.replace(/from\s+["']dggs["']/, `from ${JSON.stringify(MODULE)}`);
    const m = EXPECT.exec(line);
    if (!m) return line;
    const at = `${where}:${i}`;
    return `globalThis.__docsExpect(${JSON.stringify(at)}, ${JSON.stringify(m.groups.code.trim())}, ` +
      `(${m.groups.code.trim()}), (${m.groups.value.trim()}));`;
  });
  return lines.join("\n");
}

const checked = [];
globalThis.__docsExpect = (at, code, got, want) => {
  checked.push(at);
  assert.deepStrictEqual(got, want, `${at}: ${code}`);
};

async function runModule(source, folder) {
  const file = join(folder, `block-${checked.length}-${Math.random().toString(36).slice(2)}.mjs`);
  writeFileSync(file, source);
  await import(pathToFileURL(file).href);
}

const scratch = mkdtempSync(join(tmpdir(), "dggs-docs-"));

for (const file of ["docs/js.md", "js/README.md"]) {
  const found = blocks(file, "js");
  test(`${file} has js blocks`, () => assert.ok(found.length > 0));
  for (const { code, line } of found) {
    test(`${file}, the js block at line ${line}`, async () => {
      const before = checked.length;
      await runModule(asModule(code, `${file}:${line}`), scratch);
      assert.ok(checked.length > before, `${file}:${line}: no line says what it gives (// → value)`);
    });
  }
}

test("docs/js.md's MapLibre page builds the cells' features from ids", async () => {
  const [page] = blocks("docs/js.md", "html");
  assert.ok(page, "docs/js.md has no html block");
  const script = /<script type="module">([\s\S]*?)<\/script>/.exec(page.code);
  assert.ok(script, "the page has no module script");

  // The page's folder: vendor/dggs/ as `make static-wasm` fills it, vendor/maplibre-gl/ a stand-in.
  const folder = mkdtempSync(join(tmpdir(), "dggs-page-"));
  mkdirSync(join(folder, "vendor/dggs"), { recursive: true });
  mkdirSync(join(folder, "vendor/maplibre-gl"), { recursive: true });
  copyFileSync(fileURLToPath(MODULE), join(folder, "vendor/dggs/dggs.js"));
  copyFileSync(fileURLToPath(new URL("js/dist/dggs.wasm", ROOT)), join(folder, "vendor/dggs/dggs.wasm"));
  writeFileSync(join(folder, "vendor/maplibre-gl/maplibre-gl.mjs"), `
    export class Map {
      constructor(options) { globalThis.__docsMaps.push(options); }
      once(event, fn) { if (event === "idle") fn(); }
    }`);

  // Level-3 cells by the north pole, the antimeridian and elsewhere, as /map/cells?f=uint64 sends them.
  await dggs.init();
  const ids = [
    ...dggs.cellToChildren(dggs.stringToCell("A"), 3).slice(0, 5),
    ...dggs.gridDisk(dggs.latLngToCell(89.9, 0, 3, { asBigInt: true }), 1),
    ...dggs.gridDisk(dggs.latLngToCell(0.5, 179.9, 3, { asBigInt: true }), 1),
  ];
  const n = ids.length;
  const body = new ArrayBuffer(8 + 24 * n);
  new BigUint64Array(body, 0, 1)[0] = BigInt(n);
  new BigUint64Array(body, 8, n).set(ids);
  new Float64Array(body, 8 + 8 * n, n).set(ids.map((_, i) => i + 1));
  new Float64Array(body, 8 + 16 * n, n).set(ids.map((_, i) => 0.5 * i));

  const saved = { fetch: globalThis.fetch, window: globalThis.window };
  const asked = [];
  globalThis.__docsMaps = [];
  const pageWindow = {};
  globalThis.window = pageWindow;
  globalThis.fetch = async (url) => {
    asked.push(String(url));
    return new Response(body);
  };
  try {
    await runModule(script[1], folder);
  } finally {
    globalThis.fetch = saved.fetch;
    if (saved.window === undefined) delete globalThis.window;
    else globalThis.window = saved.window;
  }

  assert.deepEqual(asked, ["/map/cells?level=3&f=uint64"]);
  assert.equal(globalThis.__docsMaps.length, 1);
  const features = globalThis.__docsMaps[0].style.sources.cells.data.features;
  assert.equal(pageWindow.cellsDrawn, n);
  assert.equal(features.length, n);
  features.forEach((f, i) => {
    assert.equal(f.properties.zone_id, dggs.cellToString(ids[i]));
    assert.equal(f.properties.count, i + 1);
    const [ring] = f.geometry.coordinates;
    const want = dggs.cellToBoundary(ids[i], { densify: 4 });
    assert.equal(ring.length, want.length + 1);
    assert.deepEqual(ring[ring.length - 1], ring[0], `${f.properties.zone_id}: ring not closed`);
    want.forEach(([lat, lng], k) => {
      const [x, y] = ring[k];
      assert.equal(y, lat);
      const turns = (x - lng) / 360;
      assert.ok(Math.abs(turns - Math.round(turns)) < 1e-9, `${f.properties.zone_id}, point ${k}: ${x} is not ${lng}`);
      if (k > 0) assert.ok(Math.abs(x - ring[k - 1][0]) < 180, `${f.properties.zone_id}: a jump at point ${k}`);
    });
  });
});
